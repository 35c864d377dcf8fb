#pragma once
// A sharded sweep (issue #28, docs/cluster.md): `lpv bench PROJECT --sweep ...
// --reference REF.exr --shard I/N --out DIR` renders the combinations whose
// index is I modulo N and writes DIR/shard.json (each run's timings and
// errors, numbers kept exactly) and DIR/run-K.exr (run K's indirect light
// and final frame, for the crops and frames sheets); `lpv bench merge OUT
// SHARD_DIR...` checks the shards belong together (mergeSweepShards) and
// writes the files one unsharded sweep would.
#include "lpv/bench/Settings.h"
#include "lpv/bench/SweepOutput.h"
#include "lpv/reference/ReferenceImage.h"
#include "lpv/reference/Shards.h"
#include "lpv/scene/Error.h"
#include "lpv/scene/ParameterRegistry.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace lpv::bench {

struct SweepShard {
    reference::ShardSpec shard;
    int combinations = 0;         // in the whole sweep
    std::string command;          // the sweep's command without --shard and --out: the same in every shard
    std::string machine;          // describeMachine(): CPU, GL renderer, driver
    int width = 0, height = 0;
    std::string referenceFile;    // as given to --reference
    std::string referenceAbsolute;
    std::string referenceHash;    // fileContentHash (ContentHash.h) of it
    std::vector<int> indices;     // each run's combination index, in run order
    std::vector<SweepRun> runs;
    // The project's output.* overrides: the pictures' exposure and tonemapper, as one process shows them.
    std::vector<Setting> display;
    SweepTimingInfo timing; // how the shard's times were taken
};

// The combinations shard `shard` renders: those whose index is I modulo N.
bool shardRunsCombination(const reference::ShardSpec& shard, int combinationIndex);

// Writes each run's EXR, then shard.json through a temporary file: a shard
// killed part way leaves no shard.json (the caller removes an old one before
// it starts), and merge accepts only folders that have one. Returns the
// shard.json written.
scene::Expected<std::filesystem::path> writeSweepShard(const std::filesystem::path& dir, const SweepShard& shard);

// Reads DIR/shard.json and its run images; the error names the file.
scene::Expected<SweepShard> readSweepShard(const std::filesystem::path& dir);

// The shards of one sweep joined as one process would have run it.
struct MergedSweep {
    std::vector<SweepRun> runs;    // in combination order
    std::size_t machineCount = 0;  // distinct machines the shards ran on
    std::string note;              // for sweep.md: "" unless the shards ran on several machines
    scene::ParameterSet display;   // the first shard's output.* overrides
};

// Checks `shards` (read from `folders`, in the same order) belong together:
// one shard count, one command, size and reference hash, no shard twice and
// none missing, each with exactly its combinations. The error's file is the
// folder at fault; it is empty when the set as a whole is incomplete.
scene::Expected<MergedSweep> mergeSweepShards(const std::vector<SweepShard>& shards,
                                              const std::vector<std::string>& folders);

// The reference the shards were measured against, for the crops and the
// header: `override` (--reference) or the path the first shard recorded
// (absolute, then as given); refused unless its content hash is the recorded one.
scene::Expected<reference::ReferenceImage> loadShardsReference(const SweepShard& first,
                                                              const std::optional<std::filesystem::path>& override);

} // namespace lpv::bench
