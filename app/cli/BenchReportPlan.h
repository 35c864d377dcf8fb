#pragma once
// What `lpv bench report` does, laid out before it does it: per scene the
// project, the references it needs (one per bounce count and sky setting a
// sweep measures against) and the sweeps (one per question, or per value for
// bounces and sky). The report runs the plan in one process
// (BenchAccuracyReport.cpp); on a cluster, shards and a coordinator run it in
// pieces (BenchReportShards.cpp, docs/cluster.md).
#include "Cli.h"
#include "BenchSweepCommand.h"
#include "lpv/bench/ContentHash.h"
#include "lpv/bench/ReferenceFile.h"
#include "ReferenceTrace.h"

#include "lpv/bench/Questions.h"
#include "lpv/reference/Shards.h"
#include "lpv/scene/ParameterRegistry.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace lpv::cli::report {

using bench::Question;
extern const std::vector<Question>& kQuestions;

struct SceneSpec {
    std::string name;
    std::string source; // relative to --scenes; empty = the built-in template
    // Reference samples per pixel unless --spp says otherwise (see kScenes).
    int defaultSpp;
};
extern const std::vector<SceneSpec> kScenes;

struct ReportOptions {
    std::filesystem::path outDir = "bench-report";
    std::filesystem::path scenesDir = "../shared/scenes";
    std::vector<std::string> scenes;    // --scene; empty = all
    std::vector<std::string> questions; // --question; empty = all
    bool quick = false;
    bool resume = false;
    int width = 320, height = 180, frames = 10, warmup = 2;
    std::optional<int> spp; // --spp; else per scene
    int radiosityCount = 160;
    bench::RoundPlan rounds; // the timing step's rounds (--rounds, --time-budget, --spread-target), per scene

    bool wantsScene(const std::string& name) const;
    bool wantsQuestion(const std::string& name) const;
    int sppFor(const SceneSpec& spec) const; // --quick is a smoke run: 256 unless --spp
};

struct PlannedReference {
    std::filesystem::path file;
    int bounces = 1;
    std::string sky; // effects.skyInjection it is traced for ("": the project's)
};

struct PlannedSweep {
    std::string question;
    std::string sweep; // "KEY=V1,V2,..."
    std::filesystem::path dir;
    std::size_t reference = 0; // into ScenePlan::references
};

struct ScenePlan {
    const SceneSpec* spec = nullptr;
    std::filesystem::path dir;     // OUT/NAME
    std::filesystem::path project; // OUT/NAME/NAME.lpvproj
    int spp = 0;
    int projectBounces = 1;
    scene::ParameterSet current; // the project's own parameters
    std::vector<PlannedReference> references; // the project's own first
    std::vector<PlannedSweep> sweeps;
};

std::filesystem::path projectFileOf(const SceneSpec& spec, const ReportOptions& options);
// The plan of one scene; its project must exist (its lpv.bounces decides the references).
std::optional<ScenePlan> planScene(const SceneSpec& spec, const ReportOptions& options);

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
// "lpv.bounces=1,2,3" -> {"1", "2", "3"}.
std::vector<std::string> splitValues(const std::string& sweep);
// A fresh project for the scene; false (and a message) when it cannot be made.
bool makeProject(const SceneSpec& spec, const std::filesystem::path& scenesDir,
                 const std::filesystem::path& project);
// A reference traced earlier with the same size and bounce count and at least `spp` is reused.
bool referenceMatches(const std::filesystem::path& file, int width, int height, int bounces = 0, int spp = 0);
bool referenceMatches(const bench::LoadedReference& ref, int width, int height, int bounces, int spp);
// --resume: whether `file` was written by the very sweep the report would run
// now (its recorded command holds the project, the swept values, the
// reference, the size, frames and warm-up) after the reference was traced.
bool sweepDoneAlready(const std::filesystem::path& file, const ScenePlan& plan, const PlannedSweep& sweep,
                      const ReportOptions& options);

// The options every form of `lpv bench report` shares; nullopt after a usage
// error, whose exit code is in `exitCode`.
std::optional<ReportOptions> parseReportOptions(Args& args, int& exitCode);
// The command line that gives these options (headed in report.md; printed as the next step).
std::string reportCommand(const ReportOptions& options);

// OUT/NAME/timing.json: every distinct setting of the scene's sweeps timed
// once, together, in interleaved rounds (BenchReportTiming.cpp); the sweeps
// take their times from it. False after printing why it failed.
std::filesystem::path timingFileOf(const ScenePlan& plan);
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
