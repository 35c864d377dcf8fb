#pragma once
// Splitting a reference into shards that separate processes (or cluster
// nodes) trace, and joining them back exactly (issue #28, docs/cluster.md).
//
// The image is cut into the path tracer's 16x16 tiles, dealt to the shards
// along diagonals (tile (tx, ty) belongs to shard (tx + ty) mod N), so every
// shard gets tiles from every part of the view and the shards take about the
// same time. A pixel's samples depend only on the pixel and the sample index
// (PathTracer::samplePixel), and each pixel accumulates its own samples in
// order, so the merged image is bit-identical to one traced in one process.
#include "lpv/reference/ReferenceImage.h"
#include "lpv/scene/Error.h"

#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace lpv::reference {

inline constexpr int kShardTileSize = 16;

struct ShardSpec {
    int index = 0; // 0-based
    int count = 1;

    bool whole() const { return count == 1; }
    bool operator==(const ShardSpec&) const = default;
};

// "I/N" with 0 <= I < N; the error says what is wrong with the text.
scene::Expected<ShardSpec> parseShard(std::string_view text);
std::string formatShard(const ShardSpec& shard); // "I/N"

// The shard (0..count-1) that traces tile (tileX, tileY): (tileX + tileY) mod count.
int shardOfTile(int tileX, int tileY, int shardCount);
// The shard that traces the tile holding pixel (x, y).
int shardOfPixel(int x, int y, int shardCount);
// Whether `shard` traces tile (tileX, tileY).
bool shardOwnsTile(const ShardSpec& shard, int tileX, int tileY);

// One traced shard as read from its file: the image (pixels of other shards
// are zero) and the header's settings ("lpv:shard", "lpv:projectHash", ...).
struct ShardPiece {
    std::string source; // the file, for messages
    ReferenceImage image;
    std::map<std::string, std::string> attributes;
};

// "missing shard 1/4" or "missing shards 1/5, 3/5": the indices whose
// `present` is false, out of present.size(); "" when none is missing.
std::string describeMissingShards(const std::vector<bool>& present);

// Header keys every shard of one set must agree on: what was traced, how,
// and with which cutting.
const std::vector<std::string>& shardMatchKeys();

struct MergedShards {
    ReferenceImage image;
    std::map<std::string, std::string> attributes; // the shards' shared ones, lpv:seconds summed
};

// Checks that the pieces form one complete set (same size, shard count,
// project, settings; each index once) and copies each shard's pixels into
// one image. The errors name the offending files and the missing shards.
scene::Expected<MergedShards> mergeShards(const std::vector<ShardPiece>& pieces);

} // namespace lpv::reference
