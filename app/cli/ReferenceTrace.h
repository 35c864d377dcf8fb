#pragma once
// Tracing the reference of a loaded project, shared by `lpv reference` and
// `lpv bench PROJECT --sweep` (which traces one when not given a file).
#include "lpv/bench/Reference.h"
#include "lpv/reference/ReferenceImage.h"
#include "lpv/reference/Shards.h"
#include "lpv/renderer/ReferenceLights.h"
#include "lpv/scene/Project.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace lpv::cli {

struct ReferenceRequest {
    int width = 320;
    int height = 180;
    int threads = 0;
    bool printProgress = true;
    reference::ShardSpec shard; // trace only these tiles (`lpv reference --shard`)
};

using bench::TracedReference;

// bench::traceReference (bench/Reference.h) with what it traces, its progress
// and its warnings printed; textures are loaded relative to `projectFile`.
// nullopt (the error printed) when the scene cannot be traced.
std::optional<TracedReference> traceReference(const scene::Project& project,
                                                        const std::filesystem::path& projectFile,
                                                        const scene::Camera& camera,
                                                        const ReferenceRequest& request);

// `lpv reference` as a function of its options (what `lpv bench report` runs):
// traces, writes the EXR with the settings in its header, prints as the command.
struct ReferenceCommand {
    std::string projectFile;
    std::string output; // .exr
    int width = 320, height = 180, threads = 0;
    std::optional<std::string> spp, seconds, bounces, cameraName;
    std::vector<std::string> sets; // KEY=VALUE
    reference::ShardSpec shard;
    bool preview = false;
};
int runReferenceCommand(const ReferenceCommand& command);

} // namespace lpv::cli
