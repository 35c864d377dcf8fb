#pragma once
// Temporal stability of the LPV's indirect light (issue #11 item 5,
// docs/flicker.md), per setting: frames along a camera path or while the sun
// turns, the frame-to-frame change of indirect irradiance on pixels whose
// surface stayed the same (reference::measureFlicker), beside the GPU time
// and, given a reference, the error of the first frame. `lpv bench PROJECT
// --flicker` runs it and writes flickerCsv / flickerMarkdown.
#include "lpv/bench/Settings.h"

#include "lpv/reference/ReferenceImage.h"
#include "lpv/renderer/GlContext.h"
#include "lpv/scene/Camera.h"
#include "lpv/scene/Error.h"
#include "lpv/scene/Project.h"

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace lpv::bench {

struct FlickerRun {
    std::vector<Setting> settings; // the row's label: the fixed settings and the combination
    double meanFlicker = 0.0;  // mean over pairs of the mean relative change
    double worstFlicker = 0.0; // largest per-pair mean
    double p95Flicker = 0.0;   // mean over pairs of the 95th percentile
    double keptFraction = 0.0; // kept pixels / pixels with geometry, mean over pairs
    double totalMs = 0.0;      // sum of the pass medians
    std::optional<double> mare; // first frame against the reference, when given one
};

struct FlickerSpec {
    scene::Project project; // its parameters are the base every combination changes
    std::filesystem::path projectDir;
    scene::Camera camera;   // the fixed camera, or the base the path's keys fill in
    int width = 320;
    int height = 180;
    int frames = 16;        // measured frames: frames - 1 pairs (at least 2)
    // The motion: a camera path sampled at `fps` from its start, or else every
    // directional light turning `sunDegrees` about +y over the frames.
    std::optional<scene::CameraPath> path;
    int fps = 30;
    float sunDegrees = 0.0f;
    std::vector<Setting> fixed; // shown in every row's label (already in the project's parameters)
    std::vector<std::vector<Setting>> combinations; // {} runs the project's own settings once
};

struct FlickerCallbacks {
    std::function<bool(int done, int total, const std::string& label)> progress; // false stops
    std::function<void(const FlickerRun&)> runDone;
    std::function<void(const std::string&)> warning;
};

struct FlickerResult {
    std::vector<FlickerRun> runs;
    renderer::GlInfo gl;
};

// A sentence for the report: "camera path 'dolly', 16 frames at 30 fps from its start".
std::string describeMotion(const FlickerSpec& spec);

// In its own headless GL context on the calling thread. `reference` (may be
// null) must be spec.width x spec.height.
scene::Expected<FlickerResult> runFlicker(const FlickerSpec& spec, const reference::ReferenceImage* reference,
                                          const FlickerCallbacks& callbacks = {});

std::string flickerLabel(const std::vector<Setting>& settings); // "key=value key=value", or "defaults"
std::string flickerCsv(const std::vector<FlickerRun>& runs);
std::string flickerMarkdown(const std::vector<FlickerRun>& runs, const std::string& command,
                            const std::string& machine, const std::string& motion);

} // namespace lpv::bench
