#pragma once
// A sweep: every combination of swept settings rendered on the GPU and
// measured against the path-traced reference (the LPV's indirect irradiance
// and the final image), then timed per pass in interleaved rounds (Timing.h)
// with each figure's median and spread, and its GPU memory counted.
// `lpv bench PROJECT --sweep`, its shards, `lpv bench report` and the
// editor's sweep dock all run it; results come back in memory, and
// SweepOutput.h writes them as files.
#include "lpv/bench/Settings.h"
#include "lpv/bench/Pareto.h"
#include "lpv/bench/Timing.h"

#include "lpv/reference/Metrics.h"
#include "lpv/reference/ReferenceImage.h"
#include "lpv/renderer/GlContext.h"
#include "lpv/renderer/GpuTimer.h"
#include "lpv/scene/Camera.h"
#include "lpv/scene/Error.h"
#include "lpv/scene/Project.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace lpv::bench {

struct SweepRun {
    std::vector<Setting> settings;
    // Per pass over the timing rounds: medianMs, minMs and maxMs of the
    // rounds' medians; passStats holds each one's quartiles.
    std::vector<renderer::PassTiming> passes;
    std::vector<TimingStats> passStats;
    TimingStats total;   // the frame: each round's sum of pass medians
    double totalMs = 0.0; // total.median
    // GPU memory of the resources the frame used (frame graph and LPV
    // volumes, renderer::GpuMemory), exact bytes; 0 when not counted.
    std::uint64_t gpuBytes = 0;
    std::uint64_t lpvBytes = 0; // of which the LPV's volumes
    int bounces = 1;                     // lpv.bounces of this run
    reference::ErrorMetrics indirect;    // like for like: against the reference layer with lpv.bounces bounces
    reference::ErrorMetrics indirectOne; // against the one-bounce indirect irradiance
    reference::ErrorMetrics image;       // final image against the reference image
    std::vector<glm::vec3> indirectPixels;
    std::vector<glm::vec3> imagePixels; // the final frame, linear HDR (for the files' pictures; not in sweep.json)
    // gi.method = radiosity: the saved solution's solve time (its cost is paid
    // once, before any frame) and residual; 0 for other runs.
    double solveSeconds = 0.0;
    double solveResidual = 0.0;
};

// A run's settings as "steps=8 gridSize=32" ("defaults" when none).
std::string sweepLabel(const std::vector<Setting>& settings);

// The test's mean over the reference's (0 when the reference is black).
double meanRatio(const reference::ErrorMetrics& m);
// A run as a point of time (with its spread) or GPU memory against its
// indirect light's symmetric error, biased when its mean is outside 0.8-1.25x.
CostPoint timeErrorPoint(const SweepRun& run);
CostPoint memoryErrorPoint(const SweepRun& run);

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
    int frames = 20; // timed frames per combination and round
    int warmup = 3;  // untimed frames before a combination is measured (one more before each timing round)
    RoundPlan rounds; // how long timing goes on; rounds.maxRounds = 0: accuracy and memory only
    std::vector<std::vector<Setting>> combinations; // {} runs the project's own settings once
    int referenceBounces = 0; // the reference's multi-bounce layer's bounces; 0: unknown
};

// Where a sweep is: called before each combination renders (done of total,
// and its label) and once at the end (done == total). Returning false stops
// the sweep after the combination in flight (runSweep then gives Cancelled).
struct SweepProgress {
    int done = 0;  // combinations measured (accuracy); == total once timing starts
    int total = 0;
    std::string label;
    int round = -1;        // the timing round under way (0-based), -1 while measuring accuracy
    double fraction = 0.0; // of the whole sweep, timing rounds estimated at rounds.minRounds
};
struct SweepCallbacks {
    std::function<bool(const SweepProgress&)> progress;
    // Each run once its accuracy and memory are measured, before any timing
    // round (its times are still empty), in order.
    std::function<void(const SweepRun&)> runMeasured;
    std::function<void(const SweepRun&)> runDone; // each finished run, with its times, in order, at the end
    std::function<void(const std::string&)> warning; // e.g. a missing texture
};

struct SweepResult {
    std::vector<SweepRun> runs;
    renderer::GlInfo gl; // the context the runs were timed in
    int rounds = 0;        // timing rounds run
    std::string stopReason; // why they stopped
    std::string load;       // describeLoad() before and after: "load 0.10 0.20 0.30 -> load 1.90 ..."
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

// Times every combination in interleaved rounds and counts its GPU memory,
// measuring no error (no reference needed): `lpv bench report` times all
// the distinct settings of a scene's questions at once, so that a setting in
// several questions has one time (issue #43).
scene::Expected<SweepResult> timeSettings(const SweepSpec& spec, const SweepCallbacks& callbacks = {});

} // namespace lpv::bench
