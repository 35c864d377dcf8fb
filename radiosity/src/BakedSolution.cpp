#include "lpv/radiosity/BakedSolution.h"

#include "lpv/radiosity/SolutionFile.h"
#include "lpv/radiosity/SurfaceProperties.h"

namespace lpv::radiosity {

std::uint64_t currentSignature(const scene::Scene& scene, const scene::TextureImages& textures, float maxPatchArea) {
    const PatchMesh unrefined = buildPatchMesh(scene, {maxPatchArea});
    return sceneSignature(unrefined, surfaceProperties(unrefined, scene, textures), scene.lights);
}

scene::Expected<BakedSolution> loadBakedSolution(const scene::Scene& scene, const scene::TextureImages& textures,
                                                 const std::filesystem::path& projectFile) {
    const std::filesystem::path file = solutionPath(projectFile);
    std::error_code ec;
    if (projectFile.empty() || !std::filesystem::exists(file, ec))
        return scene::makeError(scene::ErrorCode::FileNotFound, file.string(), "",
                                "no radiosity solution is saved for this project: solve it first (lpv radiosity " +
                                    (projectFile.empty() ? std::string("PROJECT") : projectFile.string()) +
                                    ", or the editor's Radiosity dock)");
    auto stored = loadSolution(file, scene.materials.size(), scene.objects.size());
    if (!stored)
        return std::unexpected(stored.error());
    const std::uint64_t signature = currentSignature(scene, textures, stored->maxPatchArea);
    if (signature != stored->sceneSignature)
        return scene::makeError(scene::ErrorCode::InvalidValue, file.string(), "scene signature",
                                "the solution was solved for another scene (its geometry, materials or lights "
                                "changed since): solve again (lpv radiosity PROJECT --restart)");
    BakedSolution out;
    out.mesh = std::move(stored->mesh);
    out.incident = std::move(stored->state.incident);
    out.shots = stored->state.shots;
    out.seconds = stored->state.seconds;
    out.signature = signature;
    out.maxPatchArea = stored->maxPatchArea;
    out.file = file;
    glm::dvec3 unshot(0.0);
    for (std::size_t i = 0; i < out.mesh.size(); ++i)
        unshot += glm::dvec3(stored->state.unshot[i]) * double(out.mesh.patches[i].area);
    const glm::dvec3& emitted = stored->state.balance.emitted;
    const double total = emitted.x + emitted.y + emitted.z;
    out.residual = total > 0.0 ? (unshot.x + unshot.y + unshot.z) / total : 0.0;
    return out;
}

} // namespace lpv::radiosity
