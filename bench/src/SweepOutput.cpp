#include "lpv/bench/SweepOutput.h"

#include "lpv/bench/Pareto.h"
#include "lpv/bench/Plots.h"

#include "lpv/importers/ImageIO.h"
#include "lpv/reference/Preview.h"
#include "lpv/scene/Project.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <sstream>

namespace lpv::bench {

namespace fs = std::filesystem;

namespace {



// A centre crop of an irradiance image; one key gives every crop the same exposure.
scene::Image8 crop(const std::vector<glm::vec3>& pixels, int width, int height, float key) {
    const int w = std::min(width, 200), h = std::min(height, 150);
    return reference::previewImage(pixels, width, (width - w) / 2, (height - h) / 2, w, h, key);
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
    return {{"relMse", m.relMse},     {"noiseRelMse", m.noiseRelMse},     {"mare", m.mare},
            {"noiseMare", m.noiseMare}, {"ssim", m.ssim},                 {"meanTest", m.meanTest},
            {"meanReference", m.meanReference}};
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
    using Json = nlohmann::ordered_json;
    Json j{{"command", command},
           {"machine", machine},
           {"reference", {{"width", ref.width}, {"height", ref.height}, {"spp", ref.samplesPerPixel}}},
           {"runs", Json::array()}};
    for (const SweepRun& r : runs) {
        Json settings = Json::object();
        for (const auto& [key, value] : r.settings)
            settings[key] = value;
        Json passes = Json::array();
        for (const auto& p : r.passes)
            passes.push_back({{"pass", p.pass},
                              {"medianMs", p.medianMs},
                              {"minMs", p.minMs},
                              {"maxMs", p.maxMs},
                              {"frames", p.samples}});
        j["runs"].push_back({{"settings", settings},
                             {"bounces", r.bounces},
                             {"totalMs", r.totalMs},
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

std::string sweepMarkdown(const std::vector<SweepRun>& runs, const std::vector<bool>& front,
                          const std::string& command, const std::string& machine, const std::string& note,
                          const reference::ReferenceImage& ref, const std::vector<std::string>& plots) {
    std::ostringstream out;
    char buf[512];
    out << "# LPV settings: time against error\n\n`" << command << "`\n\nMachine: " << machine << "\n\n";
    if (!note.empty())
        out << note << "\n\n";
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
                      sweepLabel(r.settings).c_str(), r.totalMs, percent(r.indirect.mare).c_str(),
                      r.indirect.mareBelowNoise() ? " (below noise)" : "", r.indirect.relMse, r.indirect.ssim,
                      r.indirect.meanReference > 0.0 ? r.indirect.meanTest / r.indirect.meanReference : 0.0,
                      percent(r.image.mare).c_str(), r.image.ssim, front[i] ? "yes" : "");
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
    for (double target : {0.10, 0.05}) {
        const SweepRun* best = nullptr;
        for (const SweepRun& r : runs)
            if (r.indirect.mare <= target && (!best || r.totalMs < best->totalMs))
                best = &r;
        if (best)
            std::snprintf(buf, sizeof buf,
                          "Cheapest setting with indirect MARE <= %s: **%s**, %.3f ms (MARE %s).\n\n",
                          percent(target).c_str(), sweepLabel(best->settings).c_str(), best->totalMs,
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
                                                         const std::string& note) {
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
    std::vector<std::pair<double, double>> costError;
    for (const SweepRun& r : runs)
        costError.emplace_back(r.totalMs, r.indirect.mare);
    const std::vector<bool> front = paretoFront(costError);
    std::vector<PlotPoint> points;
    for (std::size_t i = 0; i < runs.size(); ++i)
        points.push_back({runs[i].totalMs, 100.0 * runs[i].indirect.mare, sweepLabel(runs[i].settings), front[i]});
    if (!writePng("error-time.png", scatterPlot("Indirect light error against GPU time",
                                                "total GPU ms per frame", "indirect MARE %", points)))
        return std::unexpected(*failure);
    // The crops show the layer the runs are measured against (the first run's bounce count).
    const std::vector<glm::vec3>& shownLayer =
        runs.empty() || runs.front().bounces == 1 ? ref.indirectOne : ref.indirectMulti;
    const float key = reference::meanLuminance(shownLayer, ref.coverage);
    std::vector<std::pair<std::string, scene::Image8>> crops{
        {"reference, " + std::to_string(runs.empty() ? 1 : runs.front().bounces) + " bounce",
         crop(shownLayer, ref.width, ref.height, key)}};
    for (const SweepRun& r : runs)
        crops.emplace_back(sweepLabel(r.settings), crop(r.indirectPixels, width, height, key));
    if (!writePng("crops.png", contactSheet(crops, 4)))
        return std::unexpected(*failure);

    const std::pair<const char*, std::string> texts[] = {
        {"sweep.csv", sweepCsv(runs, keys, passes)},
        {"sweep.json", sweepJson(runs, command, machine, ref)},
        {"sweep.md", sweepMarkdown(runs, front, command, machine, note, ref, plots)}};
    for (const auto& [name, text] : texts) {
        if (auto ok = scene::writeFileAtomically(outDir / name, text); !ok)
            return std::unexpected(ok.error());
        written.push_back(outDir / name);
    }
    return written;
}

} // namespace lpv::bench
