#pragma once
// A sweep from nothing but a project and a view: the path-traced references
// it needs are traced first, one per group of settings that must be measured
// against the same light (the same lpv.bounces, the same choice of sky and
// emissive light for the reference), then every setting is timed and
// measured against its own (bench::runSweep). What the editor's Sweeps dock
// runs; results arrive one run at a time, with progress and the time left.
#include "lpv/bench/Sweep.h"

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace lpv::bench {

struct MeasuredSweepSpec {
    scene::Project project;           // its parameters are the base every combination changes
    std::filesystem::path projectDir; // textures are read relative to it
    std::filesystem::path projectFile; // a baked radiosity solution is read beside it (gi.method = radiosity)
    scene::Camera camera;
    std::vector<std::vector<Setting>> combinations; // {} = the project's own settings
    int width = 160;
    int height = 90;
    int frames = 3;
    int warmup = 1;
    int referenceSpp = 512;
    // Timing rounds: few, for an editor that waits on them; each run still
    // gets a median and a spread.
    RoundPlan rounds{3, 5, 0.10, 0.0};
};

struct MeasuredSweepCallbacks {
    // 0..1 of the whole job and what it does ("Reference 1 of 2: 96/512 spp",
    // "Setting 3 of 9: steps=4 (about 20 s left)"); false stops after the
    // pass or setting in flight.
    std::function<bool(double fraction, const std::string& text)> progress;
    // Run `index` of spec.combinations, with its indirect pixels, and the
    // layer of the reference it was measured against with its coverage.
    std::function<void(int index, const SweepRun& run, const std::vector<glm::vec3>& referenceLayer,
                       const std::vector<float>& coverage)>
        runDone;
    std::function<void(const std::string&)> warning;
};

struct MeasuredSweep {
    std::vector<SweepRun> runs;            // in the order of spec.combinations
    reference::ReferenceImage reference;   // the first group's (the project's own settings)
    int referenceBounces = 1;              // of that reference's measured layer
    int references = 0;                    // traced in all
    renderer::GlInfo gl;
    int rounds = 0;                        // timing rounds (the most any group ran)
    std::string stopReason;                // why the last group's rounds stopped
    std::string load;                      // the machine's load before and after (describeLoad)
};

// Groups of combinations that share a like-for-like reference, in order of
// first appearance (indices into spec.combinations).
std::vector<std::vector<int>> groupByReference(const MeasuredSweepSpec& spec);

scene::Expected<MeasuredSweep> measureSweep(const MeasuredSweepSpec& spec, const MeasuredSweepCallbacks& callbacks = {});

} // namespace lpv::bench
