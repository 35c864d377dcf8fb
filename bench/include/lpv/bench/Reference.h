#pragma once
// The path-traced reference of a project's view, in memory: the settings
// come from the project's parameters (reference.samplesPerPixel,
// reference.bounces, reference.maxSeconds, reference.skyLight and
// reference.emissiveLight, whose `auto` follows what the LPV injects, so the
// two compare like for like). `lpv reference`, a sweep without a reference
// file and the editor's sweep dock trace it here.
#include "lpv/reference/PathTracer.h"
#include "lpv/reference/ReferenceImage.h"
#include "lpv/reference/Shards.h"
#include "lpv/renderer/ReferenceLights.h"
#include "lpv/scene/Error.h"
#include "lpv/scene/Project.h"

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>

namespace lpv::bench {

struct ReferenceRequest {
    int width = 320;
    int height = 180;
    int threads = 0;            // 0: every core
    reference::ShardSpec shard; // trace only these tiles (`lpv reference --shard`)
};

// What is about to be traced, for the caller to say so.
struct ReferencePlan {
    std::size_t triangles = 0;
    reference::PathTracerSettings settings;
    renderer::ReferenceLights lights; // whether the sky and emissive surfaces light it, and why
};

struct ReferenceCallbacks {
    std::function<void(const ReferencePlan&)> started;
    reference::ProgressCallback progress; // after every pass; false stops (the image so far is returned)
    std::function<void(const std::string&)> warning; // e.g. a missing texture
};

struct TracedReference {
    reference::ReferenceImage image;
    renderer::ReferenceLights lights;
    int bounces = 0;
};

// Textures are read relative to `projectDir`; a missing one is a warning and
// draws as the placeholder, as in the renderer. Fails only when the scene
// cannot be built for Embree.
scene::Expected<TracedReference> traceReference(const scene::Project& project, const std::filesystem::path& projectDir,
                                                const scene::Camera& camera, const ReferenceRequest& request,
                                                const ReferenceCallbacks& callbacks = {});

} // namespace lpv::bench
