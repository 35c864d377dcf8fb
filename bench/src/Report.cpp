#include "lpv/bench/Report.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace lpv::bench {

namespace fs = std::filesystem;
using Json = nlohmann::json;

namespace {

std::string percent(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f%%", 100.0 * v);
    return buf;
}

std::string fixed(double v, int digits) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.*f", digits, v);
    return buf;
}

// "12.3 ±0.4 ms" (half the interquartile range over the rounds).
std::string timeText(const ReportRun& r) {
    if (r.time.rounds > 1)
        return fixed(r.totalMs, 1) + " ±" + fixed(0.5 * r.time.spread(), 1) + " ms";
    return fixed(r.totalMs, 1) + " ms";
}

std::string bytesText(std::uint64_t bytes) {
    if (bytes == 0)
        return "-";
    return fixed(double(bytes) / (1024.0 * 1024.0), 1) + " MiB";
}

std::string figures(const ReportRun& r) {
    return timeText(r) + ", " + bytesText(r.gpuBytes) + ", " + percent(r.indirectSymmetric) + ", mean " +
           fixed(r.indirectMeanRatio, 2) + "x" + (r.biased() ? " **biased**" : "");
}

std::string runCell(const ReportRun* r) {
    if (!r)
        return "none (no run's mean within 0.8-1.25x)";
    return "`" + r->setting + "`: " + figures(*r);
}

ReportRun reportRun(const std::string& question, const std::vector<Setting>& settings,
                    const scene::ParameterSet& current) {
    ReportRun run;
    run.question = question;
    run.projectSettings = true;
    for (const auto& [key, value] : settings) {
        run.setting += (run.setting.empty() ? "" : " ") + key + "=" + value;
        scene::ParameterSet changed = current;
        if (!changed.setFromText(key, value) || !(changed.get(key) == current.get(key)))
            run.projectSettings = false;
    }
    return run;
}

} // namespace

std::vector<ReportRun> reportRunsOf(const std::string& question, const std::vector<SweepRun>& runs,
                                    const scene::ParameterSet& current) {
    std::vector<ReportRun> out;
    for (const SweepRun& r : runs) {
        ReportRun run = reportRun(question, r.settings, current);
        run.totalMs = r.totalMs;
        run.time = r.total;
        run.gpuBytes = r.gpuBytes;
        run.indirectSymmetric = r.indirect.symmetricError();
        run.noiseSymmetric = r.indirect.noiseSymmetricError();
        run.indirectMare = r.indirect.mare;
        run.indirectMeanRatio = r.indirect.meanReference > 0.0 ? r.indirect.meanTest / r.indirect.meanReference : 0.0;
        run.noiseMare = r.indirect.noiseMare;
        run.imageMare = r.image.mare;
        out.push_back(run);
    }
    return out;
}

std::vector<ReportRun> reportRunsFromSweepJson(const fs::path& file, const std::string& question,
                                               const scene::ParameterSet& current) {
    std::vector<ReportRun> out;
    std::ifstream in(file);
    const Json j = Json::parse(in, nullptr, false);
    if (j.is_discarded() || !j.contains("runs"))
        return out;
    for (const Json& r : j["runs"]) {
        std::vector<Setting> settings;
        for (const auto& [key, value] : r["settings"].items())
            settings.emplace_back(key, value.get<std::string>());
        ReportRun run = reportRun(question, settings, current);
        run.totalMs = r.value("totalMs", 0.0);
        if (r.contains("total") && r["total"].is_object()) {
            const Json& t = r["total"];
            run.time = {t.value("medianMs", 0.0), t.value("q1Ms", 0.0), t.value("q3Ms", 0.0),
                        t.value("minMs", 0.0),    t.value("maxMs", 0.0), t.value("rounds", 0)};
        }
        run.gpuBytes = r.value("gpuBytes", std::uint64_t(0));
        run.indirectSymmetric = std::expm1(r["indirect"].value("logError", 0.0));
        run.noiseSymmetric = std::expm1(r["indirect"].value("noiseLogError", 0.0));
        run.indirectMare = r["indirect"].value("mare", 0.0);
        const double meanReference = r["indirect"].value("meanReference", 0.0);
        run.indirectMeanRatio = meanReference > 0.0 ? r["indirect"].value("meanTest", 0.0) / meanReference : 0.0;
        run.noiseMare = r["indirect"].value("noiseMare", 0.0);
        run.imageMare = r["image"].value("mare", 0.0);
        out.push_back(run);
    }
    return out;
}

const ReportRun* lowestInBand(const std::vector<ReportRun>& runs) {
    const ReportRun* best = nullptr;
    for (const ReportRun& r : runs)
        if (!r.biased() && (!best || r.indirectSymmetric < best->indirectSymmetric))
            best = &r;
    return best;
}

const ReportRun* cheapestWithinBest(const std::vector<ReportRun>& runs, double fraction) {
    const ReportRun* best = lowestInBand(runs);
    if (!best)
        return nullptr;
    std::vector<CostPoint> points;
    for (const ReportRun& r : runs)
        points.push_back(timedPoint(r.time.rounds > 0 ? r.time : TimingStats{r.totalMs, r.totalMs, r.totalMs,
                                                                            r.totalMs, r.totalMs, 1},
                                    r.indirectSymmetric, r.biased()));
    const auto index = cheapestWithin(points, best->indirectSymmetric * (1.0 + fraction), kSameCostFraction);
    return index ? &runs[*index] : nullptr;
}

std::string reportMarkdown(const std::vector<SceneReport>& scenes, const std::string& command,
                           const std::string& machine) {
    std::ostringstream out;
    out << "# LPV Studio: what accuracy costs in time\n\n`" << command << "`\n\nMachine: " << machine
        << "\n\nTime: the sum of the per-pass GPU medians of a frame (timer queries), measured for every distinct "
           "setting of a scene once, all of them together in interleaved rounds (each in turn, the order "
           "reversed every round), and given as the median over the rounds ± half the interquartile range. A "
           "setting that several questions contain has that one time. Two settings whose times are the same "
           "within that noise (interquartile ranges overlap, or medians differ by less than the larger relative "
           "spread, at least 5%) are the same cost. Memory: the GPU memory of the frame's resources (frame graph "
           "and LPV volumes), to the byte. Error: the symmetric error of the LPV's indirect irradiance against "
           "the path-traced indirect irradiance at the same pixels, exp(mean |ln((t+e)/(r+e))|) - 1, too dark and "
           "too bright alike (MARE rewarded a dark LPV; docs/reference.md), background masked, like for like: the "
           "reference's light reflected as many times as the LPV's `lpv.bounces`, from the same lights (the sky "
           "and emissive surfaces where the LPV injects them). Mean: the LPV's mean indirect irradiance over the "
           "reference's; outside 0.8-1.25x a run is **biased**. Each question varies one key around the "
           "project's settings.\n\n";
    out << "| scene | project settings | cheapest within 10% of the best unbiased error | cheapest within 25% | "
           "lowest error found | lowest unbiased error |\n"
           "|---|---|---|---|---|---|\n";
    for (const SceneReport& s : scenes) {
        const ReportRun* base = nullptr;
        const ReportRun* lowest = nullptr;
        for (const ReportRun& r : s.runs) {
            if (r.projectSettings && !base)
                base = &r;
            if (!lowest || r.indirectSymmetric < lowest->indirectSymmetric)
                lowest = &r;
        }
        out << "| " << s.name << " | " << (base ? figures(*base) : "-") << " | "
            << runCell(cheapestWithinBest(s.runs, 0.10)) << " | " << runCell(cheapestWithinBest(s.runs, 0.25))
            << " | " << runCell(lowest) << " | " << runCell(lowestInBand(s.runs)) << " |\n";
    }
    for (const SceneReport& s : scenes) {
        out << "\n## " << s.name << "\n\nReference: " << s.referenceNote;
        if (!s.runs.empty())
            out << "; its own noise on the indirect light: symmetric error " << percent(s.runs.front().noiseSymmetric)
                << ", MARE " << percent(s.runs.front().noiseMare);
        out << ".";
        if (!s.timingNote.empty())
            out << " Times: " << s.timingNote << ".";
        out << "\n\n| question | setting | GPU ms | GPU memory | indirect symmetric error | indirect mean (LPV / "
               "reference) | indirect MARE | image MARE |\n|---|---|---:|---:|---:|---:|---:|---:|\n";
        for (const ReportRun& r : s.runs)
            out << "| " << r.question << " | `" << r.setting << "`" << (r.projectSettings ? " (project)" : "")
                << " | " << timeText(r) << " | " << bytesText(r.gpuBytes) << " | " << percent(r.indirectSymmetric)
                << " | " << fixed(r.indirectMeanRatio, 2) << "x" << (r.biased() ? " **biased**" : "") << " | "
                << percent(r.indirectMare) << " | " << percent(r.imageMare) << " |\n";
        std::vector<std::string> questions;
        for (const ReportRun& r : s.runs)
            if (std::ranges::find(questions, r.question) == questions.end())
                questions.push_back(r.question);
        out << "\nPlots:";
        for (const std::string& q : questions)
            if (q == "bounces" || q == "sky") { // one sweep per value, in QUESTION/VALUE/
                for (const ReportRun& r : s.runs)
                    if (r.question == q && r.setting.find('=') != std::string::npos)
                        out << " [" << r.setting << "](" << s.name << "/" << q << "/"
                            << r.setting.substr(r.setting.find('=') + 1) << "/sweep.md)";
            } else {
                out << " [" << q << "](" << s.name << "/" << q << "/sweep.md)";
            }
        out << "\n\n### Radiosity against solve time\n\n" << s.radiosityNote << "\n\n";
        if (!s.radiosity.empty()) {
            out << "| solve time | residual | indirect MARE | indirect mean (radiosity / reference) | image MARE | "
                   "image SSIM |\n|---:|---:|---:|---:|---:|---:|\n";
            for (const RadiosityPoint& p : s.radiosity)
                out << "| " << fixed(p.seconds, 1) << " s | " << fixed(p.residual, 5) << " | "
                    << percent(p.indirect.mare) << (p.indirect.mareBelowNoise() ? " (below noise)" : "") << " | "
                    << fixed(p.indirect.meanReference > 0.0 ? p.indirect.meanTest / p.indirect.meanReference : 0.0, 2)
                    << "x | " << percent(p.image.mare) << " | " << fixed(p.image.ssim, 3) << " |\n";
        }
        for (const std::string& f : s.failures)
            out << "\n**Failed:** " << f << "\n";
    }
    return out.str();
}

std::string reportJson(const std::vector<SceneReport>& scenes, const std::string& command,
                       const std::string& machine) {
    Json j{{"command", command}, {"machine", machine}, {"scenes", Json::array()}};
    for (const SceneReport& s : scenes) {
        Json scene{{"name", s.name},
                   {"reference", s.referenceNote},
                   {"timing", s.timingNote},
                   {"runs", Json::array()},
                   {"radiosity", Json::array()},
                   {"failures", s.failures}};
        for (const ReportRun& r : s.runs)
            scene["runs"].push_back({{"question", r.question},
                                     {"setting", r.setting},
                                     {"projectSettings", r.projectSettings},
                                     {"totalMs", r.totalMs},
                                     {"time",
                                      {{"medianMs", r.time.median},
                                       {"q1Ms", r.time.q1},
                                       {"q3Ms", r.time.q3},
                                       {"minMs", r.time.min},
                                       {"maxMs", r.time.max},
                                       {"rounds", r.time.rounds}}},
                                     {"gpuBytes", r.gpuBytes},
                                     {"indirectSymmetric", r.indirectSymmetric},
                                     {"noiseSymmetric", r.noiseSymmetric},
                                     {"biased", r.biased()},
                                     {"indirectMare", r.indirectMare},
                                     {"indirectMeanRatio", r.indirectMeanRatio},
                                     {"noiseMare", r.noiseMare},
                                     {"imageMare", r.imageMare}});
        for (const RadiosityPoint& p : s.radiosity)
            scene["radiosity"].push_back(
                {{"seconds", p.seconds},
                 {"residual", p.residual},
                 {"indirectMare", p.indirect.mare},
                 {"indirectMeanRatio",
                  p.indirect.meanReference > 0.0 ? p.indirect.meanTest / p.indirect.meanReference : 0.0},
                 {"imageMare", p.image.mare},
                 {"imageRelMse", p.image.relMse}});
        j["scenes"].push_back(scene);
    }
    return j.dump(2) + "\n";
}

} // namespace lpv::bench
