// `lpv bench merge OUT_DIR SHARD_DIR...`: reads the shards, lets lpv_bench
// check they belong together (bench/SweepShard.h) and writes the sweep's files.
#include "BenchReport.h"
#include "Cli.h"

#include "lpv/bench/SweepShard.h"

#include <cstdio>
#include <iostream>

namespace lpv::cli {

namespace fs = std::filesystem;

void printBenchMergeHelp() {
    std::cout << R"(
bench merge OUT_DIR SHARD_DIR... [--reference REF.exr]:
joins the shards of one sweep (`lpv bench PROJECT --sweep ... --reference
REF.exr --shard I/N --out SHARD_DIR`, one per process or cluster task, see
docs/cluster.md) and writes into OUT_DIR the files the sweep writes unsharded
(sweep.csv, sweep.json, sweep.md, the plots and crops), its error columns
exactly as one process would have measured them. Refuses shards of different
sweeps (command, size, reference file content, shard count), a shard given
twice, a shard folder without its shard.json (killed before it finished) and
an incomplete set, naming the missing shards. Warns, and says so in sweep.md,
when the shards ran on different machines (their timings do not compare).
  --reference REF.exr   The reference, where it is no longer at the path the
                        shards recorded (its content must be the same)
)";
}

int benchMerge(Args args) {
    const auto referenceOverride = args.option("--reference");
    if (auto e = args.error())
        return usageError(*e, "bench");
    auto pos = args.positionals();
    pos.erase(pos.begin()); // "merge"
    if (pos.size() < 2)
        return usageError("bench merge expects OUT_DIR and at least one shard folder", "bench");
    const fs::path outDir = pos.front();
    const std::vector<std::string> folders(pos.begin() + 1, pos.end());
    auto fail = [](const scene::Error& e) {
        // A set that is incomplete as a whole has no folder to blame.
        std::cerr << "lpv: " << (e.file.empty() ? "lpv bench merge: " + e.message : e.describe()) << "\n";
        return kFailure;
    };
    std::vector<bench::SweepShard> shards;
    for (const std::string& folder : folders) {
        auto s = bench::readSweepShard(folder);
        if (!s)
            return fail(s.error());
        shards.push_back(std::move(*s));
    }
    const auto merged = bench::mergeSweepShards(shards, folders);
    if (!merged)
        return fail(merged.error());
    const bench::SweepShard& first = shards.front();
    const auto ref = bench::loadShardsReference(
        first, referenceOverride ? std::optional<fs::path>(*referenceOverride) : std::nullopt);
    if (!ref)
        return fail(ref.error());
    if (merged->machineCount > 1)
        std::cerr << "lpv: warning: the shards ran on " << merged->machineCount
                  << " different machines; their timings do not compare (listed in sweep.md)\n";
    std::error_code ec;
    fs::create_directories(outDir, ec);
    if (ec) {
        std::cerr << "lpv: " << outDir.string() << ": cannot create the folder: " << ec.message() << "\n";
        return kFailure;
    }
    if (!writeSweepFiles(outDir, merged->runs, first.width, first.height, first.command, first.machine, *ref,
                         merged->note, first.timing, merged->display))
        return kFailure;
    std::printf("merged %d shards: %d runs\n", first.shard.count, first.combinations);
    return kOk;
}

} // namespace lpv::cli
