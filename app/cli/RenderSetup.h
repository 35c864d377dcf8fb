#pragma once
// What `lpv render` and `lpv bench render` share: load a project, apply
// --set overrides, pick the camera, open a headless GL context and create
// the renderer with the scene uploaded.
#include "Args.h"

#include "lpv/bench/Settings.h"
#include "lpv/renderer/ForwardRenderer.h"
#include "lpv/renderer/GlContext.h"
#include "lpv/scene/Project.h"

#include <optional>
#include <string>
#include <vector>

namespace lpv::cli {

struct RenderSetup {
    scene::Project project;
    scene::Camera camera;
    std::optional<renderer::HeadlessContext> context;
    std::optional<renderer::ForwardRenderer> renderer;
};

struct RenderRequest {
    std::string projectFile;
    std::optional<std::string> cameraName;
    std::vector<std::string> sets; // KEY=VALUE
    // Load the project's radiosity solution even when its gi.method (after
    // `sets`) is not radiosity: a swept --set shows it in some images.
    bool bakedRadiosity = false;
};

// --camera NAME and every --set KEY=VALUE, the options every rendering command takes.
RenderRequest renderRequestOptions(Args& args);

// Whether some combination of a sweep sets gi.method = radiosity.
bool sweepShowsBakedRadiosity(const std::vector<std::vector<bench::Setting>>& combinations);

// The named camera, or the project's first (a framing camera when it has none);
// an unknown name prints the cameras there are and gives nothing.
std::optional<scene::Camera> pickCamera(const scene::Scene& scene, const std::optional<std::string>& name,
                                        const std::string& projectFile);

// The project with the --set overrides (KEY=VALUE) applied. On failure prints
// the message (naming the file or the option) and returns the exit code in
// `exitCode`: a failure for a bad project, a usage error for a bad --set.
std::optional<scene::Project> loadProjectWithSets(const std::string& projectFile, const std::vector<std::string>& sets,
                                                  const std::string& command, int& exitCode);

// On failure prints the message (naming the file or the option) and returns
// the exit code in `exitCode`. With gi.method = radiosity (or
// request.bakedRadiosity) the renderer gets the project's radiosity solution;
// none saved, a damaged one or one solved for another scene is a failure
// ("lpv: FILE: why"): the image asked for cannot be made.
std::optional<RenderSetup> prepareRender(const RenderRequest& request, const std::string& command, int& exitCode);

// Renders `frames` frames and resolves every timer query; false (message printed) on error.
bool renderFrames(RenderSetup& setup, int width, int height, int frames);

// Per-pass GPU time of every frame, one row per frame (the summary table is
// renderer::formatTimingTable).
std::string formatPerFrameTimes(const renderer::GpuTimer& timer);

} // namespace lpv::cli
