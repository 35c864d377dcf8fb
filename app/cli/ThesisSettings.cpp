#include "ThesisSettings.h"

#include <cmath>
#include <cstdio>
#include <set>

namespace lpv::cli {

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

std::vector<ThesisPhase> thesisPhases(const std::vector<renderer::PassTiming>& table,
                                      std::optional<double> lpvOffTotalMs) {
    std::vector<ThesisPhase> out;
    double whole = 0.0;
    std::set<std::string> counted;
    for (const PhaseSpec& spec : phaseSpecs()) {
        ThesisPhase phase{spec.name, "", 0.0, spec.thesisMs};
        for (const renderer::PassTiming& t : table)
            if (spec.passes.contains(t.pass) && t.samples > 0) {
                phase.oursMs += t.medianMs;
                phase.ourPasses += (phase.ourPasses.empty() ? "" : " + ") + t.pass;
                counted.insert(t.pass);
            }
        out.push_back(phase);
    }
    // The whole frame is every pass that ran, grouped or not.
    std::string others;
    for (const renderer::PassTiming& t : table)
        if (t.samples > 0) {
            whole += t.medianMs;
            if (!counted.contains(t.pass))
                others += (others.empty() ? "" : " + ") + t.pass;
        }
    out.push_back({"whole frame", others.empty() ? "every pass" : "every pass (also " + others + ")", whole,
                   kThesisWholeFrameMs});
    if (lpvOffTotalMs)
        out.push_back({"LPV off (whole frame)", "every pass, gi.method=off", *lpvOffTotalMs, kThesisLpvOffMs});
    return out;
}

std::string formatThesisPhases(const std::vector<ThesisPhase>& phases) {
    std::string out = "phase                   ours ms  thesis app ms  ours/thesis  our passes\n";
    for (const ThesisPhase& p : phases) {
        char line[256];
        if (p.thesisMs)
            std::snprintf(line, sizeof line, "%-22s %8.1f %14.0f %11.2fx  ", p.name.c_str(), p.oursMs, *p.thesisMs,
                          p.oursMs / *p.thesisMs);
        else
            std::snprintf(line, sizeof line, "%-22s %8.1f %14s %12s  ", p.name.c_str(), p.oursMs, "-", "-");
        out += line + p.ourPasses + "\n";
    }
    out += "thesis app: its own phase timer (glFinish and a wall clock), raster gather, on a 2-core llvmpipe machine "
           "(issue #25); ours: GPU timer queries, medians per pass summed\n";
    return out;
}

} // namespace lpv::cli
