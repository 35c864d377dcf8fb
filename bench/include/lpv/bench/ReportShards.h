#pragma once
// `lpv bench report` in pieces on a cluster (issue #28, docs/cluster.md):
// where each shard's part of a reference and of a sweep lies, and whether it
// is done. The shards share the output folder and run the same options, so
// these names are all that ties a shard's files to the coordinator's merge.
#include "lpv/bench/ReportPlan.h"
#include "lpv/reference/Shards.h"

#include <filesystem>
#include <vector>

namespace lpv::bench::report {

// NAME.shard-I-of-N.exr beside the reference.
std::filesystem::path referenceShardFile(const PlannedReference& ref, const reference::ShardSpec& shard);
// SWEEP_DIR/shards/I-of-N.
std::filesystem::path sweepShardDir(const PlannedSweep& sweep, const reference::ShardSpec& shard);

// Whether `file` is this shard of a reference of the plan's size, bounce count and sample count.
bool referenceShardDone(const std::filesystem::path& file, const reference::ShardSpec& shard,
                        const PlannedReference& ref, const ScenePlan& plan, const ReportOptions& options);
// Whether any reference of the plans is still to be traced (or merged).
bool anyReferenceMissing(const std::vector<ScenePlan>& plans, const ReportOptions& options);

} // namespace lpv::bench::report
