#pragma once
// A sweep's files: sweep.csv, sweep.json, sweep.md (the cheapest settings
// reaching 10% and 5% indirect MARE) and the PNG plots (time per pass
// against each swept key, error against time with the Pareto front, crops
// of each run's indirect light). Written by a sweep itself and, from its
// shards, by `lpv bench merge`, so both give the same files.
#include "lpv/bench/Sweep.h"

#include <filesystem>
#include <string>
#include <vector>

namespace lpv::bench {

// Every file of a finished sweep into `outDir` (which must exist); the
// columns are the swept keys in the order the runs first name them and every
// pass any run timed. `command` and `machine` head the JSON and Markdown;
// `note` (may be empty) is a paragraph added under them (a sharded sweep's
// machines, say). Returns the files written, in order; each is written
// atomically.
scene::Expected<std::vector<std::filesystem::path>> writeSweepOutputs(
    const std::filesystem::path& outDir, const std::vector<SweepRun>& runs, int width, int height,
    const std::string& command, const std::string& machine, const reference::ReferenceImage& ref,
    const std::string& note = "");

} // namespace lpv::bench
