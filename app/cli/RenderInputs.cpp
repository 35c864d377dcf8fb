// loadRenderInputs (RenderInputs.h) for `lpv`: a project, its textures
// decoded by lpv_importers and its radiosity solution, or a bench pack.
#include "RenderInputs.h"

#include "Cli.h"

#include "lpv/importers/SceneTextures.h"
#include "lpv/renderer/SceneAnalysis.h"
#include "lpv/scene/BenchPack.h"

#include <cstdio>
#include <filesystem>
#include <iostream>

namespace lpv::cli {

std::optional<RenderInputs> loadRenderInputs(const RenderRequest& request, const std::string& command, int& exitCode) {
    if (scene::isBenchPackFile(request.projectFile))
        return loadPackInputs(request, command, exitCode);
    auto project = loadProjectWithSets(request.projectFile, request.sets, command, exitCode);
    if (!project)
        return std::nullopt;
    exitCode = kFailure;
    RenderInputs inputs;
    inputs.project = std::move(*project);
    // Texture paths are relative to the project file's folder; a missing one
    // draws as the placeholder and is named here.
    auto textures = importers::loadSceneTextures(inputs.project.scene,
                                                 std::filesystem::absolute(request.projectFile).parent_path());
    for (const std::string& w : textures.warnings)
        std::cerr << "lpv: warning: " << w << "\n";
    inputs.textures = std::move(textures.images);
    if (request.bakedRadiosity || renderer::showsBakedRadiosity(inputs.project.parameters)) {
        auto solution = radiosity::loadBakedSolution(inputs.project.scene, inputs.textures, request.projectFile);
        if (!solution) {
            std::cerr << "lpv: " << solution.error().describe() << "\n";
            return std::nullopt;
        }
        std::printf("radiosity: %s: %zu patches, residual %.4g, %llu shots\n", solution->file.string().c_str(),
                    solution->mesh.size(), solution->residual, static_cast<unsigned long long>(solution->shots));
        inputs.bakedRadiosity = std::make_shared<const radiosity::BakedSolution>(std::move(*solution));
    }
    exitCode = kOk;
    return inputs;
}

} // namespace lpv::cli
