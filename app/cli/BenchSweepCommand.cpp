// `lpv bench PROJECT --sweep KEY=V1,V2,...`: every combination of the swept
// values, each timed per pass on the GPU (median/min/max after warm-up) and
// measured against the path-traced reference (indirect irradiance and final
// image); written as CSV, JSON, a Markdown report and PNG plots.
#include "BenchReport.h"
#include "BenchSweepCommand.h"
#include "lpv/bench/Sweep.h"
#include "lpv/bench/SweepOutput.h"
#include "lpv/bench/SweepShard.h"
#include "Cli.h"
#include "lpv/bench/ContentHash.h"
#include "lpv/bench/ReferenceFile.h"
#include "ReferenceTrace.h"
#include "RenderSetup.h"
#include "lpv/bench/Settings.h"
#include "lpv/bench/SavedSweep.h"
#include "lpv/bench/SharedTiming.h"

#include "lpv/importers/ImageIO.h"
#include "lpv/reference/Metrics.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

namespace lpv::cli {

namespace fs = std::filesystem;

void printBenchSweepHelp() {
    std::cout << R"(
bench PROJECT --sweep KEY=V1,V2,... [--sweep ...] [options]:
renders every combination of the swept values (e.g. --sweep
lpv.propagationSteps=0,4,8,16 --sweep lpv.gridSize=16,32), and for each
measures the error of the LPV's indirect irradiance (output.view=indirect)
and of the final image against the path-traced reference (`lpv reference`):
the symmetric error (too dark and too bright alike), the mean's ratio (a
mean outside 0.8-1.25x is marked biased), relMSE, MARE and SSIM, background
masked, beside the reference's own noise; the GPU memory of the frame's
resources, to the byte; and per-pass GPU time in interleaved rounds (see
--rounds), each a median with its spread. Like for like: a run with
lpv.bounces = k is measured against the reference's k-bounce light (its
indirect1 layer for k = 1, its multi-bounce layer when traced with
--bounces k), and the reference traces the sky and emissive surfaces where
the LPV injects them (reference.skyLight and reference.emissiveLight on
auto). Writes into --out: sweep.csv, sweep.json, sweep.md (the cheapest unbiased
settings within 10% and 25% of the lowest unbiased error; settings of the
same cost within the noise), time-<KEY>.png (time per pass against each
swept key), error-time.png (symmetric error against total time on a log
axis, the times' spread as bars, Pareto front and biased runs marked),
error-memory.png (the same against GPU memory), crops.png (the reference's
indirect light and each setting's) and frames.png (the reference image and
each setting's final frame), each sheet through the project's exposure and
tonemapper, metered once on the reference.

  --reference REF.exr   Reference traced beforehand at the same size and
                        camera; without it one is traced first (--spp,
                        --max-seconds, reference.* parameters)
  --out DIR             Output folder (default bench-sweep)
  --width N --height N  Image size (default 320x180, as `lpv reference`)
  --frames N --warmup N Timed frames per round (default 20); warm-up frames
                        (default 3) before a setting's image is measured
  --camera NAME --set KEY=VALUE
)" << kRoundOptionsHelp << R"(
  --times-from FILE     Take each setting's times and GPU memory from FILE, a
                        timing.json that `lpv bench report` wrote for the
                        scene (one time per setting for all its questions);
                        no timing rounds run here
  --shard I/N           Render only the combinations whose index is I modulo N
                        (0-based), for a cluster: needs --reference; writes
                        DIR/shard.json and DIR/run-K.exr, which `lpv bench merge`
                        joins into the files above (docs/cluster.md)
)";
}

int benchSweep(Args args) {
    SweepCommand c;
    c.cameraName = args.option("--camera");
    c.sets = args.options("--set");
    c.sweeps = args.options("--sweep");
    c.referenceFile = args.option("--reference");
    c.outDir = args.option("--out").value_or("bench-sweep");
    c.width = args.integer("--width", 320, {1});
    c.height = args.integer("--height", 180, {1});
    c.frames = args.integer("--frames", 20, {1});
    c.warmup = args.integer("--warmup", 3, {0});
    c.spp = args.option("--spp");
    c.seconds = args.option("--max-seconds");
    const auto shard = args.shard("--shard");
    c.timesFrom = args.path("--times-from");
    parseRoundOptions(args, c.rounds);
    const auto pos = args.expectPositionals(1, "bench --sweep expects exactly one project file");
    if (pos.empty())
        return usageError(*args.error(), "bench");
    if (c.sweeps.empty())
        return usageError("give at least one --sweep KEY=V1,V2,...", "bench");
    if (shard) {
        c.shard = *shard;
        // Every shard must be measured against one and the same reference.
        if (!c.referenceFile)
            return usageError("--shard needs --reference REF.exr: every shard is measured against the one "
                              "reference (trace it first, sharded too: `lpv reference --shard`, `lpv merge`)",
                              "bench");
    }
    c.projectFile = pos.front();
    return runSweepCommand(c);
}

int runSweepCommand(const SweepCommand& c, std::vector<SweepRun>* runsOut) {
    RenderRequest request;
    request.cameraName = c.cameraName;
    const std::vector<std::string>& sets = c.sets;
    const std::vector<std::string>& sweeps = c.sweeps;
    const std::optional<std::string>& referenceFile = c.referenceFile;
    const fs::path& outDir = c.outDir;
    const std::optional<int> width = c.width, height = c.height, frames = c.frames, warmup = c.warmup;
    const std::optional<std::string>& spp = c.spp;
    const std::optional<std::string>& seconds = c.seconds;
    const reference::ShardSpec& shard = c.shard;
    std::vector<std::string> all = sets;
    all.insert(all.end(), sweeps.begin(), sweeps.end());
    if (spp)
        all.push_back("reference.samplesPerPixel=" + *spp);
    if (seconds)
        all.push_back("reference.maxSeconds=" + *seconds);
    std::string planError;
    SetPlan plan = planSettings(all, planError);
    if (!planError.empty())
        return usageError(planError, "bench");
    // A --sweep of one value is still a swept key: it names the run (sweep.json,
    // sweep.md) instead of folding into the fixed settings like a --set.
    for (const std::string& s : sweeps) {
        const auto eq = s.find('=');
        if (eq == std::string::npos || s.find(',', eq) != std::string::npos)
            continue;
        const Setting swept{s.substr(0, eq), s.substr(eq + 1)};
        if (std::erase(plan.fixed, swept) == 0)
            continue;
        if (plan.combinations.empty())
            plan.combinations = {{}};
        for (auto& combination : plan.combinations)
            combination.push_back(swept);
    }
    // Timed frames must compute the LPV every frame, not reuse the first
    // frame's volumes (a later --set lpv.reuse=true wins).
    request.sets.push_back(kSweepBaseSet);
    for (const auto& [key, value] : plan.fixed)
        request.sets.push_back(key + "=" + value);
    request.projectFile = c.projectFile;
    int exitCode = kOk;
    auto loadedProject = loadProjectWithSets(request.projectFile, request.sets, "bench", exitCode);
    if (!loadedProject)
        return exitCode;
    const scene::Project project = std::move(*loadedProject);
    if (auto error = checkCombinations(plan, project.parameters, "--sweep"))
        return usageError(*error, "bench");
    const auto camera = pickCamera(project.scene, request.cameraName, request.projectFile);
    if (!camera)
        return kFailure;

    // Like for like (issue #22): a run with lpv.bounces = k is measured against
    // the reference's k-bounce layer: indirect1 for k = 1, the multi-bounce
    // layer when the reference was traced with --bounces k.
    bench::SweepSpec spec;
    spec.project = project;
    spec.projectDir = fs::absolute(request.projectFile).parent_path();
    spec.projectFile = request.projectFile;
    spec.camera = *camera;
    spec.width = *width;
    spec.height = *height;
    spec.frames = *frames;
    spec.warmup = *warmup;
    spec.rounds = c.rounds;
    std::optional<bench::SharedTiming> sharedTiming;
    if (c.timesFrom) {
        auto loaded = bench::loadSharedTiming(*c.timesFrom);
        if (!loaded) {
            std::cerr << "lpv: " << loaded.error().describe() << "\n";
            return kFailure;
        }
        sharedTiming = std::move(*loaded);
        spec.rounds.maxRounds = 0;
    }
    const std::vector<std::vector<Setting>> combinations =
        plan.combinations.empty() ? std::vector<std::vector<Setting>>{{}} : plan.combinations;
    int maxBounces = 1;
    for (const auto& combination : combinations)
        maxBounces = std::max(maxBounces, bench::bouncesOf(project.parameters, combination));
    reference::ReferenceImage ref;
    if (referenceFile) {
        auto loaded = bench::readReferenceExr(*referenceFile);
        if (!loaded) {
            std::cerr << "lpv: " << loaded.error().describe() << "\n";
            return kFailure;
        }
        ref = std::move(loaded->image);
        if (const auto bounces = loaded->bounces())
            spec.referenceBounces = *bounces;
        if (ref.width != *width || ref.height != *height) {
            std::cerr << "lpv: " << *referenceFile << " is " << ref.width << "x" << ref.height
                      << "; give the same --width and --height\n";
            return kFailure;
        }
    } else {
        // Traced here with as many bounces as the most any run has; sweeping
        // lpv.bounces over more than one value above 1 needs one reference each.
        for (const auto& combination : combinations)
            if (const int k = bench::bouncesOf(project.parameters, combination); k > 1 && k != maxBounces)
                return usageError("sweeping lpv.bounces over more than one value above 1 needs one reference per "
                                  "value: trace each with `lpv reference --bounces K` and sweep with --reference",
                                  "bench");
        scene::Project traceProject = project;
        (void)traceProject.parameters.setFromText("reference.bounces", std::to_string(maxBounces), "bench");
        auto traced = traceReference(traceProject, request.projectFile, *camera, {*width, *height, 0, true, {}});
        if (!traced)
            return kFailure;
        ref = std::move(traced->image);
        spec.referenceBounces = traced->bounces;
    }
    spec.combinations = combinations;
    if (auto problem = bench::checkSweep(spec, referenceFile.value_or("the traced reference")))
        return usageError(*problem, "bench");
    std::error_code ec;
    fs::create_directories(outDir, ec);
    if (ec) {
        std::cerr << "lpv: " << outDir.string() << ": cannot create the folder: " << ec.message() << "\n";
        return kFailure;
    }

    if (!shard.whole())
        fs::remove(outDir / "shard.json", ec); // a rerun into the folder of a killed one starts unfinished
    std::vector<int> runIndices;
    spec.combinations.clear();
    for (std::size_t index = 0; index < combinations.size(); ++index)
        if (bench::shardRunsCombination(shard, int(index))) {
            runIndices.push_back(int(index));
            spec.combinations.push_back(combinations[index]);
        }
    bench::SweepCallbacks callbacks;
    int lastRound = -1;
    callbacks.progress = [&lastRound](const bench::SweepProgress& p) {
        if (p.round < 0 && p.done < p.total)
            std::printf("\n== %s\n", p.label.c_str());
        if (p.round >= 0 && p.round != lastRound) {
            lastRound = p.round;
            std::printf("timing round %d ...\n", p.round + 1);
            std::fflush(stdout);
        }
        return true;
    };
    callbacks.runMeasured = [](const SweepRun& run) {
        std::printf("GPU memory: %s (LPV volumes %s)\nindirect: %s\nimage:    %s\n",
                    renderer::formatBytes(run.gpuBytes).c_str(), renderer::formatBytes(run.lpvBytes).c_str(),
                    reference::describe(run.indirect).c_str(), reference::describe(run.image).c_str());
    };
    callbacks.runDone = [&spec](const SweepRun& run) {
        if (spec.rounds.maxRounds <= 0)
            return;
        std::printf("\n== %s: %s over %d rounds (quartiles %.2f-%.2f ms)\n%s", sweepLabel(run.settings).c_str(),
                    bench::formatTiming(run.total).c_str(), run.total.rounds, run.total.q1, run.total.q3,
                    renderer::formatTimingTable(run.passes).c_str());
    };
    callbacks.warning = [](const std::string& w) { std::cerr << "lpv: warning: " << w << "\n"; };
    auto swept = bench::runSweep(spec, ref, callbacks);
    if (!swept) {
        std::cerr << "lpv: " << swept.error().describe() << "\n";
        return kFailure;
    }
    std::vector<SweepRun> runs = std::move(swept->runs);
    bench::SweepTimingInfo timing{swept->rounds, swept->stopReason, swept->load};
    if (sharedTiming) {
        if (auto ok = bench::applySharedTiming(*sharedTiming, project.parameters, runs); !ok) {
            std::cerr << "lpv: " << c.timesFrom->string() << ": " << ok.error().message << "\n";
            return kFailure;
        }
        timing = {sharedTiming->rounds,
                  sharedTiming->stopReason + "; times from " + c.timesFrom->filename().string() +
                      ", measured once per setting for all the scene's questions",
                  sharedTiming->load};
        for (const SweepRun& run : runs)
            std::printf("%s: %s (from %s)\n", sweepLabel(run.settings).c_str(), bench::formatTiming(run.total).c_str(),
                        c.timesFrom->string().c_str());
    }
    if (spec.rounds.maxRounds > 0)
        std::printf("\ntimed in %d interleaved round%s (%s); %s\n", swept->rounds, swept->rounds == 1 ? "" : "s",
                    swept->stopReason.c_str(),
                    swept->load.c_str());

    const renderer::GlInfo& gl = swept->gl;
    std::string command = "lpv bench " + request.projectFile + " --width " + std::to_string(*width) +
                          " --height " + std::to_string(*height) + " --frames " + std::to_string(*frames) +
                          " --warmup " + std::to_string(*warmup) +
                          (c.timesFrom ? " --times-from " + c.timesFrom->string() : roundOptionsText(c.rounds));
    for (const std::string& s : sweeps)
        command += " --sweep " + s;
    for (const std::string& s : sets)
        command += " --set " + s;
    if (referenceFile)
        command += " --reference " + *referenceFile;
    const std::string machine = describeMachine(gl.renderer, gl.version);
    if (!shard.whole()) {
        const auto referenceHash = bench::fileContentHash(*referenceFile);
        if (!referenceHash) {
            std::cerr << "lpv: " << referenceHash.error().describe() << "\n";
            return kFailure;
        }
        bench::SweepShard out{shard, int(combinations.size()), command, machine, *width, *height, *referenceFile,
                       fs::absolute(*referenceFile).string(), *referenceHash, runIndices, std::move(runs), {}, timing};
        for (const auto& [key, value] : bench::settingsOf(project.parameters))
            if (key.starts_with("output."))
                out.display.emplace_back(key, value);
        const auto written = bench::writeSweepShard(outDir, out);
        if (!written) {
            std::cerr << "lpv: " << written.error().describe() << "\n";
            return kFailure;
        }
        std::printf("wrote %s\n", written->string().c_str());
        std::printf("shard %s: %zu of %zu combinations; join the shards with `lpv bench merge`\n",
                    reference::formatShard(shard).c_str(), out.runs.size(), combinations.size());
        return kOk;
    }
    if (!writeSweepFiles(outDir, runs, *width, *height, command, machine, ref, "", timing, project.parameters))
        return kFailure;
    if (runsOut)
        *runsOut = std::move(runs);
    return kOk;
}

} // namespace lpv::cli
