#pragma once
// Tracing the reference of a loaded project, shared by `lpv reference` and
// `lpv bench PROJECT --sweep` (which traces one when not given a file).
#include "lpv/reference/ReferenceImage.h"
#include "lpv/reference/Shards.h"
#include "lpv/renderer/ReferenceLights.h"
#include "lpv/scene/Project.h"

#include <filesystem>
#include <optional>

namespace lpv::cli {

struct ReferenceRequest {
    int width = 320;
    int height = 180;
    int threads = 0;
    bool printProgress = true;
    reference::ShardSpec shard; // trace only these tiles (`lpv reference --shard`)
};

struct TracedReference {
    reference::ReferenceImage image;
    renderer::ReferenceLights lights; // whether the sky and emissive surfaces lit it, and why
    int bounces = 0;
};

// Settings come from the project's parameters (reference.samplesPerPixel,
// reference.bounces, reference.maxSeconds, reference.skyLight and
// reference.emissiveLight, whose `auto` follows what the LPV injects). Textures
// are loaded relative to `projectFile`; a missing one is a warning, as in `lpv render`.
std::optional<TracedReference> traceReference(const scene::Project& project,
                                                        const std::filesystem::path& projectFile,
                                                        const scene::Camera& camera,
                                                        const ReferenceRequest& request);

} // namespace lpv::cli
