#include "BenchReportPlan.h"

#include <cstdio>
#include <iostream>

namespace lpv::cli::report {

namespace fs = std::filesystem;

const std::vector<Question>& kQuestions = bench::reportQuestions();

std::optional<ScenePlan> planSceneOrSay(const SceneSpec& spec, const ReportOptions& options) {
    auto plan = bench::report::planScene(spec, options);
    if (!plan) {
        std::cerr << "lpv: " << plan.error().describe() << "\n";
        return std::nullopt;
    }
    return std::move(*plan);
}

ReferenceCommand referenceCommandOf(const ScenePlan& plan, const PlannedReference& ref, const fs::path& out,
                                    const ReportOptions& options) {
    ReferenceCommand c;
    c.projectFile = plan.project.string();
    c.output = out.string();
    c.width = options.width;
    c.height = options.height;
    c.spp = std::to_string(plan.spp);
    c.bounces = std::to_string(ref.bounces);
    if (!ref.sky.empty())
        c.sets.push_back("effects.skyInjection=" + ref.sky);
    return c;
}

SweepCommand sweepCommandOf(const ScenePlan& plan, const PlannedSweep& sweep, const ReportOptions& options) {
    SweepCommand c;
    c.projectFile = plan.project.string();
    c.sweeps = {sweep.sweep};
    c.referenceFile = plan.references[sweep.reference].file.string();
    c.outDir = sweep.dir;
    c.width = options.width;
    c.height = options.height;
    c.frames = options.frames;
    c.warmup = options.warmup;
    c.timesFrom = timingFileOf(plan);
    return c;
}

int runEchoed(const ReferenceCommand& c) {
    std::printf("\n$ lpv reference %s -o %s --width %d --height %d --spp %s --bounces %s", c.projectFile.c_str(),
                c.output.c_str(), c.width, c.height, c.spp.value_or("-").c_str(), c.bounces.value_or("-").c_str());
    for (const std::string& set : c.sets)
        std::printf(" --set %s", set.c_str());
    if (!c.shard.whole())
        std::printf(" --shard %s", reference::formatShard(c.shard).c_str());
    std::printf("\n");
    std::fflush(stdout);
    return runReferenceCommand(c);
}

int runEchoed(const SweepCommand& c, std::vector<SweepRun>* runs) {
    std::printf("\n$ lpv bench %s --sweep %s --reference %s --width %d --height %d --frames %d --warmup %d --out %s",
                c.projectFile.c_str(), c.sweeps.front().c_str(), c.referenceFile.value_or("-").c_str(), c.width,
                c.height, c.frames, c.warmup, c.outDir.string().c_str());
    if (c.timesFrom)
        std::printf(" --times-from %s", c.timesFrom->string().c_str());
    if (!c.shard.whole())
        std::printf(" --shard %s", reference::formatShard(c.shard).c_str());
    std::printf("\n");
    std::fflush(stdout);
    return runSweepCommand(c, runs);
}

int call(const char* name, int (*command)(Args), std::vector<std::string> args) {
    std::printf("\n$ lpv %s", name);
    for (const auto& a : args)
        std::printf(" %s", a.c_str());
    std::printf("\n");
    std::fflush(stdout);
    return command(Args(std::move(args)));
}

bool makeProject(const SceneSpec& spec, const fs::path& scenesDir, const fs::path& project) {
    std::error_code ec;
    fs::remove(project, ec);
    fs::remove_all(fs::path(project).replace_extension(".assets"), ec);
    if (spec.source.empty()) {
        if (call("new", runNew, {project.string(), "--template", "cornell-box"}) != kOk)
            return false;
        // The default project as a user first sees it: lit by its ceiling
        // lamp (an area light), which the LPV injects on auto.
        return true;
    }
    const fs::path source = scenesDir / spec.source;
    if (!fs::exists(source)) {
        std::cerr << "lpv: " << source.string() << ": no such scene file (give --scenes DIR)\n";
        return false;
    }
    return call("import", runImport, {source.string(), "-o", project.string()}) == kOk;
}

} // namespace lpv::cli::report
