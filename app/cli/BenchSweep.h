#pragma once
// A sweep's results (`lpv bench PROJECT --sweep`) and the files they become:
// sweep.csv, sweep.json, sweep.md and the PNG plots. Written by the sweep
// itself and, from the shards of a sharded sweep, by `lpv bench merge`
// (BenchSweepShard.h), so both give the same files.
#include "SetSweep.h"

#include "lpv/reference/Metrics.h"
#include "lpv/reference/ReferenceImage.h"
#include "lpv/renderer/GpuTimer.h"

#include <filesystem>
#include <string>
#include <vector>

namespace lpv::cli {

struct SweepRun {
    std::vector<Setting> settings;
    std::vector<renderer::PassTiming> passes;
    double totalMs = 0.0;
    int bounces = 1;                     // lpv.bounces of this run
    reference::ErrorMetrics indirect;    // like for like: against the reference layer with lpv.bounces bounces
    reference::ErrorMetrics indirectOne; // against the one-bounce indirect irradiance
    reference::ErrorMetrics image;       // final image against the reference image
    std::vector<glm::vec3> indirectPixels;
};

// A run's settings as "steps=8 gridSize=32" ("defaults" when none).
std::string sweepLabel(const std::vector<Setting>& settings);

// Every file of a finished sweep into `outDir`: the columns are the swept keys
// in the order the runs first name them and every pass any run timed.
// `command` and `machine` head the JSON and Markdown; `note` (may be empty)
// is a paragraph added under them (a sharded sweep's machines, say).
bool writeSweepOutputs(const std::filesystem::path& outDir, const std::vector<SweepRun>& runs, int width,
                       int height, const std::string& command, const std::string& machine,
                       const reference::ReferenceImage& ref, const std::string& note = "");

} // namespace lpv::cli
