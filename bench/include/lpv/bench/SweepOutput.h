#pragma once
// A sweep's files: sweep.csv, sweep.json, sweep.md (each run's time with
// its spread, GPU memory, symmetric error and bias; the cheapest unbiased
// settings whose error is within 10% and 25% of the lowest unbiased one) and the PNG plots (time per
// pass against each swept key, error against time on a log axis with the
// times' spread and the Pareto front, error against GPU memory, crops of
// each run's indirect light and of its final frame beside the reference's,
// all through the frame's exposure and tonemapper: renderer/DisplayMapping.h). Written by a sweep itself and, from its
// shards, by `lpv bench merge`, so both give the same files.
#include "lpv/bench/Sweep.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace lpv::bench {

// Every file of a finished sweep into `outDir` (which must exist); the
// columns are the swept keys in the order the runs first name them and every
// pass any run timed. `command` and `machine` head the JSON and Markdown;
// `note` (may be empty) is a paragraph added under them (a sharded sweep's
// machines, say). Returns the files written, in order; each is written
// atomically.
// How the times were taken, headed beside the machine.
struct SweepTimingInfo {
    int rounds = 0;          // interleaved timing rounds (0: times not measured in rounds)
    std::string stopReason;  // why they stopped
    std::string load;        // the machine's load before -> after
};

// "Cheapest within X% of the best" in sweep.md and the report: the cheapest
// unbiased run whose symmetric error is at most (1 + X) times the lowest
// unbiased one. Relative, because the LPV's error has a floor of its own on
// every scene (tens of percent) that no fixed bound suits.
inline constexpr double kWithinBest[] = {0.10, 0.25};
// The index of that run (nullopt when no run is unbiased).
std::optional<std::size_t> cheapestWithinBest(const std::vector<SweepRun>& runs, double fraction);

scene::Expected<std::vector<std::filesystem::path>> writeSweepOutputs(
    const std::filesystem::path& outDir, const std::vector<SweepRun>& runs, int width, int height,
    const std::string& command, const std::string& machine, const reference::ReferenceImage& ref,
    const std::string& note = "", const SweepTimingInfo& timing = {},
    const scene::ParameterSet& display = {});
// `display`: the parameters whose output.exposure, output.exposureMode and
// output.tonemapper show the pictures (the project's; the registry's defaults
// when empty), metered once on the reference so every picture shares one exposure.

// The runs that cost the same as run `index` within the noise (sameCost), by index.
std::vector<std::size_t> sameCostAs(const std::vector<SweepRun>& runs, std::size_t index);

} // namespace lpv::bench
