#include "lpv/bench/ThesisSettings.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

namespace lpv::bench {

namespace {

// The thesis application's medians (ms) from issue #25: rebuilt and run beside
// `lpv bench render` on the same kind of 2-core llvmpipe machine, Sibenik from
// sibenik.4ds at 1024x600, the start camera, the settings above, 4 rounds.
struct PhaseSpec {
    const char* name;
    std::set<std::string> passes;
    std::optional<double> thesisMs;
};

const std::vector<PhaseSpec>& phaseSpecs() {
    static const std::vector<PhaseSpec> kSpecs = {
        {"shadow maps", {"shadowMaps"}, 132.0},
        {"RSM", {"rsm", "localRsm", "emissiveVpls"}, 75.0},
        {"injection", {"lpvInjection", "skyInjection", "skyHeight", "lpvNormals", "geometryVolume"}, 15.0},
        {"propagation", {"lpvPropagation", "lpvBounces", "subsurface"}, 235.0},
        {"final shading", {"depthPrepass", "shading", "glossyReflections", "sunRays", "exposure", "tonemap"}, 349.0},
    };
    return kSpecs;
}

constexpr double kThesisWholeFrameMs = 839.0;
constexpr double kThesisLpvOffMs = 649.0;

} // namespace

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
                                      std::optional<TimingStats> lpvOff) {
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
                              spec.thesisMs));
    }
    // The whole frame is every pass that ran, grouped or not.
    std::string others;
    for (const std::string& pass : ran)
        if (!counted.contains(pass))
            others += (others.empty() ? "" : " + ") + pass;
    out.push_back(phaseOf("whole frame", others.empty() ? "every pass" : "every pass (also " + others + ")",
                          [](const std::string&) { return true; }, kThesisWholeFrameMs));
    if (lpvOff)
        out.push_back({"LPV off (whole frame)", "every pass, gi.method=off", *lpvOff, kThesisLpvOffMs});
    return out;
}

std::string formatThesisPhases(const std::vector<ThesisPhase>& phases) {
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
    out += "thesis app: its own phase timer (glFinish and a wall clock), raster gather, on a 2-core llvmpipe machine "
           "(issue #25); ours: GPU timer queries, per round the medians of a phase's passes summed, then the median "
           "over " +
           std::to_string(rounds) + " round" + (rounds == 1 ? "" : "s") + " and half its interquartile range\n";
    return out;
}

} // namespace lpv::bench
