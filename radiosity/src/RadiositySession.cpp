#include "lpv/radiosity/RadiositySession.h"

#include "lpv/radiosity/DirectLight.h"
#include "lpv/radiosity/SurfaceProperties.h"
#include "lpv/scene/AreaLight.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace lpv::radiosity {

namespace {

// Whether a light could deliver anything (shadows and facing aside).
bool anyLightShines(const scene::Scene& scene) {
    for (const scene::Light& l : scene.lights)
        if (l.intensity > 0.0f && glm::any(glm::greaterThan(l.color, glm::vec3(0.0f))))
            return true;
    return false;
}

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
                                                           const scene::TextureImages& textures,
                                                           const SessionOptions& options,
                                                           std::optional<StoredSolution> saved) {
    const bool lights = anyLightShines(scene);
    if (!lights && !anythingEmits(scene, textures))
        return scene::makeError(scene::ErrorCode::InvalidValue, "radiosity", "lights",
                                "nothing in the scene shoots light: it has no light with a positive intensity "
                                "and no emissive surface, so the solve would end at once with a black "
                                "solution; nothing was solved or written");
    const std::size_t patches = countPatches(scene, {options.maxPatchArea});
    if (patches > options.maxPatches)
        return scene::makeError(scene::ErrorCode::OutOfRange, "radiosity", "radiosity.maxPatches",
                                "the scene would mesh into " + std::to_string(patches) +
                                    " patches at radiosity.maxPatchArea = " + std::to_string(options.maxPatchArea) +
                                    " m^2, over radiosity.maxPatches = " + std::to_string(options.maxPatches) +
                                    "; raise radiosity.maxPatchArea or radiosity.maxPatches");
    RadiositySession session(scene, textures, options.maxPatchArea, std::move(saved));
    if (session.resumed() || !lights)
        return session;
    const auto start = std::chrono::steady_clock::now();
    auto direct = directLight(session.mesh(), scene, textures, options.lightSamples, options.cancel);
    if (!direct)
        return std::unexpected(direct.error());
    if (auto added = session.solver().addDirectLight(std::move(*direct)); !added)
        return std::unexpected(added.error());
    session.directLightSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const glm::dvec3 power = session.solver().unshotPower();
    if (!(power.x + power.y + power.z > 0.0))
        return scene::makeError(scene::ErrorCode::InvalidValue, "radiosity", "lights",
                                "nothing shoots: the lights reach no patch (all shadowed, facing away or out of "
                                "range) and no surface emits; nothing was solved or written");
    return session;
}

scene::Expected<RadiositySession> RadiositySession::create(const scene::Scene& scene,
                                                           const scene::TextureImages& textures, float maxPatchArea,
                                                           std::size_t maxPatches,
                                                           std::optional<StoredSolution> saved) {
    SessionOptions options;
    options.maxPatchArea = maxPatchArea;
    options.maxPatches = maxPatches;
    return create(scene, textures, options, std::move(saved));
}

float patchAreaFor(const scene::Scene& scene, const scene::ParameterSet& parameters) {
    const float set = parameters.getFloat("radiosity.maxPatchArea");
    if (parameters.isSet("radiosity.maxPatchArea"))
        return set;
    const scene::Bounds bounds = scene.worldBounds();
    const glm::vec3 size = bounds.empty() ? glm::vec3(0.0f) : bounds.size();
    const float side = std::max({size.x, size.y, size.z}) / kAutoPatchesPerSide;
    // An empty or flat-to-a-point scene has no length to scale with: the registry's value.
    return std::isfinite(side) && side > 0.0f ? side * side : set;
}

scene::Expected<RadiositySession> RadiositySession::create(const scene::Scene& scene,
                                                           const scene::ParameterSet& parameters,
                                                           const scene::TextureImages& textures,
                                                           std::optional<StoredSolution> saved,
                                                           const std::atomic<bool>* cancel) {
    SessionOptions options;
    options.maxPatchArea = patchAreaFor(scene, parameters);
    options.maxPatches = std::size_t(parameters.getInt("radiosity.maxPatches"));
    options.lightSamples = parameters.getInt("radiosity.lightSamples");
    options.cancel = cancel;
    return create(scene, textures, options, std::move(saved));
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
    signature_ = sceneSignature(*fresh, freshSurfaces, scene.lights);
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
