// `lpv bench report --shard I/N` and `--merge-shards N`: the report run in
// pieces on a cluster (issue #28, docs/cluster.md). The shards share the
// output folder (a cluster's shared file system) and run the same options;
// each run of a shard does its part of whatever comes next, and the
// coordinator (--merge-shards) joins what the shards made:
//   coordinator  makes the projects (imports once, so shards never race on
//                them), then times every scene's settings (timing.json)
//   N shards     trace their tiles of every reference (lpv reference --shard)
//   coordinator  merges the references (lpv merge)
//   N shards     run their combinations of every sweep (lpv bench --sweep --shard)
//   coordinator  merges the sweeps (lpv bench merge), measures radiosity and
//                writes report.md and report.json as one process would
#include "BenchReport.h"
#include "BenchReportPlan.h"
#include "lpv/bench/ReportShards.h"
#include "lpv/bench/SweepShard.h"
#include "lpv/bench/ContentHash.h"
#include "lpv/bench/ReferenceFile.h"

#include "lpv/scene/Project.h"

#include <cstdio>
#include <iostream>

namespace lpv::cli::report {

namespace fs = std::filesystem;

namespace {

std::optional<std::vector<ScenePlan>> planAll(const ReportOptions& o, int shardCount) {
    std::vector<ScenePlan> plans;
    for (const SceneSpec& spec : kScenes) {
        if (!o.wantsScene(spec.name))
            continue;
        if (!fs::exists(projectFileOf(spec, o))) {
            std::cerr << "lpv: " << projectFileOf(spec, o).string()
                      << ": no project yet; the coordinator makes the projects before the shards run:\n  "
                      << reportCommand(o) << " --merge-shards " << shardCount << "\n";
            return std::nullopt;
        }
        auto plan = planSceneOrSay(spec, o);
        if (!plan)
            return std::nullopt;
        plans.push_back(std::move(*plan));
    }
    return plans;
}

void printNext(const ReportOptions& o, int shardCount, const std::string& what) {
    std::printf("\nnext: %s, then the coordinator again:\n  %s --merge-shards %d\n", what.c_str(),
                reportCommand(o).c_str(), shardCount);
}

} // namespace

int runReportShard(const ReportOptions& o, const reference::ShardSpec& shard) {
    const auto plans = planAll(o, shard.count);
    if (!plans)
        return kFailure;
    if (anyReferenceMissing(*plans, o)) {
        for (const ScenePlan& plan : *plans)
            for (const PlannedReference& ref : plan.references) {
                if (referenceMatches(ref.file, o.width, o.height, ref.bounces, plan.spp))
                    continue;
                const fs::path out = referenceShardFile(ref, shard);
                if (referenceShardDone(out, shard, ref, plan, o)) {
                    std::printf("reusing %s (this shard traced it already)\n", out.string().c_str());
                    continue;
                }
                ReferenceCommand command = referenceCommandOf(plan, ref, out, o);
                command.shard = shard;
                if (runEchoed(command) != kOk)
                    return kFailure;
            }
        printNext(o, shard.count, "every shard traces its tiles of the references");
        return kOk;
    }
    int ran = 0;
    for (const ScenePlan& plan : *plans)
        for (const PlannedSweep& sweep : plan.sweeps) {
            if (sweepDoneAlready(sweep.dir / "sweep.json", plan, sweep, o))
                continue; // merged already
            ++ran;
            SweepCommand command = sweepCommandOf(plan, sweep, o);
            command.outDir = sweepShardDir(sweep, shard);
            command.shard = shard;
            if (runEchoed(command) != kOk)
                return kFailure;
        }
    if (ran == 0) {
        std::printf(
            "\nnothing left for the shards: every sweep is merged; the coordinator writes the report:\n"
            "  %s --merge-shards %d\n",
            reportCommand(o).c_str(), shard.count);
        return kOk;
    }
    printNext(o, shard.count, "every shard runs its part of the sweeps");
    return kOk;
}

int runReportCoordinator(const ReportOptions& o, int shardCount) {
    // 1. The projects, made once here so that no two shards import into one folder.
    bool made = false;
    for (const SceneSpec& spec : kScenes) {
        const fs::path project = projectFileOf(spec, o);
        if (!o.wantsScene(spec.name) || fs::exists(project))
            continue;
        std::error_code ec;
        fs::create_directories(project.parent_path(), ec);
        if (ec || !makeProject(spec, o.scenesDir, project)) {
            std::cerr << "lpv: making " << project.string() << " failed\n";
            return kFailure;
        }
        made = true;
    }
    if (made) {
        std::printf("\nprojects made.");
        printNext(o, shardCount,
                  "the " + std::to_string(shardCount) + " shards (" + reportCommand(o) + " --shard I/" +
                      std::to_string(shardCount) + ")");
        return kOk;
    }
    const auto plans = planAll(o, shardCount);
    if (!plans)
        return kFailure;

    // 1b. The settings' times, here on the coordinator's machine, all of a
    // scene's in one process (interleaved rounds; timing.json): the shards'
    // sweeps take their times from them. Kept once made: a sweep merged
    // from the shards is older than a timing made after it.
    ReportOptions keepTiming = o;
    keepTiming.resume = true;
    for (const ScenePlan& plan : *plans)
        if (!timeScene(plan, keepTiming))
            return kFailure;

    // 2. The references, from their shards.
    std::vector<std::string> missing;
    bool merged = false;
    for (const ScenePlan& plan : *plans)
        for (const PlannedReference& ref : plan.references) {
            if (referenceMatches(ref.file, o.width, o.height, ref.bounces, plan.spp))
                continue;
            std::vector<std::string> args{ref.file.string()};
            bool complete = true;
            for (int i = 0; i < shardCount; ++i) {
                const fs::path piece = referenceShardFile(ref, {i, shardCount});
                if (!referenceShardDone(piece, {i, shardCount}, ref, plan, o)) {
                    missing.push_back(piece.string());
                    complete = false;
                }
                args.push_back(piece.string());
            }
            if (complete) {
                if (call("merge", runMerge, args) != kOk)
                    return kFailure;
                merged = true;
            }
        }
    auto refuseIncomplete = [&](const std::string& what) {
        std::cerr << "lpv: " << what << " are incomplete: " << missing.size() << " shard"
                  << (missing.size() == 1 ? "" : "s") << " missing:\n";
        for (const std::string& m : missing)
            std::cerr << "  " << m << "\n";
        std::cerr << "run the shards that made no file (" << reportCommand(o) << " --shard I/" << shardCount
                  << ") and this command again\n";
        return kFailure;
    };
    if (!missing.empty())
        return refuseIncomplete("the references");
    if (merged) {
        std::printf("\nreferences merged.");
        printNext(o, shardCount, "the " + std::to_string(shardCount) + " shards again, for the sweeps");
        return kOk;
    }

    // 3. The sweeps, from their shards.
    for (const ScenePlan& plan : *plans)
        for (const PlannedSweep& sweep : plan.sweeps) {
            if (sweepDoneAlready(sweep.dir / "sweep.json", plan, sweep, o))
                continue;
            std::vector<std::string> args{"merge", sweep.dir.string()};
            bool complete = true;
            for (int i = 0; i < shardCount; ++i) {
                const fs::path dir = sweepShardDir(sweep, {i, shardCount});
                if (!fs::exists(dir / "shard.json")) {
                    missing.push_back(dir.string());
                    complete = false;
                }
                args.push_back(dir.string());
            }
            if (complete && call("bench", benchMerge, args) != kOk)
                return kFailure;
        }
    if (!missing.empty())
        return refuseIncomplete("the sweeps");

    // 4. The report, from the merged references and sweeps, as one process writes it.
    ReportOptions whole = o;
    whole.resume = true;
    return runWholeReport(whole);
}

} // namespace lpv::cli::report
