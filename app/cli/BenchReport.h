#pragma once
// The tables `lpv bench render` writes: per combination of swept settings,
// each pass's median/min/max GPU time, as CSV and as Markdown headed by the
// machine it ran on.
#include "lpv/bench/Machine.h"
#include "lpv/bench/Settings.h"
#include "lpv/bench/Sweep.h"
#include "lpv/bench/SweepOutput.h"
#include "lpv/bench/Timing.h"

#include "lpv/renderer/GpuTimer.h"

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace lpv::cli {

// The benchmark library's types by their short names, as the commands use them.
using bench::Setting;
using bench::SetPlan;
using bench::planSettings;
using bench::checkCombinations;
using bench::combinationSuffix;
using bench::SweepRun;
using bench::sweepLabel;
using bench::describeMachine;

struct BenchRun {
    std::vector<Setting> settings; // the swept values of this run ({} when nothing is swept)
    std::vector<renderer::PassTiming> passes;
};

// One row per (run, pass): the swept keys as columns, then pass, median_ms, min_ms, max_ms, frames.
std::string benchCsv(const std::vector<BenchRun>& runs);

// A Markdown report: the command and machine, then one row per run and one
// column per pass, "median (min-max)" in ms, and the total of the medians.
std::string benchMarkdown(const std::vector<BenchRun>& runs, const std::string& command, const std::string& machine);

// Writes each (file, text) whose file is given, atomically, and says so; on
// failure prints the error and returns false.
bool writeReportFiles(const std::vector<std::pair<std::optional<std::string>, std::string>>& reports);

// A sweep's files (bench/SweepOutput.h), each named on stdout as written;
// on failure prints the error and returns false.
bool writeSweepFiles(const std::filesystem::path& outDir, const std::vector<SweepRun>& runs, int width, int height,
                     const std::string& command, const std::string& machine, const reference::ReferenceImage& ref,
                     const std::string& note = "", const bench::SweepTimingInfo& timing = {});

// --rounds N, --time-budget S and --spread-target PERCENT into `plan` (its
// fields are the defaults); a usage error's text, or empty. Shared by every
// bench command that times (bench.md "Timing with its spread").
std::string parseRoundOptions(class Args& args, bench::RoundPlan& plan);
// The same options as a command line would give them (" --rounds 9 ...").
std::string roundOptionsText(const bench::RoundPlan& plan);
// The help lines of those options.
extern const char* const kRoundOptionsHelp;

// A whole number >= minimum (command-line counts), or nullopt.
std::optional<int> parseCount(const std::string& text, int minimum);
// The median of `values` (the mean of the middle two for an even count; 0 when empty).
double median(std::vector<double> values);
// A finite number of degrees, or nullopt.
std::optional<float> parseDegrees(const std::string& text);

} // namespace lpv::cli
