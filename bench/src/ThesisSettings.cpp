#include "lpv/bench/ThesisSettings.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <set>

namespace lpv::bench {

namespace {

// Which of our passes each of the thesis application's phases sums.
struct PhaseSpec {
    const char* name;
    std::set<std::string> passes;
    std::optional<double> ThesisFigures::*thesisMs;
};

const std::vector<PhaseSpec>& phaseSpecs() {
    static const std::vector<PhaseSpec> kSpecs = {
        {"shadow maps", {"shadowMaps"}, &ThesisFigures::shadowMaps},
        {"RSM", {"rsm", "localRsm", "emissiveVpls"}, &ThesisFigures::rsm},
        {"injection",
         {"lpvInjection", "skyInjection", "skyHeight", "lpvNormals", "geometryVolume"},
         &ThesisFigures::injection},
        {"propagation", {"lpvPropagation", "lpvBounces", "subsurface"}, &ThesisFigures::propagation},
        {"final shading",
         {"depthPrepass", "lpvLookup", "lpvLookupResolve", "shading", "glossyReflections", "sunRays", "exposure",
          "tonemap"},
         &ThesisFigures::finalShading},
    };
    return kSpecs;
}

// A finite, non-negative number of milliseconds and nothing else.
std::optional<double> parseMs(std::string_view text) {
    double value = 0.0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc{} || end != text.data() + text.size() || !std::isfinite(value) || value < 0.0)
        return std::nullopt;
    return value;
}

} // namespace

ThesisFigures issue25ThesisFigures() {
    // Rebuilt and run beside `lpv bench render` on issue #25's day (4 rounds):
    // Sibenik from sibenik.4ds at 1024x600, the start camera, the settings above.
    return {.shadowMaps = 132.0,
            .rsm = 75.0,
            .injection = 15.0,
            .propagation = 235.0,
            .finalShading = 349.0,
            .wholeFrame = 839.0,
            .lpvOff = 649.0,
            .source = "issue #25's day, another day's machine (--thesis-run FILE takes tools/thesis-app/run.sh's "
                      "output of this session instead)"};
}

scene::Expected<ThesisFigures> parseThesisRun(std::string_view text, std::string source) {
    ThesisFigures figures;
    figures.source = std::move(source);
    std::optional<double> clear;
    int lineNumber = 0;
    while (!text.empty()) {
        const std::size_t eol = text.find('\n');
        std::string_view line = text.substr(0, eol);
        text = eol == std::string_view::npos ? std::string_view{} : text.substr(eol + 1);
        ++lineNumber;
        if (!line.starts_with("phase "))
            continue;
        line.remove_prefix(6);
        const std::size_t space = line.find(' ');
        const std::string_view name = line.substr(0, space);
        const auto ms = space == std::string_view::npos ? std::nullopt : parseMs(line.substr(space + 1));
        if (!ms)
            return scene::makeError(scene::ErrorCode::InvalidValue, figures.source, "line " + std::to_string(lineNumber),
                                    "expected \"phase NAME MS\" with a finite, non-negative MS");
        if (name == "shadow_maps")
            figures.shadowMaps = ms;
        else if (name == "rsm")
            figures.rsm = ms;
        else if (name == "lpv_clear")
            clear = ms;
        else if (name == "injection")
            figures.injection = ms;
        else if (name == "propagation")
            figures.propagation = ms;
        else if (name == "final_shading")
            figures.finalShading = ms;
        else if (name == "whole_frame")
            figures.wholeFrame = ms;
        else if (name == "lpv_off_whole_frame")
            figures.lpvOff = ms;
    }
    if (!figures.wholeFrame)
        return scene::makeError(scene::ErrorCode::MissingField, figures.source, "",
                                "no \"phase whole_frame MS\" line: is this tools/thesis-app/run.sh's output?");
    // Its lpv_clear is part of our injection (our passes clear their own volumes).
    if (figures.injection && clear)
        *figures.injection += *clear;
    return figures;
}

std::vector<std::string> thesisSettingsSets() {
    return {"lpv.cascades=4",       "lpv.gridSize=32",     "rsm.tileSize=128",
            "shadow.cascades=6",    "shadow.mapSize=1024", "lpv.propagationSteps=8"};
}

scene::Camera thesisStartCamera() {
    scene::Camera c;
    c.name = "thesis start camera";
    c.position = {-2.2f, 5.7f, 4.3f};
    const float pitch = 5.0f * 3.14159265f / 180.0f;
    c.target = c.position + glm::vec3(std::cos(pitch), -std::sin(pitch), 0.0f);
    c.fovY = 60.0f * 3.14159265f / 180.0f;
    return c;
}

std::vector<ThesisPhase> thesisPhases(const std::vector<std::vector<renderer::PassTiming>>& rounds,
                                      std::optional<TimingStats> lpvOff, const ThesisFigures& figures) {
    // Our passes in the order they first ran, and which phase counts each.
    std::vector<std::string> ran;
    for (const auto& table : rounds)
        for (const renderer::PassTiming& t : table)
            if (t.samples > 0 && std::find(ran.begin(), ran.end(), t.pass) == ran.end())
                ran.push_back(t.pass);
    auto phaseOf = [&](const std::string& name, const std::string& passes, auto counts,
                       std::optional<double> thesisMs) {
        ThesisPhase phase{name, passes, {}, thesisMs};
        std::vector<double> sums;
        for (const auto& table : rounds) {
            double sum = 0.0;
            for (const renderer::PassTiming& t : table)
                if (t.samples > 0 && counts(t.pass))
                    sum += t.medianMs;
            sums.push_back(sum);
        }
        phase.ours = timingStatsOf(std::move(sums));
        return phase;
    };
    std::vector<ThesisPhase> out;
    std::set<std::string> counted;
    for (const PhaseSpec& spec : phaseSpecs()) {
        std::string ours;
        for (const std::string& pass : ran)
            if (spec.passes.contains(pass)) {
                ours += (ours.empty() ? "" : " + ") + pass;
                counted.insert(pass);
            }
        out.push_back(phaseOf(spec.name, ours, [&](const std::string& pass) { return spec.passes.contains(pass); },
                              figures.*spec.thesisMs));
    }
    // The whole frame is every pass that ran, grouped or not.
    std::string others;
    for (const std::string& pass : ran)
        if (!counted.contains(pass))
            others += (others.empty() ? "" : " + ") + pass;
    out.push_back(phaseOf("whole frame", others.empty() ? "every pass" : "every pass (also " + others + ")",
                          [](const std::string&) { return true; }, figures.wholeFrame));
    if (lpvOff)
        out.push_back({"LPV off (whole frame)", "every pass, gi.method=off", *lpvOff, figures.lpvOff});
    return out;
}

std::string formatThesisPhases(const std::vector<ThesisPhase>& phases, const std::string& thesisSource) {
    std::string out = "phase                   ours ms   ±IQR/2  thesis app ms  ours/thesis  our passes\n";
    int rounds = 0;
    for (const ThesisPhase& p : phases) {
        char line[256];
        rounds = std::max(rounds, p.ours.rounds);
        const double half = 0.5 * p.ours.spread();
        if (p.thesisMs)
            std::snprintf(line, sizeof line, "%-22s %8.1f %8.1f %14.0f %11.2fx  ", p.name.c_str(), p.ours.median,
                          half, *p.thesisMs, p.ours.median / *p.thesisMs);
        else
            std::snprintf(line, sizeof line, "%-22s %8.1f %8.1f %14s %12s  ", p.name.c_str(), p.ours.median, half,
                          "-", "-");
        out += line + p.ourPasses + "\n";
    }
    out += "thesis app: its own phase timer (glFinish and a wall clock), raster gather; its figures: " + thesisSource +
           "; ours: GPU timer queries, per round the medians of a phase's passes summed, then the median "
           "over " +
           std::to_string(rounds) + " round" + (rounds == 1 ? "" : "s") + " and half its interquartile range\n";
    return out;
}

} // namespace lpv::bench
