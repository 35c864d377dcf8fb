// `lpv bench PROJECT --sweep KEY=V1,V2,...`: every combination of the swept
// values, each timed per pass on the GPU (median/min/max after warm-up) and
// measured against the path-traced reference (indirect irradiance and final
// image); written as CSV, JSON, a Markdown report and PNG plots.
#include "BenchPlots.h"
#include "BenchReport.h"
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
)";
}

namespace {

struct SweepRun {
    std::vector<Setting> settings;
    std::vector<renderer::PassTiming> passes;
    double totalMs = 0.0;
    int bounces = 1;                     // lpv.bounces of this run
    reference::ErrorMetrics indirect;    // like for like: against the reference layer with lpv.bounces bounces
    reference::ErrorMetrics indirectOne; // against the one-bounce indirect irradiance
    reference::ErrorMetrics image;       // final image against the reference image
    std::vector<glm::vec3> indirectPixels;
};

std::string label(const std::vector<Setting>& settings) {
    std::string s;
    for (const auto& [key, value] : settings) {
        const auto dot = key.rfind('.');
        s += (s.empty() ? "" : " ") + (dot == std::string::npos ? key : key.substr(dot + 1)) + "=" + value;
    }
    return s.empty() ? "defaults" : s;
}

std::vector<glm::vec3> readRgb(const std::vector<float>& rgba) {
    std::vector<glm::vec3> out(rgba.size() / 4);
    for (std::size_t i = 0; i < out.size(); ++i)
        out[i] = {rgba[4 * i], rgba[4 * i + 1], rgba[4 * i + 2]};
    return out;
}

// A centre crop of an irradiance image; one key gives every crop the same exposure.
scene::Image8 crop(const std::vector<glm::vec3>& pixels, int width, int height, float key) {
    const int w = std::min(width, 200), h = std::min(height, 150);
    return previewImage(pixels, width, (width - w) / 2, (height - h) / 2, w, h, key);
}

double numeric(const std::string& value, std::size_t index) {
    double v = 0.0;
    auto [ptr, ec] = std::from_chars(value.data(), value.data() + value.size(), v);
    if (ec == std::errc() && ptr == value.data() + value.size())
        return v;
    if (value == "true" || value == "on")
        return 1.0;
    if (value == "false" || value == "off")
        return 0.0;
    return double(index); // enum values: their position in the sweep
}

std::string jsonString(const std::string& s) {
    std::string out = "\"";
    for (char c : s)
        out += c == '"' || c == '\\' ? std::string("\\") + c : std::string(1, c);
    return out + "\"";
}

std::string metricsJson(const reference::ErrorMetrics& m) {
    char buf[256];
    std::snprintf(
        buf, sizeof buf,
        "{\"relMse\": %.6g, \"noiseRelMse\": %.6g, \"mare\": %.6g, \"noiseMare\": %.6g, \"ssim\": %.6g, "
        "\"meanTest\": %.6g, \"meanReference\": %.6g}",
        m.relMse, m.noiseRelMse, m.mare, m.noiseMare, m.ssim, m.meanTest, m.meanReference);
    return buf;
}

std::string sweepCsv(const std::vector<SweepRun>& runs, const std::vector<std::string>& keys,
                     const std::vector<std::string>& passes) {
    std::ostringstream out;
    for (const auto& k : keys)
        out << k << ",";
    out << "total_ms";
    for (const auto& p : passes)
        out << "," << p << "_median_ms," << p << "_min_ms," << p << "_max_ms";
    out << ",lpv_bounces,indirect_relmse,indirect_mare,indirect_ssim,indirect_mean,reference_indirect_mean,"
           "indirect1_mare,image_relmse,image_mare,image_ssim,noise_indirect_relmse,noise_indirect_mare\n";
    for (const SweepRun& r : runs) {
        for (const auto& k : keys) {
            auto it = std::ranges::find(r.settings, k, &Setting::first);
            out << (it == r.settings.end() ? "" : it->second) << ",";
        }
        out << r.totalMs;
        for (const auto& p : passes) {
            auto it = std::ranges::find(r.passes, p, &renderer::PassTiming::pass);
            if (it == r.passes.end())
                out << ",,,";
            else
                out << "," << it->medianMs << "," << it->minMs << "," << it->maxMs;
        }
        out << "," << r.bounces << "," << r.indirect.relMse << "," << r.indirect.mare << "," << r.indirect.ssim
            << "," << r.indirect.meanTest << "," << r.indirect.meanReference << "," << r.indirectOne.mare << "," << r.image.relMse << "," << r.image.mare << "," << r.image.ssim
            << "," << r.indirect.noiseRelMse << "," << r.indirect.noiseMare << "\n";
    }
    return out.str();
}

std::string sweepJson(const std::vector<SweepRun>& runs, const std::string& command,
                      const std::string& machine, const reference::ReferenceImage& ref) {
    std::ostringstream out;
    out << "{\n  \"command\": " << jsonString(command) << ",\n  \"machine\": " << jsonString(machine)
        << ",\n  \"reference\": {\"width\": " << ref.width << ", \"height\": " << ref.height
        << ", \"spp\": " << ref.samplesPerPixel << "},\n  \"runs\": [\n";
    for (std::size_t i = 0; i < runs.size(); ++i) {
        const SweepRun& r = runs[i];
        out << "    {\"settings\": {";
        for (std::size_t k = 0; k < r.settings.size(); ++k)
            out << (k ? ", " : "") << jsonString(r.settings[k].first) << ": "
                << jsonString(r.settings[k].second);
        out << "}, \"bounces\": " << r.bounces << ", \"totalMs\": " << r.totalMs << ", \"passes\": [";
        for (std::size_t p = 0; p < r.passes.size(); ++p)
            out << (p ? ", " : "") << "{\"pass\": " << jsonString(r.passes[p].pass)
                << ", \"medianMs\": " << r.passes[p].medianMs << ", \"minMs\": " << r.passes[p].minMs
                << ", \"maxMs\": " << r.passes[p].maxMs << ", \"frames\": " << r.passes[p].samples << "}";
        out << "],\n     \"indirect\": " << metricsJson(r.indirect)
            << ", \"indirectOneBounce\": " << metricsJson(r.indirectOne)
            << ", \"image\": " << metricsJson(r.image) << "}" << (i + 1 < runs.size() ? "," : "") << "\n";
    }
    out << "  ]\n}\n";
    return out.str();
}

std::string percent(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f%%", 100.0 * v);
    return buf;
}

std::string sweepMarkdown(const std::vector<SweepRun>& runs, const std::vector<bool>& front,
                          const std::string& command, const std::string& machine,
                          const reference::ReferenceImage& ref, const std::vector<std::string>& plots) {
    std::ostringstream out;
    char buf[512];
    out << "# LPV settings: time against error\n\n`" << command << "`\n\nMachine: " << machine << "\n\n";
    std::snprintf(
        buf, sizeof buf,
        "Reference: path traced, %dx%d, %d spp in %.1f s. Its own noise on the indirect light: MARE %s "
        "(errors at or below it are marked *below noise*).\n\n",
        ref.width, ref.height, ref.samplesPerPixel, ref.seconds,
        runs.empty() ? "-" : percent(runs.front().indirect.noiseMare).c_str());
    out << buf;
    out << "Indirect: the LPV's indirect irradiance against the reference's layer with as many bounces as "
           "`lpv.bounces` (like for like); mean = the LPV's mean over the reference's.\n\n";
    out << "| settings | total GPU ms (sum of pass medians) | indirect MARE | indirect relMSE | indirect "
           "SSIM | indirect mean | image MARE | image SSIM | Pareto |\n|---|---:|---:|---:|---:|---:|---:|---:|:-:|\n";
    for (std::size_t i = 0; i < runs.size(); ++i) {
        const SweepRun& r = runs[i];
        std::snprintf(buf, sizeof buf, "| %s | %.3f | %s%s | %.4g | %.3f | %.2fx | %s | %.3f | %s |\n",
                      label(r.settings).c_str(), r.totalMs, percent(r.indirect.mare).c_str(),
                      r.indirect.mareBelowNoise() ? " (below noise)" : "", r.indirect.relMse, r.indirect.ssim,
                      r.indirect.meanReference > 0.0 ? r.indirect.meanTest / r.indirect.meanReference : 0.0,
                      percent(r.image.mare).c_str(), r.image.ssim, front[i] ? "yes" : "");
        out << buf;
    }
    out << "\n";
    for (double target : {0.10, 0.05}) {
        const SweepRun* best = nullptr;
        for (const SweepRun& r : runs)
            if (r.indirect.mare <= target && (!best || r.totalMs < best->totalMs))
                best = &r;
        if (best)
            std::snprintf(buf, sizeof buf,
                          "Cheapest setting with indirect MARE <= %s: **%s**, %.3f ms (MARE %s).\n\n",
                          percent(target).c_str(), label(best->settings).c_str(), best->totalMs,
                          percent(best->indirect.mare).c_str());
        else
            std::snprintf(buf, sizeof buf, "No setting of this sweep reaches indirect MARE <= %s.\n\n",
                          percent(target).c_str());
        out << buf;
    }
    for (const std::string& p : plots)
        out << "![" << p << "](" << p << ")\n\n";
    return out.str();
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

    std::vector<SweepRun> runs;
    for (const auto& combination : combinations) {
        SweepRun run;
        run.settings = combination;
        setup->project.parameters = base;
        for (const auto& [key, value] : combination)
            (void)setup->project.parameters.setFromText(key, value, "--sweep");
        (void)setup->project.parameters.setFromText("output.view", "final", "bench");
        std::printf("\n== %s\n", label(combination).c_str());
        if (*warmup > 0 && !renderFrames(*setup, *width, *height, *warmup))
            return kFailure;
        setup->renderer->timer().clearHistory();
        if (!renderFrames(*setup, *width, *height, *frames))
            return kFailure;
        run.passes = setup->renderer->timer().table();
        std::erase_if(run.passes, [](const renderer::PassTiming& t) { return t.samples == 0; });
        for (const auto& p : run.passes)
            run.totalMs += p.medianMs;
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

    // Columns and series: every swept key, every pass any run timed.
    std::vector<std::string> keys, passes;
    for (const auto& c : combinations)
        for (const auto& [k, v] : c)
            if (std::ranges::find(keys, k) == keys.end())
                keys.push_back(k);
    for (const SweepRun& r : runs)
        for (const auto& p : r.passes)
            if (std::ranges::find(passes, p.pass) == passes.end())
                passes.push_back(p.pass);

    std::vector<std::string> plots;
    auto writePng = [&](const std::string& name, const scene::Image8& img) {
        if (img.pixels.empty())
            return true;
        if (auto ok = importers::writeImage(outDir / name, img); !ok) {
            std::cerr << "lpv: " << ok.error().describe() << "\n";
            return false;
        }
        plots.push_back(name);
        std::printf("wrote %s\n", (outDir / name).string().c_str());
        return true;
    };
    for (const std::string& key : keys) {
        // Time per pass against this key, averaged over the other swept keys' values.
        std::vector<std::string> order;
        for (const SweepRun& r : runs)
            if (auto it = std::ranges::find(r.settings, key, &Setting::first);
                it != r.settings.end() && std::ranges::find(order, it->second) == order.end())
                order.push_back(it->second);
        std::vector<PlotSeries> series;
        for (const std::string& pass : passes) {
            PlotSeries s{pass, {}};
            for (std::size_t vi = 0; vi < order.size(); ++vi) {
                double sum = 0.0;
                int count = 0;
                for (const SweepRun& r : runs) {
                    auto sk = std::ranges::find(r.settings, key, &Setting::first);
                    auto p = std::ranges::find(r.passes, pass, &renderer::PassTiming::pass);
                    if (sk != r.settings.end() && sk->second == order[vi] && p != r.passes.end()) {
                        sum += p->medianMs;
                        ++count;
                    }
                }
                if (count > 0)
                    s.points.emplace_back(numeric(order[vi], vi), sum / count);
            }
            series.push_back(std::move(s));
        }
        if (!writePng("time-" + key + ".png",
                      linePlot("GPU time per pass against " + key, key, "median ms", series)))
            return kFailure;
    }
    std::vector<std::pair<double, double>> costError;
    for (const SweepRun& r : runs)
        costError.emplace_back(r.totalMs, r.indirect.mare);
    const std::vector<bool> front = paretoFront(costError);
    std::vector<PlotPoint> points;
    for (std::size_t i = 0; i < runs.size(); ++i)
        points.push_back({runs[i].totalMs, 100.0 * runs[i].indirect.mare, label(runs[i].settings), front[i]});
    if (!writePng("error-time.png", scatterPlot("Indirect light error against GPU time",
                                                "total GPU ms per frame", "indirect MARE %", points)))
        return kFailure;
    // The crops show the layer the runs are measured against (the first run's bounce count).
    const std::vector<glm::vec3>& shownLayer =
        runs.empty() || runs.front().bounces == 1 ? ref.indirectOne : ref.indirectMulti;
    const float key = meanLuminance(shownLayer, ref.coverage);
    std::vector<std::pair<std::string, scene::Image8>> crops{
        {"reference, " + std::to_string(runs.empty() ? 1 : runs.front().bounces) + " bounce",
         crop(shownLayer, ref.width, ref.height, key)}};
    for (const SweepRun& r : runs)
        crops.emplace_back(label(r.settings), crop(r.indirectPixels, *width, *height, key));
    if (!writePng("crops.png", contactSheet(crops, 4)))
        return kFailure;

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
    const std::optional<std::string> csv = (outDir / "sweep.csv").string(),
                                     json = (outDir / "sweep.json").string(),
                                     md = (outDir / "sweep.md").string();
    if (!writeReportFiles({{csv, sweepCsv(runs, keys, passes)},
                           {json, sweepJson(runs, command, machine, ref)},
                           {md, sweepMarkdown(runs, front, command, machine, ref, plots)}}))
        return kFailure;
    return kOk;
}

} // namespace lpv::cli
