#pragma once
// The tables `lpv bench render` writes: per combination of swept settings,
// each pass's GPU time over interleaved rounds (median, quartiles, extremes),
// as CSV and as Markdown headed by the machine it ran on and its load.
#include "Args.h"

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
    // Per pass over the rounds (bench::SettingTiming): medianMs, minMs and
    // maxMs of the rounds' medians, samples = frames timed in all.
    std::vector<renderer::PassTiming> passes;
    std::vector<bench::TimingStats> passStats; // per pass, in the order of `passes` (empty: not timed in rounds)
    bench::TimingStats total;                  // of each round's sum of pass medians
};

// A run's label: its swept values ("shadow.mapSize=512 lpv.gridSize=16"), or "project settings".
std::string benchRunLabel(const std::vector<Setting>& settings);

// The other runs whose totals are the same cost as run `index` within the noise (bench::sameCost).
std::vector<std::size_t> benchSameCostAs(const std::vector<BenchRun>& runs, std::size_t index);

// One row per (run, pass) and a "total" row per run: the swept keys as
// columns, then pass, median_ms, q1_ms, q3_ms, min_ms, max_ms, rounds,
// frames, same_cost_as (on total rows: the labels of the runs of the same
// cost, separated by ';').
std::string benchCsv(const std::vector<BenchRun>& runs);

// A Markdown report: the command, the machine, its load before -> after and
// why the rounds stopped, then one row per run and one column per pass,
// "median ±half the interquartile range" in ms, the total with its quartiles
// and rounds, and, with several runs, which cost the same within the noise.
std::string benchMarkdown(const std::vector<BenchRun>& runs, const std::string& command, const std::string& machine,
                          const bench::SweepTimingInfo& timing = {});

// The printed table of one run: per pass and for the total, the median over
// rounds, q1-q3, the interquartile range in % of the median, min-max, rounds
// and frames.
std::string benchTable(const BenchRun& run);

// With several runs: each total and the runs of the same cost ("" for one run).
std::string benchComparison(const std::vector<BenchRun>& runs);

// Writes each (file, text) whose file is given, atomically, and says so; on
// failure prints the error and returns false.
bool writeReportFiles(const std::vector<std::pair<std::optional<std::string>, std::string>>& reports);

// A sweep's files (bench/SweepOutput.h), each named on stdout as written;
// on failure prints the error and returns false.
bool writeSweepFiles(const std::filesystem::path& outDir, const std::vector<SweepRun>& runs, int width, int height,
                     const std::string& command, const std::string& machine, const reference::ReferenceImage& ref,
                     const std::string& note = "", const bench::SweepTimingInfo& timing = {},
                     const scene::ParameterSet& display = {});

// --rounds N, --time-budget S and --spread-target PERCENT into `plan` (its
// fields are the defaults); a bad value is left in args.error(). Shared by
// every bench command that times (bench.md "Timing with its spread").
void parseRoundOptions(Args& args, bench::RoundPlan& plan);
using bench::roundOptionsText;
// The help lines of those options.
extern const char* const kRoundOptionsHelp;

// The median of `values` (the mean of the middle two for an even count; 0 when empty).
double median(std::vector<double> values);

} // namespace lpv::cli
