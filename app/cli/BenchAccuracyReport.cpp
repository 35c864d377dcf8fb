// `lpv bench report`: the accuracy-against-time report from one command.
// For each scene (the built-in Cornell box, Sibenik and Sponza from
// ../shared/scenes) it makes a project, traces the path-traced reference
// once, runs one `lpv bench --sweep` per question (propagation steps, grid,
// cascades, RSM tile, variant, each extension off/on), each varied alone
// around the project's settings (the full cartesian product would be
// thousands of renders), and, where the scene has emissive surfaces, measures
// radiosity against the same reference as it converges. The summary
// (report.md, report.json) names per scene the cheapest settings that reach
// 10% and 5% indirect error; each sweep keeps its own CSV, JSON and plots.
#include "BenchReport.h"
#include "BenchReportPlan.h"
#include "Cli.h"
#include "lpv/bench/ContentHash.h"
#include "lpv/bench/ReferenceFile.h"

#include "BenchSweepCommand.h"
#include "ReferenceTrace.h"

#include "lpv/bench/Report.h"
#include "lpv/bench/SharedTiming.h"
#include "lpv/radiosity/PatchMesh.h"
#include "lpv/reference/Metrics.h"
#include "lpv/scene/Project.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>

namespace lpv::cli {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using namespace report;
using bench::RadiosityPoint;
using bench::ReportRun;
using bench::SceneReport;

void printBenchAccuracyReportHelp() {
    std::cout << R"(
bench report [--out DIR] [--scenes DIR] [--scene NAME ...] [--quick] [options]:
the README's accuracy-against-time report from one command. For each scene
(cornell-box: the built-in template as `lpv new` makes it, lit by its
ceiling lamp, an area light; cornell-obj, sibenik and sponza: imported from
--scenes, default ../shared/scenes, as `lpv import` makes them) it creates
the project in DIR/NAME/, then
 1. times every distinct setting of the questions below once, all together,
    in interleaved rounds (A B C, then C B A, ...; --rounds, --time-budget,
    --spread-target): each time is a median over the rounds with its
    interquartile range, and a setting that several questions contain has
    one time (DIR/NAME/timing.json);
 2. traces the reference once per bounce count and sky setting a question
    needs (kept for later runs of the same size);
 3. runs `lpv bench --sweep` once per question, each key varied alone
    around the project's settings, its times taken from timing.json:
)";
    for (const bench::Question& q : kQuestions)
        std::printf("  %-14s %s%s\n", q.name.c_str(), q.sweep.c_str(),
                    q.name == "bounces" || q.name == "sky" ? " (one sweep and one reference per value)" : "");
    std::cout << R"(Like for like: each LPV is measured against the reference's light reflected
as many times as its lpv.bounces, and the reference traces the sky and
emissive surfaces where the LPV injects them (reference.skyLight and
reference.emissiveLight on auto). The tables give the indirect light's
symmetric error (too dark and too bright alike), the ratio of the LPV's
mean indirect irradiance to the reference's (outside 0.8-1.25x: biased),
MARE, the GPU time with its spread and the frame's GPU memory.
Each scene also gets a radiosity solve of its lights (meshed as finely as
150,000 patches allow), measured at doubling solve times against a
reference of the same lights reflected 8 times without the sky: the residual,
the indirect error and the mean ratio per solve time. Writes DIR/report.md
(headline table per scene: the project's settings, the cheapest unbiased
settings within 10% and 25% of the lowest unbiased error, the lowest error)
and DIR/report.json; each sweep's CSV, JSON, Markdown and plots stay in
DIR/NAME/QUESTION/.

  --out DIR             Output folder (default bench-report)
  --scenes DIR          Folder with cornell/CornellBox-Original.obj,
                        sibenik/sibenik.obj and sponza/sponza.obj
                        (default ../shared/scenes)
  --scene NAME          Only this scene (cornell-box, cornell-obj, sibenik,
                        sponza); repeatable
  --question NAME       Only this question (steps, grid, ...); repeatable
  --resume              Reuse a scene's timing.json made by the same options
                        for the same settings, and each sweep whose sweep.json
                        was made by the same sweep command after its
                        reference and timing (after an interruption; not
                        after changing the program)
  --quick               Three questions with fewer values, 5 s of radiosity:
                        a smoke run (minutes instead of most of an hour)
  --width N --height N  Image size (default 320x180)
  --frames N --warmup N Timed frames per setting and round (default 10);
                        warm-up frames before a setting is measured (default 2)
  --spp N               Reference samples per pixel (default per scene, so that
                        the reference's own noise stays low: Cornell box 4096,
                        Sibenik 4096, Sponza 2048; --quick: 256)
  --radiosity-seconds S Longest radiosity solve (default 160; solve times
                        double from 5 s up to it)
)" << kRoundOptionsHelp << R"(                        (the rounds and the budget are per scene)

On a cluster (docs/cluster.md, packaging/cluster/), in pieces that share DIR:
  --merge-shards N      The coordinator: each run does the next step, first
                        making the projects, then merging the N shards'
                        references (lpv merge), then merging their sweeps (lpv
                        bench merge), measuring radiosity and writing the report
  --shard I/N           Shard I of N (0-based): its tiles of every missing
                        reference, or once they are merged, its combinations of
                        every sweep. Same options as the coordinator's.
  Order: coordinator, N shards, coordinator, N shards, coordinator.
)";
}

namespace {

std::string fixed(double v, int digits) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.*f", digits, v);
    return buf;
}

// Radiosity as a GI method beside the LPV (issue #27 item 5): the project's
// own lights shoot, the solve runs to doubling wall times, and after each the
// frame's indirect light (gi.method = radiosity) is measured like for like
// against a reference of many bounces without the sky (the solution holds
// every bounce, and the sky does not shoot).
void measureRadiosity(SceneReport& report, const fs::path& sceneDir, int width, int height, int spp,
                      double maxSeconds) {
    auto project = scene::loadProject(report.projectFile);
    if (!project) {
        report.radiosityNote = project.error().describe();
        return;
    }
    const fs::path dir = sceneDir / "radiosity";
    fs::create_directories(dir);
    const fs::path solvedProject = dir / (report.name + ".lpvproj");
    const float patchArea = reportPatchArea(*project);
    const std::string areaSet = "radiosity.maxPatchArea=" + fixed(patchArea, 4);
    const fs::path ref = dir / "reference-8-bounce-sky-off.exr";
    ReferenceCommand traced;
    traced.projectFile = report.projectFile;
    traced.output = ref.string();
    traced.width = width;
    traced.height = height;
    traced.spp = std::to_string(spp);
    traced.bounces = "8";
    traced.sets = {"reference.skyLight=off"};
    if (!referenceMatches(ref, width, height) && runEchoed(traced) != kOk) {
        report.radiosityNote = "the 8-bounce reference failed";
        return;
    }
    report.radiosityNote = "the project's lights shoot, " + areaSet + ", ray-cast form factors; indirect light "
                           "against an 8-bounce reference without sky, " + bench::describeReferenceFile(ref);
    double solved = 0.0;
    bool restart = true;
    for (double target = 5.0; solved < maxSeconds - 1e-6; target = std::min(2.0 * target, maxSeconds)) {
        RadiosityCommand solve;
        solve.projectFile = restart ? report.projectFile : solvedProject.string();
        if (restart)
            solve.output = solvedProject.string();
        solve.maxSeconds = target - solved;
        solve.residual = 0.0001;
        solve.progressInterval = 10.0;
        solve.sets = {areaSet};
        solve.restart = restart;
        std::printf("\n$ lpv radiosity %s%s --set %s --max-seconds %.2f --residual 0.0001 --progress-interval 10%s\n",
                    solve.projectFile.c_str(), restart ? (" -o " + solvedProject.string()).c_str() : "",
                    areaSet.c_str(), solve.maxSeconds, restart ? " --restart" : "");
        restart = false;
        if (runRadiosityCommand(solve) != kOk) {
            report.failures.push_back("radiosity run to " + fixed(target, 0) + " s");
            return;
        }
        solved = target;
        SweepCommand measure;
        measure.projectFile = solvedProject.string();
        measure.sweeps = {"gi.method=radiosity"};
        measure.referenceFile = ref.string();
        measure.outDir = dir / ("sweep-" + fixed(target, 0) + "s");
        measure.width = width;
        measure.height = height;
        measure.frames = 1;
        measure.warmup = 1;
        measure.rounds = {1, 1, 0.10, 0.0}; // its frame time is not reported: the solve time is its cost
        std::vector<SweepRun> runs;
        if (runSweepCommand(measure, &runs) != kOk || runs.empty()) {
            report.failures.push_back("measuring the radiosity solution after " + fixed(target, 0) + " s");
            return;
        }
        report.radiosity.push_back({runs.front().solveSeconds, runs.front().image, runs.front().indirect,
                                    runs.front().solveResidual});
        std::printf("radiosity after %.0f s of solving: indirect %s\n", solved,
                    reference::describe(report.radiosity.back().indirect).c_str());
        if (runs.front().solveResidual <= solve.residual) {
            // Converged inside this budget: a longer one would solve nothing more (one row, not five equal ones).
            std::printf("radiosity converged to the residual %g in %.1f s\n", *solve.residual,
                        runs.front().solveSeconds);
            break;
        }
    }
}

} // namespace

namespace report {

std::optional<ReportOptions> parseReportOptions(Args& args, int& exitCode) {
    ReportOptions o;
    o.outDir = args.option("--out").value_or("bench-report");
    o.scenesDir = args.option("--scenes").value_or("../shared/scenes");
    o.scenes = args.options("--scene");
    o.questions = args.options("--question");
    o.quick = args.flag("--quick");
    o.resume = args.flag("--resume");
    o.width = args.integer("--width", o.width, {1});
    o.height = args.integer("--height", o.height, {1});
    o.frames = args.integer("--frames", o.frames, {1});
    o.warmup = args.integer("--warmup", o.warmup, {0});
    o.spp = args.optionalInteger("--spp", {1});
    // A quick run is a smoke test of the radiosity step too: the shortest solve.
    o.radiosityCount = args.integer("--radiosity-seconds", o.quick ? 5 : 160, {5});
    parseRoundOptions(args, o.rounds);
    auto fail = [&](const std::string& message) -> std::optional<ReportOptions> {
        exitCode = usageError(message, "bench");
        return std::nullopt;
    };
    if (auto e = args.error())
        return fail(*e);
    if (args.positionals().size() != 1)
        return fail("bench report takes no files (scenes come from --scenes)");
    for (const std::string& name : o.questions)
        if (std::ranges::find(kQuestions, name, &Question::name) == kQuestions.end())
            return fail("unknown question '" + name + "' (see lpv bench --help)");
    for (const std::string& name : o.scenes)
        if (std::ranges::find(kScenes, name, &SceneSpec::name) == kScenes.end())
            return fail("unknown scene '" + name + "' (cornell-box, cornell-obj, sibenik, sponza)");
    return o;
}

int runWholeReport(const ReportOptions& o) {
    std::vector<SceneReport> reports;
    std::string machine;
    int status = kOk;
    for (const SceneSpec& spec : kScenes) {
        if (!o.wantsScene(spec.name))
            continue;
        SceneReport report;
        report.name = spec.name;
        const fs::path sceneDir = o.outDir / spec.name;
        std::error_code ec;
        fs::create_directories(sceneDir, ec);
        if (ec) {
            std::cerr << "lpv: " << sceneDir.string() << ": cannot create the folder: " << ec.message()
                      << "\n";
            return kFailure;
        }
        const fs::path project = projectFileOf(spec, o);
        report.projectFile = project.string();
        std::printf("\n=== %s\n", spec.name.c_str());
        // --resume keeps a project that loads (its references and sweeps were made from it).
        const bool keepProject = o.resume && scene::loadProject(project).has_value();
        if (keepProject)
            std::printf("reusing %s (--resume)\n", project.string().c_str());
        const auto plan = keepProject || makeProject(spec, o.scenesDir, project) ? planSceneOrSay(spec, o) : std::nullopt;
        if (!plan) {
            report.failures.push_back("making the project");
            reports.push_back(report);
            status = kFailure;
            continue;
        }
        // Every setting timed once, together, before the sweeps take their times from it.
        if (!timeScene(*plan, o)) {
            report.failures.push_back("timing the settings");
            reports.push_back(report);
            status = kFailure;
            continue;
        }
        if (const auto timing = bench::loadSharedTiming(timingFileOf(*plan)))
            report.timingNote = std::to_string(timing->rounds) + " interleaved rounds (" + timing->stopReason + "), " +
                                timing->load;
        std::vector<int> traced(plan->references.size(), -1); // -1 not yet, 0 failed, 1 there
        auto referenceThere = [&](std::size_t i) {
            if (traced[i] < 0) {
                const PlannedReference& ref = plan->references[i];
                if (referenceMatches(ref.file, o.width, o.height, ref.bounces, plan->spp)) {
                    std::printf("reusing %s (delete it to trace again)\n", ref.file.string().c_str());
                    traced[i] = 1;
                } else {
                    traced[i] = runEchoed(referenceCommandOf(*plan, ref, ref.file, o)) == kOk;
                }
            }
            return traced[i] == 1;
        };
        if (!referenceThere(0)) {
            report.failures.push_back("tracing the reference");
            reports.push_back(report);
            status = kFailure;
            continue;
        }
        report.referenceNote = bench::describeReferenceFile(plan->references[0].file) + ", " +
                               std::to_string(plan->projectBounces) + " bounce" +
                               (plan->projectBounces == 1 ? "" : "s");
        for (const PlannedSweep& sweep : plan->sweeps) {
            const bool resumed = referenceThere(sweep.reference) && o.resume &&
                                 sweepDoneAlready(sweep.dir / "sweep.json", *plan, sweep, o);
            std::vector<SweepRun> runs;
            if (resumed) {
                std::printf("reusing %s (--resume: made by the same sweep command)\n",
                            (sweep.dir / "sweep.json").string().c_str());
            } else if (!referenceThere(sweep.reference) || runEchoed(sweepCommandOf(*plan, sweep, o), &runs) != kOk) {
                report.failures.push_back("sweep " + sweep.question + " (" + sweep.sweep + ")");
                status = kFailure;
                continue;
            }
            const auto rows = resumed ? bench::reportRunsFromSweepJson(sweep.dir / "sweep.json", sweep.question,
                                                                       plan->current)
                                      : bench::reportRunsOf(sweep.question, runs, plan->current);
            report.runs.insert(report.runs.end(), rows.begin(), rows.end());
            if (machine.empty()) {
                std::ifstream in(sweep.dir / "sweep.json");
                const Json j = Json::parse(in, nullptr, false);
                if (!j.is_discarded() && j.contains("machine") && j["machine"].is_string())
                    machine = j["machine"].get<std::string>();
            }
        }
        measureRadiosity(report, sceneDir, o.width, o.height, plan->spp, double(o.radiosityCount));
        if (!report.failures.empty())
            status = kFailure;
        reports.push_back(std::move(report));
    }

    const std::string command = reportCommand(o);
    const std::optional<std::string> md = (o.outDir / "report.md").string(),
                                     json = (o.outDir / "report.json").string();
    if (!writeReportFiles(
            {{md, bench::reportMarkdown(reports, command, machine)}, {json, bench::reportJson(reports, command, machine)}}))
        return kFailure;
    return status;
}

} // namespace report

int benchAccuracyReport(Args args) {
    const auto shard = args.shard("--shard");
    const auto shardCount = args.optionalInteger("--merge-shards", {1});
    int exitCode = kOk;
    const auto options = parseReportOptions(args, exitCode);
    if (!options)
        return exitCode;
    if (shard && shardCount)
        return usageError("--shard runs one shard, --merge-shards joins them: give one", "bench");
    if (shard)
        return report::runReportShard(*options, *shard);
    if (shardCount)
        return report::runReportCoordinator(*options, *shardCount);
    return report::runWholeReport(*options);
}

} // namespace lpv::cli
