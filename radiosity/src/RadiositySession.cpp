#include "lpv/radiosity/RadiositySession.h"

#include "lpv/radiosity/SurfaceProperties.h"

#include <cstdio>

namespace lpv::radiosity {

namespace {

// Whether a visible object's mesh uses a material that emits (its emissive
// colour times its texture's average has a positive channel).
bool anythingEmits(const scene::Scene& scene, const scene::TextureImages& textures) {
    const std::vector<glm::vec3> emission = materialEmissions(scene, textures);
    for (const scene::Object& o : scene.objects) {
        if (!o.visible || o.mesh < 0 || std::size_t(o.mesh) >= scene.meshes.size())
            continue;
        for (const scene::Submesh& sub : scene.meshes[std::size_t(o.mesh)].submeshes)
            if (sub.materialIndex < emission.size() && sub.indexCount >= 3 &&
                glm::any(glm::greaterThan(emission[sub.materialIndex], glm::vec3(0.0f))))
                return true;
    }
    return false;
}

} // namespace

scene::Expected<RadiositySession> RadiositySession::create(const scene::Scene& scene,
                                                           const scene::TextureImages& textures, float maxPatchArea,
                                                           std::size_t maxPatches,
                                                           std::optional<StoredSolution> saved) {
    if (!anythingEmits(scene, textures))
        return scene::makeError(scene::ErrorCode::InvalidValue, "radiosity", "materials",
                                "nothing in the scene emits light: radiosity shoots from emissive surfaces "
                                "only (give a material an emissive colour), so the solve would end at once "
                                "with a black solution; nothing was solved or written");
    const std::size_t patches = countPatches(scene, {maxPatchArea});
    if (patches > maxPatches)
        return scene::makeError(scene::ErrorCode::OutOfRange, "radiosity", "radiosity.maxPatches",
                                "the scene would mesh into " + std::to_string(patches) +
                                    " patches at radiosity.maxPatchArea = " + std::to_string(maxPatchArea) +
                                    " m^2, over radiosity.maxPatches = " + std::to_string(maxPatches) +
                                    "; raise radiosity.maxPatchArea or radiosity.maxPatches");
    return RadiositySession(scene, textures, maxPatchArea, std::move(saved));
}

scene::Expected<RadiositySession> RadiositySession::create(const scene::Scene& scene,
                                                           const scene::ParameterSet& parameters,
                                                           const scene::TextureImages& textures,
                                                           std::optional<StoredSolution> saved) {
    return create(scene, textures, parameters.getFloat("radiosity.maxPatchArea"),
                  std::size_t(parameters.getInt("radiosity.maxPatches")), std::move(saved));
}

std::optional<StoredSolution> loadSavedSolution(const scene::Scene& scene, const std::filesystem::path& projectFile,
                                                std::string* ignored) {
    const auto file = solutionPath(projectFile);
    std::error_code ec;
    if (projectFile.empty() || !std::filesystem::exists(file, ec))
        return std::nullopt;
    auto loaded = loadSolution(file, scene.materials.size(), scene.objects.size());
    if (!loaded) {
        if (ignored)
            *ignored = loaded.error().describe();
        return std::nullopt;
    }
    return std::move(*loaded);
}

RadiositySession::RadiositySession(const scene::Scene& scene, const scene::TextureImages& textures,
                                   float maxPatchArea, std::optional<StoredSolution> saved)
    : maxPatchArea_(maxPatchArea) {
    auto fresh = std::make_unique<PatchMesh>(buildPatchMesh(scene, {maxPatchArea}));
    const SurfaceProperties freshSurfaces = surfaceProperties(*fresh, scene, textures);
    signature_ = sceneSignature(*fresh, freshSurfaces);
    if (saved && saved->sceneSignature == signature_) {
        mesh_ = std::make_unique<PatchMesh>(std::move(saved->mesh));
        solver_ = std::make_unique<ProgressiveSolver>(*mesh_, surfaceProperties(*mesh_, scene, textures));
        if (solver_->restore(std::move(saved->state))) {
            resumed_ = true;
            char text[160];
            std::snprintf(
                text, sizeof(text), "resuming the saved solution: %zu patches, %llu shots, residual %.4g",
                mesh_->size(), static_cast<unsigned long long>(solver_->state().shots), solver_->residual());
            note_ = text;
            return;
        }
    }
    if (saved)
        note_ = "the saved solution was solved for another scene or patch size; starting over";
    mesh_ = std::move(fresh);
    solver_ = std::make_unique<ProgressiveSolver>(*mesh_, freshSurfaces);
}

std::size_t RadiositySession::refine(float threshold) {
    const std::vector<std::uint32_t> which = solver_->patchesToRefine(threshold);
    if (which.empty())
        return 0;
    std::vector<std::uint32_t> parentOf;
    auto refined = std::make_unique<PatchMesh>(refinePatches(*mesh_, which, parentOf));
    // Children keep their parent's material, so its reflectance and emission.
    SurfaceProperties surfaces;
    for (std::uint32_t parent : parentOf) {
        surfaces.reflectance.push_back(solver_->surfaces().reflectance[parent]);
        surfaces.emission.push_back(solver_->surfaces().emission[parent]);
    }
    SolverState state = refineState(solver_->state(), parentOf);
    auto next = std::make_unique<ProgressiveSolver>(*refined, std::move(surfaces));
    (void)next->restore(std::move(state)); // sizes match by construction
    solver_ = std::move(next);
    mesh_ = std::move(refined);
    return which.size();
}

StoredSolution RadiositySession::stored() const {
    StoredSolution s;
    s.mesh.patches = mesh_->patches;
    s.state = solver_->state();
    s.sceneSignature = signature_;
    s.maxPatchArea = maxPatchArea_;
    return s;
}

} // namespace lpv::radiosity
