// loadPackInputs (RenderInputs.h): a bench pack (issue #45) as a rendering
// command's input, in `lpv` and in the GPU bench program alike.
#include "RenderInputs.h"

#include "Cli.h"

#include "lpv/renderer/SceneAnalysis.h"
#include "lpv/scene/BenchPack.h"

#include <iostream>

namespace lpv::cli {

std::optional<RenderInputs> loadPackInputs(const RenderRequest& request, const std::string& command, int& exitCode) {
    exitCode = kFailure;
    auto pack = scene::loadBenchPack(request.projectFile);
    if (!pack) {
        std::cerr << "lpv: " << pack.error().describe() << "\n";
        return std::nullopt;
    }
    RenderInputs inputs{std::move(pack->project), std::move(pack->textures), nullptr};
    if (!applySets(inputs.project.parameters, request.sets, command, exitCode))
        return std::nullopt;
    if (request.bakedRadiosity || renderer::showsBakedRadiosity(inputs.project.parameters)) {
        std::cerr << "lpv: " << request.projectFile
                  << ": a bench pack holds no radiosity solution, so gi.method=radiosity cannot be rendered from it "
                     "(bench the project itself)\n";
        exitCode = kFailure;
        return std::nullopt;
    }
    exitCode = kOk;
    return inputs;
}

} // namespace lpv::cli
