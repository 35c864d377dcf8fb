#include "lpv/bench/ReportShards.h"

#include <string>

namespace lpv::bench::report {

namespace fs = std::filesystem;

fs::path referenceShardFile(const PlannedReference& ref, const reference::ShardSpec& shard) {
    fs::path out = ref.file;
    out.replace_filename(ref.file.stem().string() + ".shard-" + std::to_string(shard.index) + "-of-" +
                         std::to_string(shard.count) + ".exr");
    return out;
}

fs::path sweepShardDir(const PlannedSweep& sweep, const reference::ShardSpec& shard) {
    return sweep.dir / "shards" / (std::to_string(shard.index) + "-of-" + std::to_string(shard.count));
}

bool referenceShardDone(const fs::path& file, const reference::ShardSpec& shard, const PlannedReference& ref,
                        const ScenePlan& plan, const ReportOptions& o) {
    if (!fs::exists(file))
        return false;
    const auto loaded = readReferenceExr(file); // read once: the size, bounces and spp, then the shard
    if (!loaded || !referenceMatches(*loaded, o.width, o.height, ref.bounces, plan.spp))
        return false;
    auto it = loaded->attributes.find("lpv:shard");
    return it != loaded->attributes.end() && it->second == reference::formatShard(shard);
}

bool anyReferenceMissing(const std::vector<ScenePlan>& plans, const ReportOptions& o) {
    for (const ScenePlan& plan : plans)
        for (const PlannedReference& ref : plan.references)
            if (!referenceMatches(ref.file, o.width, o.height, ref.bounces, plan.spp))
                return true;
    return false;
}

} // namespace lpv::bench::report
