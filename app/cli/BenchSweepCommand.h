#pragma once
// `lpv bench PROJECT --sweep` as a function of its options, so that `lpv
// bench report` runs its sweeps with the options in hand and gets the runs
// back in memory instead of building an argument list and reading sweep.json.
#include "BenchReport.h"

#include "lpv/reference/Shards.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace lpv::cli {

// What every sweep sets before its own settings: timed frames compute the
// LPV every frame instead of reusing the first frame's volumes. The report's
// timing step (BenchReportTiming.cpp) renders with the same, so its times
// match the sweeps' settings by value.
inline const std::string kSweepBaseSet = "lpv.reuse=false";

struct SweepCommand {
    std::string projectFile;
    std::optional<std::string> cameraName;
    std::vector<std::string> sets;   // KEY=VALUE (a list sweeps the key too)
    std::vector<std::string> sweeps; // KEY=V1,V2,...
    std::optional<std::string> referenceFile; // else one is traced (spp, seconds)
    std::filesystem::path outDir = "bench-sweep";
    int width = 320, height = 180, frames = 20, warmup = 3;
    bench::RoundPlan rounds; // interleaved timing rounds (--rounds, --time-budget, --spread-target)
    // --times-from: each run's times and memory from this timing.json (`lpv
    // bench report` times a scene's settings once, for all its questions); no rounds here.
    std::optional<std::filesystem::path> timesFrom;
    std::optional<std::string> spp, seconds;
    reference::ShardSpec shard;
};

// Prints what `lpv bench --sweep` prints and writes its files (or the shard's);
// returns its exit code and, on success, the runs in `runsOut` (may be null).
int runSweepCommand(const SweepCommand& command, std::vector<SweepRun>* runsOut = nullptr);

} // namespace lpv::cli
