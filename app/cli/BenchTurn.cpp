#include "BenchTurn.h"
#include "BenchReport.h"

#include "lpv/renderer/FrameGraphReport.h"

#include "lpv/scene/CameraTurn.h"

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <sstream>

namespace lpv::cli {

bool renderTurnFrames(RenderSetup& setup, int width, int height, int warmup, int frames, float degrees,
                      TurnFrames& out) {
    const scene::Camera start = setup.camera;
    renderer::GpuTimer& timer = setup.renderer->timer();
    // The first frame draws everything; each later one turns away from the
    // last and back, so the view stays near the start.
    for (int f = 0; f < warmup + frames; ++f) {
        setup.camera = f % 2 ? scene::yawedAboutUp(start, degrees) : start;
        timer.clearHistory();
        if (auto ok = setup.renderer->render(setup.project.scene, setup.project.parameters, setup.camera, width,
                                             height);
            !ok) {
            std::cerr << "lpv: " << ok.error().describe() << "\n";
            setup.camera = start;
            return false;
        }
        timer.resolveAll();
        if (f < warmup)
            continue;
        double total = 0.0;
        for (const renderer::PassTiming& row : timer.table()) {
            if (row.samples == 0)
                continue; // reused or not run this frame
            total += row.lastMs;
            auto it = std::find_if(out.passMs.begin(), out.passMs.end(),
                                   [&](const auto& p) { return p.first == row.pass; });
            if (it == out.passMs.end())
                it = out.passMs.insert(out.passMs.end(), {row.pass, {}});
            it->second.push_back(row.lastMs);
        }
        out.frameTotalsMs.push_back(total);
        for (const renderer::GraphPassReport& pass : setup.renderer->graphReport().passes) {
            if (pass.status != renderer::PassStatus::Reused)
                continue;
            auto it = std::find_if(out.reused.begin(), out.reused.end(),
                                   [&](const TurnFrames::Reused& r) { return r.pass == pass.name; });
            if (it == out.reused.end())
                it = out.reused.insert(out.reused.end(), {pass.name, 0, {}});
            ++it->frames;
            it->reason = pass.reason;
        }
    }
    setup.camera = start;
    return true;
}

std::string formatTurnFrames(const TurnFrames& turn, float degrees) {
    std::ostringstream text;
    char line[256];
    std::snprintf(line, sizeof line, "\nframes where only the camera turned (+-%g degrees about the up axis, reuse on):\n",
                  double(degrees));
    text << line;
    std::snprintf(line, sizeof line, "%-24s %10s %10s %10s\n", "pass", "median", "max", "ran in");
    text << line;
    for (const auto& [pass, ms] : turn.passMs) {
        std::snprintf(line, sizeof line, "%-24s %10.3f %10.3f %4zu of %zu\n", pass.c_str(), median(ms),
                      *std::max_element(ms.begin(), ms.end()), ms.size(), turn.frameTotalsMs.size());
        text << line;
    }
    // What the frame graph kept: a pass listed here did not run in those frames.
    std::snprintf(line, sizeof line, "reused by the frame graph (its output kept):%s\n",
                  turn.reused.empty() ? " none" : "");
    text << line;
    for (const TurnFrames::Reused& r : turn.reused) {
        std::snprintf(line, sizeof line, "  %-22s %4d of %zu  ", r.pass.c_str(), r.frames, turn.frameTotalsMs.size());
        text << line << r.reason << "\n";
    }
    const auto [lo, hi] = std::minmax_element(turn.frameTotalsMs.begin(), turn.frameTotalsMs.end());
    std::snprintf(line, sizeof line, "whole frame (per frame, every pass that ran): median %.3f ms, min %.3f, max %.3f\n",
                  median(turn.frameTotalsMs), turn.frameTotalsMs.empty() ? 0.0 : *lo,
                  turn.frameTotalsMs.empty() ? 0.0 : *hi);
    text << line;
    return text.str();
}

} // namespace lpv::cli
