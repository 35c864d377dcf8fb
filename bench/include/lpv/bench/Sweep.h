#pragma once
// A sweep: every combination of swept settings rendered on the GPU, each
// timed per pass (median/min/max after warm-up) and measured against the
// path-traced reference (the LPV's indirect irradiance and the final image).
// `lpv bench PROJECT --sweep`, its shards, `lpv bench report` and the
// editor's sweep dock all run it; results come back in memory, and
// SweepOutput.h writes them as files.
#include "lpv/bench/Settings.h"

#include "lpv/reference/Metrics.h"
#include "lpv/reference/ReferenceImage.h"
#include "lpv/renderer/GlContext.h"
#include "lpv/renderer/GpuTimer.h"
#include "lpv/scene/Camera.h"
#include "lpv/scene/Error.h"
#include "lpv/scene/Project.h"

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace lpv::bench {

struct SweepRun {
    std::vector<Setting> settings;
    std::vector<renderer::PassTiming> passes;
    double totalMs = 0.0;
    int bounces = 1;                     // lpv.bounces of this run
    reference::ErrorMetrics indirect;    // like for like: against the reference layer with lpv.bounces bounces
    reference::ErrorMetrics indirectOne; // against the one-bounce indirect irradiance
    reference::ErrorMetrics image;       // final image against the reference image
    std::vector<glm::vec3> indirectPixels;
    // gi.method = radiosity: the saved solution's solve time (its cost is paid
    // once, before any frame) and residual; 0 for other runs.
    double solveSeconds = 0.0;
    double solveResidual = 0.0;
};

// A run's settings as "steps=8 gridSize=32" ("defaults" when none).
std::string sweepLabel(const std::vector<Setting>& settings);

struct SweepSpec {
    // Its parameters are the base every combination changes. Set lpv.reuse
    // to false there for timings of every pass every frame (the CLI does).
    scene::Project project;
    std::filesystem::path projectDir; // textures are read relative to it
    // Where a baked radiosity solution is read (radiosity::solutionPath) for
    // combinations with gi.method = radiosity; a sweep that shows one without
    // a solution that fits the scene fails with the loader's error.
    std::filesystem::path projectFile;
    scene::Camera camera;
    int width = 320;
    int height = 180;
    int frames = 20; // timed frames per combination
    int warmup = 3;  // untimed frames before them
    std::vector<std::vector<Setting>> combinations; // {} runs the project's own settings once
    int referenceBounces = 0; // the reference's multi-bounce layer's bounces; 0: unknown
};

// Where a sweep is: called before each combination renders (done of total,
// and its label) and once at the end (done == total). Returning false stops
// the sweep after the combination in flight (runSweep then gives Cancelled).
struct SweepProgress {
    int done = 0;
    int total = 0;
    std::string label;
};
struct SweepCallbacks {
    std::function<bool(const SweepProgress&)> progress;
    std::function<void(const SweepRun&)> runDone; // each finished run, in order
    std::function<void(const std::string&)> warning; // e.g. a missing texture
};

struct SweepResult {
    std::vector<SweepRun> runs;
    renderer::GlInfo gl; // the context the runs were timed in
};

// lpv.bounces of `base` with `combination` applied.
int bouncesOf(const scene::ParameterSet& base, const std::vector<Setting>& combination);

// Refuses, before anything renders, a combination the registry rejects and a
// run of lpv.bounces = k > 1 when the reference's multi-bounce layer has
// another count (the measurement would not be like for like).
std::optional<std::string> checkSweep(const SweepSpec& spec, const std::string& referenceName);

// Renders and measures every combination in its own headless GL context,
// created on the calling thread (so a worker thread can run a sweep while
// another context draws). The reference must be spec.width x spec.height.
scene::Expected<SweepResult> runSweep(const SweepSpec& spec, const reference::ReferenceImage& reference,
                                      const SweepCallbacks& callbacks = {});

} // namespace lpv::bench
