#include "lpv/bench/Report.h"

#include <nlohmann/json.hpp>

#include <algorithm>
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

std::string runCell(const ReportRun* r) {
    if (!r)
        return "none of the sweeps";
    return "`" + r->setting + "`: " + fixed(r->totalMs, 1) + " ms, " + percent(r->indirectMare) + ", mean " +
           fixed(r->indirectMeanRatio, 2) + "x";
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
        run.indirectMare = r["indirect"].value("mare", 0.0);
        const double meanReference = r["indirect"].value("meanReference", 0.0);
        run.indirectMeanRatio = meanReference > 0.0 ? r["indirect"].value("meanTest", 0.0) / meanReference : 0.0;
        run.noiseMare = r["indirect"].value("noiseMare", 0.0);
        run.imageMare = r["image"].value("mare", 0.0);
        out.push_back(run);
    }
    return out;
}

// The lowest error among the settings whose mean is within 0.8-1.25x of the
// reference's (issue #24's band): a setting that shows almost no light can
// have a low MARE where the reference is dark.
const ReportRun* lowestInBand(const std::vector<ReportRun>& runs) {
    const ReportRun* best = nullptr;
    for (const ReportRun& r : runs)
        if (r.indirectMeanRatio >= 0.8 && r.indirectMeanRatio <= 1.25 &&
            (!best || r.indirectMare < best->indirectMare))
            best = &r;
    return best;
}

const ReportRun* cheapestBelow(const std::vector<ReportRun>& runs, double target) {
    const ReportRun* best = nullptr;
    for (const ReportRun& r : runs)
        if (r.indirectMare <= target && (!best || r.totalMs < best->totalMs))
            best = &r;
    return best;
}

std::string reportMarkdown(const std::vector<SceneReport>& scenes, const std::string& command,
                           const std::string& machine) {
    std::ostringstream out;
    out << "# LPV Studio: what accuracy costs in time\n\n`" << command << "`\n\nMachine: " << machine
        << "\n\nTime: the sum of the per-pass GPU medians of a frame (timer queries). Error: mean absolute "
           "relative error (MARE) of the LPV's indirect irradiance against the path-traced indirect "
           "irradiance at the same pixels, background masked, like for like: the reference's light reflected as "
           "many times as the LPV's `lpv.bounces`, from the same lights (the sky and emissive surfaces where the "
           "LPV injects them). Mean: the LPV's mean indirect irradiance over the reference's. Each question "
           "varies one key around the project's settings.\n\n";
    out << "| scene | project settings | cheapest at <= 10% | cheapest at <= 5% | lowest error found | lowest "
           "error with the mean within 0.8-1.25x |\n"
           "|---|---|---|---|---|---|\n";
    for (const SceneReport& s : scenes) {
        const ReportRun* base = nullptr;
        const ReportRun* lowest = nullptr;
        for (const ReportRun& r : s.runs) {
            if (r.projectSettings && !base)
                base = &r;
            if (!lowest || r.indirectMare < lowest->indirectMare)
                lowest = &r;
        }
        out << "| " << s.name << " | "
            << (base ? fixed(base->totalMs, 1) + " ms, " + percent(base->indirectMare) + ", mean " +
                           fixed(base->indirectMeanRatio, 2) + "x"
                     : "-")
            << " | "
            << runCell(cheapestBelow(s.runs, 0.10)) << " | " << runCell(cheapestBelow(s.runs, 0.05)) << " | "
            << runCell(lowest) << " | " << runCell(lowestInBand(s.runs)) << " |\n";
    }
    for (const SceneReport& s : scenes) {
        out << "\n## " << s.name << "\n\nReference: " << s.referenceNote;
        if (!s.runs.empty())
            out << "; its own noise on the indirect light: MARE " << percent(s.runs.front().noiseMare);
        out << ".\n\n| question | setting | GPU ms | indirect MARE | indirect mean (LPV / reference) | image "
               "MARE |\n|---|---|---:|---:|---:|---:|\n";
        for (const ReportRun& r : s.runs)
            out << "| " << r.question << " | `" << r.setting << "`" << (r.projectSettings ? " (project)" : "")
                << " | " << fixed(r.totalMs, 2) << " | " << percent(r.indirectMare) << " | "
                << fixed(r.indirectMeanRatio, 2) << "x | " << percent(r.imageMare) << " |\n";
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
                   {"runs", Json::array()},
                   {"radiosity", Json::array()},
                   {"failures", s.failures}};
        for (const ReportRun& r : s.runs)
            scene["runs"].push_back({{"question", r.question},
                                     {"setting", r.setting},
                                     {"projectSettings", r.projectSettings},
                                     {"totalMs", r.totalMs},
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
