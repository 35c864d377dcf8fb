#pragma once
// Tracing the reference of a loaded project, shared by `lpv reference` and
// `lpv bench PROJECT --sweep` (which traces one when not given a file).
#include "lpv/reference/ReferenceImage.h"
#include "lpv/scene/Project.h"

#include <filesystem>
#include <optional>

namespace lpv::cli {

struct ReferenceRequest {
    int width = 320;
    int height = 180;
    int threads = 0;
    bool printProgress = true;
};

// Settings come from the project's parameters (reference.samplesPerPixel,
// reference.bounces, reference.maxSeconds, reference.skyLight). Textures are
// loaded relative to `projectFile`; a missing one is a warning, as in `lpv render`.
std::optional<reference::ReferenceImage> traceReference(const scene::Project& project,
                                                        const std::filesystem::path& projectFile,
                                                        const scene::Camera& camera,
                                                        const ReferenceRequest& request);

} // namespace lpv::cli
