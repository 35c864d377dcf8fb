// `lpv bench report`'s timing step (issue #43): every distinct setting of a
// scene's questions is timed together, in interleaved rounds, before any
// sweep runs, into OUT/NAME/timing.json. The sweeps then take their times
// from it (--times-from), so the project setting that every question
// contains has one time in the whole report instead of one per question,
// and the times of one question were taken side by side with all others.
#include "BenchReportPlan.h"
#include "RenderSetup.h"

#include "lpv/bench/SavedSweep.h"
#include "lpv/bench/SharedTiming.h"
#include "lpv/renderer/GpuMemory.h"

#include <algorithm>
#include <cstdio>
#include <iostream>

namespace lpv::cli::report {

namespace fs = std::filesystem;

namespace {

std::string timingCommand(const ScenePlan& plan, const ReportOptions& o) {
    return "lpv bench report (timing " + plan.project.string() + " --width " + std::to_string(o.width) +
           " --height " + std::to_string(o.height) + " --frames " + std::to_string(o.frames) + " --warmup " +
           std::to_string(o.warmup) + roundOptionsText(o.rounds) + ")";
}

} // namespace

bool timeScene(const ScenePlan& plan, const ReportOptions& o) {
    int exitCode = kOk;
    auto project = loadProjectWithSets(plan.project.string(), {kSweepBaseSet}, "bench", exitCode);
    if (!project)
        return false;
    const auto settings = distinctSettings(plan, project->parameters);
    const fs::path file = timingFileOf(plan);
    const std::string command = timingCommand(plan, o);
    // --resume keeps a timing of the same command that covers every setting.
    if (o.resume && fs::exists(file)) {
        const auto kept = bench::loadSharedTiming(file);
        if (kept && kept->command == command &&
            std::ranges::all_of(settings, [&](const auto& s) { return bench::findTiming(*kept, s.second); })) {
            std::printf("reusing %s (--resume: the same %zu settings timed by the same command)\n",
                        file.string().c_str(), settings.size());
            return true;
        }
    }
    const auto camera = pickCamera(project->scene, std::nullopt, plan.project.string());
    if (!camera)
        return false;
    bench::SweepSpec spec;
    spec.project = *project;
    spec.projectDir = fs::absolute(plan.project).parent_path();
    spec.projectFile = plan.project;
    spec.camera = *camera;
    spec.width = o.width;
    spec.height = o.height;
    spec.frames = o.frames;
    spec.warmup = o.warmup;
    spec.rounds = o.rounds;
    for (const auto& [combination, parameters] : settings)
        spec.combinations.push_back(combination);
    std::printf("\n$ %s\ntiming %zu distinct settings of %zu sweeps in interleaved rounds\n", command.c_str(),
                settings.size(), plan.sweeps.size());
    std::fflush(stdout);
    bench::SweepCallbacks callbacks;
    int lastRound = -1;
    callbacks.progress = [&lastRound](const bench::SweepProgress& p) {
        if (p.round >= 0 && p.round != lastRound) {
            lastRound = p.round;
            std::printf("timing round %d ...\n", p.round + 1);
            std::fflush(stdout);
        }
        return true;
    };
    callbacks.warning = [](const std::string& w) { std::cerr << "lpv: warning: " << w << "\n"; };
    auto timed = bench::timeSettings(spec, callbacks);
    if (!timed) {
        std::cerr << "lpv: " << timed.error().describe() << "\n";
        return false;
    }
    bench::SharedTiming out;
    out.command = command;
    out.machine = describeMachine(timed->gl.renderer, timed->gl.version);
    out.load = timed->load;
    out.rounds = timed->rounds;
    out.stopReason = timed->stopReason;
    for (std::size_t i = 0; i < settings.size(); ++i) {
        out.entries.push_back({bench::settingsOf(settings[i].second), timed->runs[i]});
        const SweepRun& r = timed->runs[i];
        std::printf("  %-40s %s (quartiles %.1f-%.1f), %s\n", sweepLabel(r.settings).c_str(),
                    bench::formatTiming(r.total).c_str(), r.total.q1, r.total.q3,
                    renderer::formatBytes(r.gpuBytes).c_str());
    }
    std::printf("timed in %d rounds (%s); %s\n", timed->rounds, timed->stopReason.c_str(), timed->load.c_str());
    if (auto ok = bench::saveSharedTiming(out, file); !ok) {
        std::cerr << "lpv: " << ok.error().describe() << "\n";
        return false;
    }
    std::printf("wrote %s\n", file.string().c_str());
    return true;
}

} // namespace lpv::cli::report
