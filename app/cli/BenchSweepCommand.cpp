// `lpv bench PROJECT --sweep KEY=V1,V2,...`: every combination of the swept
// values, each timed per pass on the GPU (median/min/max after warm-up) and
// measured against the path-traced reference (indirect irradiance and final
// image); written as CSV, JSON, a Markdown report and PNG plots.
#include "BenchReport.h"
#include "BenchSweep.h"
#include "BenchSweepShard.h"
#include "Cli.h"
#include "ReferenceFile.h"
#include "ReferenceTrace.h"
#include "RenderSetup.h"
#include "SetSweep.h"

#include "lpv/importers/ImageIO.h"
#include "lpv/reference/Metrics.h"

#include <algorithm>
#include <charconv>
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
measures per-pass GPU time (median/min/max over --frames after --warmup) and
the error of the LPV's indirect irradiance (output.view=indirect) and of the
final image against the path-traced reference (`lpv reference`): relMSE,
MARE, SSIM and the mean's ratio, background masked, beside the reference's
own noise. Like for like: a run with lpv.bounces = k is measured against the
reference's k-bounce light (its indirect1 layer for k = 1, its multi-bounce
layer when traced with --bounces k), and the reference traces the sky and
emissive surfaces where the LPV injects them (reference.skyLight and
reference.emissiveLight on auto). Writes
into --out: sweep.csv, sweep.json, sweep.md (the cheapest settings reaching
10% and 5% indirect MARE), time-<KEY>.png (time per pass against each swept
key), error-time.png (indirect MARE against total time, Pareto front
marked) and crops.png (reference and each setting's indirect light).

  --reference REF.exr   Reference traced beforehand at the same size and
                        camera; without it one is traced first (--spp,
                        --max-seconds, reference.* parameters)
  --out DIR             Output folder (default bench-sweep)
  --width N --height N  Image size (default 320x180, as `lpv reference`)
  --frames N --warmup N Timed frames (default 20) after warm-up frames (default 3)
  --camera NAME --set KEY=VALUE
  --shard I/N           Render only the combinations whose index is I modulo N
                        (0-based), for a cluster: needs --reference; writes
                        DIR/shard.json and DIR/run-K.exr, which `lpv bench merge`
                        joins into the files above (docs/cluster.md)
)";
}

namespace {

std::vector<glm::vec3> readRgb(const std::vector<float>& rgba) {
    std::vector<glm::vec3> out(rgba.size() / 4);
    for (std::size_t i = 0; i < out.size(); ++i)
        out[i] = {rgba[4 * i], rgba[4 * i + 1], rgba[4 * i + 2]};
    return out;
}

} // namespace

int benchSweep(Args args) {
    RenderRequest request;
    request.cameraName = args.option("--camera");
    std::vector<std::string> sets = args.options("--set");
    const std::vector<std::string> sweeps = args.options("--sweep");
    const auto referenceFile = args.option("--reference");
    const fs::path outDir = args.option("--out").value_or("bench-sweep");
    const auto width = parseCount(args.option("--width").value_or("320"), 1);
    const auto height = parseCount(args.option("--height").value_or("180"), 1);
    const auto frames = parseCount(args.option("--frames").value_or("20"), 1);
    const auto warmup = parseCount(args.option("--warmup").value_or("3"), 0);
    const auto spp = args.option("--spp");
    const auto seconds = args.option("--max-seconds");
    const auto shardText = args.option("--shard");
    if (!args.missingValue().empty())
        return usageError(args.missingValue() + " needs a value", "bench");
    if (auto unknown = args.unknownOption())
        return usageError("unknown option '" + *unknown + "'", "bench");
    const auto pos = args.positionals();
    if (pos.size() != 1)
        return usageError("bench --sweep expects exactly one project file", "bench");
    if (!width || !height || !frames || !warmup)
        return usageError("--width, --height and --frames must be positive integers, --warmup zero or more",
                          "bench");
    if (sweeps.empty())
        return usageError("give at least one --sweep KEY=V1,V2,...", "bench");
    reference::ShardSpec shard;
    if (shardText) {
        auto parsed = reference::parseShard(*shardText);
        if (!parsed)
            return usageError(parsed.error().message, "bench");
        shard = *parsed;
        // Every shard must be measured against one and the same reference.
        if (!referenceFile)
            return usageError("--shard needs --reference REF.exr: every shard is measured against the one "
                              "reference (trace it first, sharded too: `lpv reference --shard`, `lpv merge`)",
                              "bench");
    }
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
    request.sets.push_back("lpv.reuse=false");
    for (const auto& [key, value] : plan.fixed)
        request.sets.push_back(key + "=" + value);
    request.projectFile = pos.front();
    int exitCode = kOk;
    auto setup = prepareRender(request, "bench", exitCode);
    if (!setup)
        return exitCode;
    if (auto error = checkCombinations(plan, setup->project.parameters, "--sweep"))
        return usageError(*error, "bench");

    // Like for like (issue #22): a run with lpv.bounces = k is measured against
    // the reference's k-bounce layer: indirect1 for k = 1, the multi-bounce
    // layer when the reference was traced with --bounces k.
    const std::vector<std::vector<Setting>> combinations =
        plan.combinations.empty() ? std::vector<std::vector<Setting>>{{}} : plan.combinations;
    const scene::ParameterSet base = setup->project.parameters;
    auto bouncesOf = [&](const std::vector<Setting>& combination) {
        scene::ParameterSet p = base;
        for (const auto& [key, value] : combination)
            (void)p.setFromText(key, value, "--sweep");
        return p.getInt("lpv.bounces");
    };
    int maxBounces = 1;
    for (const auto& c : combinations)
        maxBounces = std::max(maxBounces, bouncesOf(c));
    int refBounces = 0; // 0: unknown (a reference file without lpv:bounces)
    reference::ReferenceImage ref;
    if (referenceFile) {
        auto loaded = readReferenceExr(*referenceFile);
        if (!loaded) {
            std::cerr << "lpv: " << loaded.error().describe() << "\n";
            return kFailure;
        }
        ref = std::move(loaded->image);
        if (auto it = loaded->attributes.find("lpv:seconds"); it != loaded->attributes.end())
            ref.seconds = std::atof(it->second.c_str());
        if (auto it = loaded->attributes.find("lpv:bounces"); it != loaded->attributes.end())
            refBounces = std::atoi(it->second.c_str());
        if (ref.width != *width || ref.height != *height) {
            std::cerr << "lpv: " << *referenceFile << " is " << ref.width << "x" << ref.height
                      << "; give the same --width and --height\n";
            return kFailure;
        }
        for (const auto& c : combinations)
            if (const int k = bouncesOf(c); k > 1 && k != refBounces)
                return usageError("lpv.bounces=" + std::to_string(k) + " is measured against a reference with " +
                                      std::to_string(k) + " bounces, and " + *referenceFile + " has " +
                                      (refBounces > 0 ? std::to_string(refBounces) : "an unrecorded number of") +
                                      " (trace one with `lpv reference --bounces " + std::to_string(k) +
                                      "`, one reference per lpv.bounces value, as `lpv bench report` does)",
                                  "bench");
    } else {
        // Traced here with as many bounces as the most any run has.
        scene::Project traceProject = setup->project;
        (void)traceProject.parameters.setFromText("reference.bounces", std::to_string(maxBounces), "bench");
        auto traced =
            traceReference(traceProject, request.projectFile, setup->camera, {*width, *height, 0, true, {}});
        if (!traced)
            return kFailure;
        ref = std::move(traced->image);
        refBounces = traced->bounces;
        for (const auto& c : combinations)
            if (const int k = bouncesOf(c); k > 1 && k != refBounces)
                return usageError("sweeping lpv.bounces over more than one value above 1 needs one reference per "
                                  "value: trace each with `lpv reference --bounces K` and sweep with --reference",
                                  "bench");
    }
    std::error_code ec;
    fs::create_directories(outDir, ec);
    if (ec) {
        std::cerr << "lpv: " << outDir.string() << ": cannot create the folder: " << ec.message() << "\n";
        return kFailure;
    }

    if (!shard.whole())
        fs::remove(outDir / "shard.json", ec); // a rerun into the folder of a killed one starts unfinished
    std::vector<SweepRun> runs;
    std::vector<int> runIndices;
    for (std::size_t index = 0; index < combinations.size(); ++index) {
        if (!shardRunsCombination(shard, int(index)))
            continue;
        const auto& combination = combinations[index];
        runIndices.push_back(int(index));
        SweepRun run;
        run.settings = combination;
        setup->project.parameters = base;
        for (const auto& [key, value] : combination)
            (void)setup->project.parameters.setFromText(key, value, "--sweep");
        (void)setup->project.parameters.setFromText("output.view", "final", "bench");
        std::printf("\n== %s\n", sweepLabel(combination).c_str());
        if (*warmup > 0 && !renderFrames(*setup, *width, *height, *warmup))
            return kFailure;
        setup->renderer->timer().clearHistory();
        if (!renderFrames(*setup, *width, *height, *frames))
            return kFailure;
        run.passes = setup->renderer->timer().table();
        std::erase_if(run.passes, [](const renderer::PassTiming& t) { return t.samples == 0; });
        for (const auto& p : run.passes)
            run.totalMs += p.medianMs;
        // The measured frame must follow a frame of the same settings: the
        // camera's geometry volume reads the previous frame's G-buffer, so
        // the first frame of a combination depends on what ran before it
        // (in a shard, another combination than in one process).
        if (*warmup == 0 && *frames == 1 && !renderFrames(*setup, *width, *height, 1))
            return kFailure;
        const auto image = readRgb(setup->renderer->readHdr());
        // The indirect view: the LPV irradiance at the same pixels, no albedo, no tonemap.
        (void)setup->project.parameters.setFromText("output.view", "indirect", "bench");
        if (!renderFrames(*setup, *width, *height, 1))
            return kFailure;
        run.indirectPixels = readRgb(setup->renderer->readHdr());
        auto measure = [&](const std::vector<glm::vec3>& test, const std::vector<glm::vec3>& r,
                           const std::vector<glm::vec3>& var) {
            return reference::compareImages({*width, *height, &test}, {ref.width, ref.height, &r}, &var,
                                            &ref.coverage);
        };
        run.bounces = setup->project.parameters.getInt("lpv.bounces");
        run.indirect = run.bounces == 1 ? measure(run.indirectPixels, ref.indirectOne, ref.indirectOneVariance)
                                        : measure(run.indirectPixels, ref.indirectMulti, ref.indirectMultiVariance);
        run.indirectOne = measure(run.indirectPixels, ref.indirectOne, ref.indirectOneVariance);
        run.image = measure(image, ref.image, ref.imageVariance);
        std::printf("%s", renderer::formatTimingTable(run.passes).c_str());
        std::printf("indirect: %s\nimage:    %s\n", reference::describe(run.indirect).c_str(),
                    reference::describe(run.image).c_str());
        runs.push_back(std::move(run));
    }

    const renderer::GlInfo& gl = setup->context->info();
    std::string command = "lpv bench " + request.projectFile + " --width " + std::to_string(*width) +
                          " --height " + std::to_string(*height) + " --frames " + std::to_string(*frames) +
                          " --warmup " + std::to_string(*warmup);
    for (const std::string& s : sweeps)
        command += " --sweep " + s;
    for (const std::string& s : sets)
        command += " --set " + s;
    if (referenceFile)
        command += " --reference " + *referenceFile;
    const std::string machine = describeMachine(gl.renderer, gl.version);
    if (!shard.whole()) {
        const auto referenceHash = fileContentHash(*referenceFile);
        if (!referenceHash) {
            std::cerr << "lpv: " << referenceHash.error().describe() << "\n";
            return kFailure;
        }
        SweepShard out{shard, int(combinations.size()), command, machine, *width, *height, *referenceFile,
                       fs::absolute(*referenceFile).string(), *referenceHash, runIndices, std::move(runs)};
        if (!writeSweepShard(outDir, out))
            return kFailure;
        std::printf("shard %s: %zu of %zu combinations; join the shards with `lpv bench merge`\n",
                    reference::formatShard(shard).c_str(), out.runs.size(), combinations.size());
        return kOk;
    }
    if (!writeSweepOutputs(outDir, runs, *width, *height, command, machine, ref))
        return kFailure;
    return kOk;
}

} // namespace lpv::cli
