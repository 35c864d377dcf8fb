#pragma once
// `lpv bench report` runs its plan (bench/ReportPlan.h: the scenes, their
// references and sweeps, what is done already) as commands: in one process
// (BenchAccuracyReport.cpp) or, on a cluster, as shards and a coordinator
// (BenchReportShards.cpp, docs/cluster.md). What is here turns a planned
// step into the command that does it, and echoes it as a user would type it.
#include "Cli.h"
#include "BenchSweepCommand.h"
#include "ReferenceTrace.h"

#include "lpv/bench/ReportPlan.h"
#include "lpv/reference/Shards.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace lpv::cli::report {

using bench::Question;
extern const std::vector<Question>& kQuestions;

// The plan and its names from lpv_bench (ReportPlan.h, ReportShards.h), as
// the report's commands use them.
using namespace bench::report;

// bench::report::planScene, its error printed (nullopt then).
std::optional<ScenePlan> planSceneOrSay(const SceneSpec& spec, const ReportOptions& options);

// `lpv reference` tracing `ref` into `out`, and `lpv bench --sweep` for
// `sweep` into its folder, as the report runs them (in this process, options
// in hand, the runs returned in memory).
ReferenceCommand referenceCommandOf(const ScenePlan& plan, const PlannedReference& ref,
                                    const std::filesystem::path& out, const ReportOptions& options);
SweepCommand sweepCommandOf(const ScenePlan& plan, const PlannedSweep& sweep, const ReportOptions& options);
// Each echoed as a user would type it, then run.
int runEchoed(const ReferenceCommand& command);
int runEchoed(const SweepCommand& command, std::vector<SweepRun>* runs = nullptr);

// Runs one `lpv` command in this process, echoing it as a user would type it.
int call(const char* name, int (*command)(Args), std::vector<std::string> args);
// A fresh project for the scene; false (and a message) when it cannot be made.
bool makeProject(const SceneSpec& spec, const std::filesystem::path& scenesDir,
                 const std::filesystem::path& project);

// The options every form of `lpv bench report` shares; nullopt after a usage
// error, whose exit code is in `exitCode`.
std::optional<ReportOptions> parseReportOptions(Args& args, int& exitCode);

// OUT/NAME/timing.json (timingFileOf): every distinct setting of the scene's
// sweeps timed once, together, in interleaved rounds (BenchReportTiming.cpp);
// the sweeps take their times from it. False after printing why it failed.
bool timeScene(const ScenePlan& plan, const ReportOptions& options);

// The whole report in this process (BenchAccuracyReport.cpp).
int runWholeReport(const ReportOptions& options);
// `--shard I/N`: this shard's part of whatever comes next, the references'
// tiles while a reference is missing, else the sweeps' combinations
// (BenchReportShards.cpp).
int runReportShard(const ReportOptions& options, const reference::ShardSpec& shard);
// `--merge-shards N`: the next step between the shards' runs: makes the
// projects, then merges the reference shards, then merges the sweep shards
// and writes the report as runWholeReport would.
int runReportCoordinator(const ReportOptions& options, int shardCount);

} // namespace lpv::cli::report
