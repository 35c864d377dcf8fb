#include "lpv/bench/SweepOutput.h"

#include "lpv/bench/Pareto.h"
#include "lpv/bench/Plots.h"
#include "lpv/bench/SweepRunJson.h"

#include "lpv/importers/ImageIO.h"
#include "lpv/renderer/DisplayMapping.h"
#include "lpv/renderer/GpuMemory.h"
#include "lpv/scene/Project.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <sstream>

namespace lpv::bench {

namespace fs = std::filesystem;

namespace {



// A centre crop of a linear image through the frame's display mapping; one
// mapping gives every crop the same exposure (issue #43: the reference is
// shown as the frame is, not through `--preview`'s x / (x + mean)).
scene::Image8 crop(const std::vector<glm::vec3>& pixels, int width, int height,
                   const renderer::DisplayMapping& mapping) {
    const int w = std::min(width, 200), h = std::min(height, 150);
    const int x0 = (width - w) / 2, y0 = (height - h) / 2;
    std::vector<glm::vec3> part(std::size_t(w) * std::size_t(h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            part[std::size_t(y) * std::size_t(w) + std::size_t(x)] =
                pixels[std::size_t(y0 + y) * std::size_t(width) + std::size_t(x0 + x)];
    return renderer::tonemapImage(part, w, h, mapping);
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


// Doubles written as nlohmann writes them, the shortest text that reads back
// to the same bits: a report read from sweep.json (--resume, a merged
// shard) has the figures of the sweep that wrote it, exactly.
nlohmann::ordered_json metricsJson(const reference::ErrorMetrics& m) {
    return {{"relMse", m.relMse},         {"noiseRelMse", m.noiseRelMse},     {"mare", m.mare},
            {"noiseMare", m.noiseMare},   {"logError", m.logError},           {"noiseLogError", m.noiseLogError},
            {"symmetricError", m.symmetricError()}, {"ssim", m.ssim},         {"meanTest", m.meanTest},
            {"meanReference", m.meanReference}};
}

std::string sweepCsv(const std::vector<SweepRun>& runs, const std::vector<std::string>& keys,
                     const std::vector<std::string>& passes) {
    std::ostringstream out;
    for (const auto& k : keys)
        out << k << ",";
    out << "total_ms,total_q1_ms,total_q3_ms,total_min_ms,total_max_ms,rounds,same_cost_as,gpu_bytes,lpv_bytes";
    for (const auto& p : passes)
        out << "," << p << "_median_ms," << p << "_min_ms," << p << "_max_ms";
    out << ",lpv_bounces,indirect_symmetric,noise_indirect_symmetric,indirect_mean_ratio,biased,indirect_relmse,"
           "indirect_mare,indirect_ssim,indirect_mean,reference_indirect_mean,indirect1_mare,image_relmse,"
           "image_mare,image_ssim,noise_indirect_relmse,noise_indirect_mare\n";
    for (std::size_t i = 0; i < runs.size(); ++i) {
        const SweepRun& r = runs[i];
        for (const auto& k : keys) {
            auto it = std::ranges::find(r.settings, k, &Setting::first);
            out << (it == r.settings.end() ? "" : it->second) << ",";
        }
        std::string same;
        for (std::size_t j : sameCostAs(runs, i)) // 1-based: the data row, as sweep.md numbers them
            same += (same.empty() ? "" : " ") + std::to_string(j + 1);
        out << r.totalMs << "," << r.total.q1 << "," << r.total.q3 << "," << r.total.min << "," << r.total.max
            << "," << r.total.rounds << "," << same << "," << r.gpuBytes << "," << r.lpvBytes;
        for (const auto& p : passes) {
            auto it = std::ranges::find(r.passes, p, &renderer::PassTiming::pass);
            if (it == r.passes.end())
                out << ",,,";
            else
                out << "," << it->medianMs << "," << it->minMs << "," << it->maxMs;
        }
        out << "," << r.bounces << "," << r.indirect.symmetricError() << "," << r.indirect.noiseSymmetricError()
            << "," << meanRatio(r.indirect) << "," << (biasedMean(meanRatio(r.indirect)) ? 1 : 0) << ","
            << r.indirect.relMse << "," << r.indirect.mare << "," << r.indirect.ssim << "," << r.indirect.meanTest
            << "," << r.indirect.meanReference << "," << r.indirectOne.mare << "," << r.image.relMse << ","
            << r.image.mare << "," << r.image.ssim << "," << r.indirect.noiseRelMse << "," << r.indirect.noiseMare
            << "\n";
    }
    return out.str();
}

std::string sweepJson(const std::vector<SweepRun>& runs, const std::string& command, const std::string& machine,
                      const reference::ReferenceImage& ref, const SweepTimingInfo& timing) {
    using Json = nlohmann::ordered_json;
    Json j{{"command", command},
           {"machine", machine},
           {"load", timing.load},
           {"timing", {{"rounds", timing.rounds}, {"stopReason", timing.stopReason}}},
           {"reference", {{"width", ref.width}, {"height", ref.height}, {"spp", ref.samplesPerPixel}}},
           {"runs", Json::array()}};
    for (std::size_t i = 0; i < runs.size(); ++i) {
        const SweepRun& r = runs[i];
        Json settings = Json::object();
        for (const auto& [key, value] : r.settings)
            settings[key] = value;
        Json passes = Json::array();
        for (std::size_t k = 0; k < r.passes.size(); ++k) {
            const auto& p = r.passes[k];
            Json pass{{"pass", p.pass}, {"medianMs", p.medianMs}, {"minMs", p.minMs}, {"maxMs", p.maxMs},
                      {"frames", p.samples}};
            if (k < r.passStats.size())
                pass["rounds"] = timingToJson<nlohmann::ordered_json>(r.passStats[k]);
            passes.push_back(pass);
        }
        Json same = Json::array();
        for (std::size_t s : sameCostAs(runs, i))
            same.push_back(s);
        j["runs"].push_back({{"settings", settings},
                             {"bounces", r.bounces},
                             {"totalMs", r.totalMs},
                             {"total", timingToJson<nlohmann::ordered_json>(r.total)},
                             {"sameCostAs", same},
                             {"gpuBytes", r.gpuBytes},
                             {"lpvBytes", r.lpvBytes},
                             {"biased", biasedMean(meanRatio(r.indirect))},
                             {"passes", passes},
                             {"indirect", metricsJson(r.indirect)},
                             {"indirectOneBounce", metricsJson(r.indirectOne)},
                             {"image", metricsJson(r.image)}});
    }
    return j.dump(2) + "\n";
}

std::string percent(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f%%", 100.0 * v);
    return buf;
}

// "12.3 ±0.4" (half the interquartile range over the rounds), or "12.3".
std::string timeCell(const SweepRun& r) {
    char buf[64];
    if (r.total.rounds > 1)
        std::snprintf(buf, sizeof buf, "%.2f ±%.2f", r.totalMs, 0.5 * r.total.spread());
    else
        std::snprintf(buf, sizeof buf, "%.2f", r.totalMs);
    return buf;
}

std::string sweepMarkdown(const std::vector<SweepRun>& runs, const std::vector<bool>& front,
                          const std::string& command, const std::string& machine, const std::string& note,
                          const reference::ReferenceImage& ref, const std::vector<std::string>& plots,
                          const SweepTimingInfo& timing) {
    std::ostringstream out;
    char buf[768];
    out << "# LPV settings: time against error\n\n`" << command << "`\n\nMachine: " << machine;
    if (!timing.load.empty())
        out << " (" << timing.load << ")";
    out << "\n\n";
    if (!note.empty())
        out << note << "\n\n";
    std::snprintf(
        buf, sizeof buf,
        "Reference: path traced, %dx%d, %d spp in %.1f s. Its own noise on the indirect light: symmetric error %s, "
        "MARE %s (errors at or below it are marked *below noise*).\n\n",
        ref.width, ref.height, ref.samplesPerPixel, ref.seconds,
        runs.empty() ? "-" : percent(runs.front().indirect.noiseSymmetricError()).c_str(),
        runs.empty() ? "-" : percent(runs.front().indirect.noiseMare).c_str());
    out << buf;
    if (timing.rounds > 0)
        out << "Time: the sum of the per-pass GPU medians of a frame, measured in " << timing.rounds
            << " interleaved rounds (each setting in turn, the order reversed every round; " << timing.stopReason
            << "); the median over the rounds, ± half the interquartile range. Settings whose times are the "
               "same within that noise (their interquartile ranges overlap, or their medians differ by less than the larger "
               "relative spread, at least "
            << int(100 * kSameCostFraction) << "%) are grouped in the *same cost* column.\n\n";
    out << "Error: the symmetric error of the LPV's indirect irradiance against the reference's layer with as many "
           "bounces as `lpv.bounces` (like for like): exp(mean |ln((t+e)/(r+e))|) - 1, too dark and too bright "
           "alike (docs/reference.md). Mean: the LPV's mean over the reference's; outside 0.8-1.25x the run is "
           "**biased**. MARE is kept beside it.\n\n";
    out << "| # | settings | GPU ms | same cost as | GPU memory | indirect symmetric error | indirect mean | "
           "indirect MARE | indirect SSIM | image MARE | Pareto |\n"
           "|---:|---|---:|---|---:|---:|---:|---:|---:|---:|:-:|\n";
    for (std::size_t i = 0; i < runs.size(); ++i) {
        const SweepRun& r = runs[i];
        std::string same;
        for (std::size_t j : sameCostAs(runs, i))
            same += (same.empty() ? "" : ", ") + std::to_string(j + 1);
        const double ratio = meanRatio(r.indirect);
        std::snprintf(buf, sizeof buf, "| %zu | %s | %s | %s | %s | %s%s | %.2fx%s | %s | %.3f | %s | %s |\n", i + 1,
                      sweepLabel(r.settings).c_str(), timeCell(r).c_str(), same.c_str(),
                      r.gpuBytes ? renderer::formatBytes(r.gpuBytes).c_str() : "-",
                      percent(r.indirect.symmetricError()).c_str(),
                      r.indirect.symmetricBelowNoise() ? " (below noise)" : "", ratio,
                      biasedMean(ratio) ? " **biased**" : "", percent(r.indirect.mare).c_str(), r.indirect.ssim,
                      percent(r.image.mare).c_str(), front[i] ? "yes" : "");
        out << buf;
    }
    out << "\n";
    for (const SweepRun& r : runs)
        if (r.solveSeconds > 0.0) {
            std::snprintf(buf, sizeof buf,
                          "%s: a radiosity solution solved in %.1f s to residual %.4g, paid once before any frame; "
                          "measured against the reference's multi-bounce layer (it holds every bounce).\n\n",
                          sweepLabel(r.settings).c_str(), r.solveSeconds, r.solveResidual);
            out << buf;
        }
    for (double fraction : kWithinBest) {
        if (const auto best = cheapestWithinBest(runs, fraction)) {
            const SweepRun& r = runs[*best];
            std::snprintf(buf, sizeof buf,
                          "Cheapest unbiased setting within %s of the lowest unbiased error: **%s**, %s ms, %s "
                          "(symmetric error %s, mean %.2fx).\n\n",
                          percent(fraction).c_str(), sweepLabel(r.settings).c_str(), timeCell(r).c_str(),
                          r.gpuBytes ? renderer::formatBytes(r.gpuBytes).c_str() : "-",
                          percent(r.indirect.symmetricError()).c_str(), meanRatio(r.indirect));
            out << buf;
        } else {
            out << "No setting of this sweep has its mean within 0.8-1.25x of the reference's.\n\n";
            break;
        }
    }
    for (const std::string& p : plots)
        out << "![" << p << "](" << p << ")\n\n";
    return out.str();
}

} // namespace

double meanRatio(const reference::ErrorMetrics& m) {
    return m.meanReference > 0.0 ? m.meanTest / m.meanReference : 0.0;
}

CostPoint timeErrorPoint(const SweepRun& run) {
    return timedPoint(run.total.rounds > 0 ? run.total : TimingStats{run.totalMs, run.totalMs, run.totalMs,
                                                                     run.totalMs, run.totalMs, 1},
                      run.indirect.symmetricError(), biasedMean(meanRatio(run.indirect)));
}

CostPoint memoryErrorPoint(const SweepRun& run) {
    return exactPoint(double(run.gpuBytes), run.indirect.symmetricError(), biasedMean(meanRatio(run.indirect)));
}

std::vector<std::size_t> sameCostAs(const std::vector<SweepRun>& runs, std::size_t index) {
    std::vector<std::size_t> out;
    if (index >= runs.size() || runs[index].total.rounds == 0)
        return out;
    for (std::size_t j = 0; j < runs.size(); ++j)
        if (j != index && runs[j].total.rounds > 0 && sameCost(runs[index].total, runs[j].total))
            out.push_back(j);
    return out;
}

std::optional<std::size_t> cheapestWithinBest(const std::vector<SweepRun>& runs, double fraction) {
    std::vector<CostPoint> points;
    double best = -1.0;
    for (const SweepRun& r : runs) {
        points.push_back(timeErrorPoint(r));
        if (!points.back().biased && (best < 0.0 || points.back().error < best))
            best = points.back().error;
    }
    if (best < 0.0)
        return std::nullopt;
    return cheapestWithin(points, best * (1.0 + fraction), kSameCostFraction);
}

std::string sweepLabel(const std::vector<Setting>& settings) {
    std::string s;
    for (const auto& [key, value] : settings) {
        const auto dot = key.rfind('.');
        s += (s.empty() ? "" : " ") + (dot == std::string::npos ? key : key.substr(dot + 1)) + "=" + value;
    }
    return s.empty() ? "defaults" : s;
}

scene::Expected<std::vector<fs::path>> writeSweepOutputs(const fs::path& outDir, const std::vector<SweepRun>& runs,
                                                         int width, int height, const std::string& command,
                                                         const std::string& machine,
                                                         const reference::ReferenceImage& ref,
                                                         const std::string& note, const SweepTimingInfo& timing,
                                                         const scene::ParameterSet& display) {
    // Columns and series: every swept key, every pass any run timed.
    std::vector<std::string> keys, passes;
    for (const SweepRun& r : runs)
        for (const auto& [k, v] : r.settings)
            if (std::ranges::find(keys, k) == keys.end())
                keys.push_back(k);
    for (const SweepRun& r : runs)
        for (const auto& p : r.passes)
            if (std::ranges::find(passes, p.pass) == passes.end())
                passes.push_back(p.pass);

    std::vector<std::string> plots;
    std::vector<fs::path> written;
    std::optional<scene::Error> failure;
    auto writePng = [&](const std::string& name, const scene::Image8& img) {
        if (img.pixels.empty())
            return true;
        if (auto ok = importers::writeImage(outDir / name, img); !ok) {
            failure = ok.error();
            return false;
        }
        plots.push_back(name);
        written.push_back(outDir / name);
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
            return std::unexpected(*failure);
    }
    std::vector<CostPoint> costError, memoryError;
    for (const SweepRun& r : runs) {
        costError.push_back(timeErrorPoint(r));
        memoryError.push_back(memoryErrorPoint(r));
    }
    const std::vector<bool> front = paretoFront(costError, kSameCostFraction);
    std::vector<PlotPoint> points;
    for (std::size_t i = 0; i < runs.size(); ++i) {
        const CostPoint& c = costError[i];
        points.push_back({c.cost, 100.0 * c.error, sweepLabel(runs[i].settings), front[i], c.costLow, c.costHigh,
                          c.biased});
    }
    if (!writePng("error-time.png",
                  scatterPlot("Indirect light error against GPU time", "total GPU ms per frame (log scale)",
                              "indirect symmetric error %", points, true)))
        return std::unexpected(*failure);
    if (std::ranges::all_of(runs, [](const SweepRun& r) { return r.gpuBytes > 0; })) {
        const std::vector<bool> memoryFront = paretoFront(memoryError, 0.0);
        std::vector<PlotPoint> memoryPoints;
        for (std::size_t i = 0; i < runs.size(); ++i)
            memoryPoints.push_back({double(runs[i].gpuBytes) / (1024.0 * 1024.0), 100.0 * memoryError[i].error,
                                    sweepLabel(runs[i].settings), memoryFront[i], 0.0, 0.0, memoryError[i].biased});
        if (!writePng("error-memory.png",
                      scatterPlot("Indirect light error against GPU memory", "GPU memory of the frame, MiB (log scale)",
                                  "indirect symmetric error %", memoryPoints, true)))
            return std::unexpected(*failure);
    }
    // The crops show the layer the runs are measured against (the first run's bounce count).
    const std::vector<glm::vec3>& shownLayer =
        runs.empty() || runs.front().bounces == 1 ? ref.indirectOne : ref.indirectMulti;
    const renderer::DisplayMapping layerMapping = renderer::meteredMapping(shownLayer, display);
    std::vector<std::pair<std::string, scene::Image8>> crops{
        {"reference, " + std::to_string(runs.empty() ? 1 : runs.front().bounces) + " bounce",
         crop(shownLayer, ref.width, ref.height, layerMapping)}};
    for (const SweepRun& r : runs)
        crops.emplace_back(sweepLabel(r.settings), crop(r.indirectPixels, width, height, layerMapping));
    if (!writePng("crops.png", contactSheet(crops, 4)))
        return std::unexpected(*failure);
    // The final frames beside the reference's image, one exposure metered on the reference.
    if (!runs.empty() && std::ranges::all_of(runs, [&](const SweepRun& r) {
            return r.imagePixels.size() == std::size_t(width) * std::size_t(height);
        })) {
        const renderer::DisplayMapping imageMapping = renderer::meteredMapping(ref.image, display);
        std::vector<std::pair<std::string, scene::Image8>> frames{
            {"reference", crop(ref.image, ref.width, ref.height, imageMapping)}};
        for (const SweepRun& r : runs)
            frames.emplace_back(sweepLabel(r.settings), crop(r.imagePixels, width, height, imageMapping));
        if (!writePng("frames.png", contactSheet(frames, 4)))
            return std::unexpected(*failure);
    }

    const std::pair<const char*, std::string> texts[] = {
        {"sweep.csv", sweepCsv(runs, keys, passes)},
        {"sweep.json", sweepJson(runs, command, machine, ref, timing)},
        {"sweep.md", sweepMarkdown(runs, front, command, machine, note, ref, plots, timing)}};
    for (const auto& [name, text] : texts) {
        if (auto ok = scene::writeFileAtomically(outDir / name, text); !ok)
            return std::unexpected(ok.error());
        written.push_back(outDir / name);
    }
    return written;
}

} // namespace lpv::bench
