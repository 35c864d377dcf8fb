#pragma once
// A sharded sweep (issue #28, docs/cluster.md): `lpv bench PROJECT --sweep ...
// --reference REF.exr --shard I/N --out DIR` renders the combinations whose
// index is I modulo N and writes DIR/shard.json (each run's timings and
// errors, numbers kept exactly) and DIR/run-K.exr (run K's indirect light
// and final frame, for the crops and frames sheets); `lpv bench merge OUT SHARD_DIR...` checks the shards
// belong together and writes the files one unsharded sweep would.
#include "BenchReport.h"
#include "Cli.h"

#include "lpv/reference/Shards.h"

#include <filesystem>
#include <string>
#include <vector>

namespace lpv::cli {

struct SweepShard {
    reference::ShardSpec shard;
    int combinations = 0;         // in the whole sweep
    std::string command;          // the sweep's command without --shard and --out: the same in every shard
    std::string machine;          // describeMachine(): CPU, GL renderer, driver
    int width = 0, height = 0;
    std::string referenceFile;    // as given to --reference
    std::string referenceAbsolute;
    std::string referenceHash;    // bench::fileContentHash (ReferenceFile.h) of it
    std::vector<int> indices;     // each run's combination index, in run order
    std::vector<SweepRun> runs;
    // The project's output.* overrides: the pictures' exposure and tonemapper, as one process shows them.
    std::vector<Setting> display;
    bench::SweepTimingInfo timing; // how the shard's times were taken
};

// The combinations shard `shard` renders: those whose index is I modulo N.
bool shardRunsCombination(const reference::ShardSpec& shard, int combinationIndex);

// Removes a previous shard.json first, writes each run's EXR, then shard.json
// through a temporary file: a shard killed part way leaves no shard.json,
// and merge accepts only folders that have one.
bool writeSweepShard(const std::filesystem::path& dir, const SweepShard& shard);

int benchMerge(Args args); // `lpv bench merge OUT_DIR SHARD_DIR...`
void printBenchMergeHelp();

} // namespace lpv::cli
