// loadRenderInputs (app/cli/RenderInputs.h) for lpv-gl-bench: bench packs
// only. A project needs lpv_importers to decode its textures (OpenImageIO),
// which this program leaves out on purpose (issue #45).
#include "RenderInputs.h"

#include "Cli.h"

#include "lpv/scene/BenchPack.h"

namespace lpv::cli {

std::optional<RenderInputs> loadRenderInputs(const RenderRequest& request, const std::string& command, int& exitCode) {
    if (!scene::isBenchPackFile(request.projectFile)) {
        exitCode = usageError("lpv-gl-bench reads bench packs (.lpvpack), not '" + request.projectFile +
                                  "': make one with `lpv bench pack PROJECT -o FILE.lpvpack`",
                              command);
        return std::nullopt;
    }
    return loadPackInputs(request, command, exitCode);
}

} // namespace lpv::cli
