#include "lpv/reference/Shards.h"

#include <algorithm>
#include <charconv>
#include <cstdlib>

namespace lpv::reference {

namespace {

bool parseInt(std::string_view text, int& out) {
    auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
    return ec == std::errc() && ptr == text.data() + text.size();
}

std::string attribute(const ShardPiece& piece, const std::string& key) {
    auto it = piece.attributes.find(key);
    return it == piece.attributes.end() ? std::string("(none)") : it->second;
}

} // namespace

scene::Expected<ShardSpec> parseShard(std::string_view text) {
    const auto slash = text.find('/');
    ShardSpec s;
    if (slash == std::string_view::npos || !parseInt(text.substr(0, slash), s.index) ||
        !parseInt(text.substr(slash + 1), s.count))
        return scene::makeError(scene::ErrorCode::InvalidValue, "", "--shard",
                                "'" + std::string(text) +
                                    "' is not I/N (e.g. 0/4: the first of four shards)");
    if (s.count < 1 || s.index < 0 || s.index >= s.count)
        return scene::makeError(scene::ErrorCode::OutOfRange, "", "--shard",
                                "'" + std::string(text) +
                                    "': need N >= 1 and 0 <= I < N (shards count from 0)");
    return s;
}

std::string formatShard(const ShardSpec& shard) {
    return std::to_string(shard.index) + "/" + std::to_string(shard.count);
}

int shardOfTile(int tileX, int tileY, int shardCount) { return (tileX + tileY) % shardCount; }

int shardOfPixel(int x, int y, int shardCount) {
    return shardOfTile(x / kShardTileSize, y / kShardTileSize, shardCount);
}

bool shardOwnsTile(const ShardSpec& shard, int tileX, int tileY) {
    return shardOfTile(tileX, tileY, shard.count) == shard.index;
}

std::string describeMissingShards(const std::vector<bool>& present) {
    const int count = int(present.size());
    std::string list;
    int missing = 0;
    for (int i = 0; i < count; ++i)
        if (!present[std::size_t(i)]) {
            list += (list.empty() ? "" : ", ") + formatShard({i, count});
            ++missing;
        }
    return missing == 0 ? "" : (missing > 1 ? "missing shards " : "missing shard ") + list;
}

const std::vector<std::string>& shardMatchKeys() {
    static const std::vector<std::string> keys{"lpv:projectHash",   "lpv:parametersHash", "lpv:camera",
                                               "lpv:spp",           "lpv:bounces",        "lpv:skyLight",
                                               "lpv:emissiveLight", "lpv:shardTile"};
    return keys;
}

scene::Expected<MergedShards> mergeShards(const std::vector<ShardPiece>& pieces) {
    if (pieces.empty())
        return scene::makeError(scene::ErrorCode::InvalidValue, "lpv merge", "shards", "no shards to merge");
    const ShardPiece& first = pieces.front();
    std::vector<const ShardPiece*> byIndex;
    int count = 0;
    for (const ShardPiece& p : pieces) {
        auto it = p.attributes.find("lpv:shard");
        if (it == p.attributes.end())
            return scene::makeError(scene::ErrorCode::MissingField, p.source, "header lpv:shard",
                                    "not a shard (trace one with `lpv reference ... --shard I/N`)");
        auto spec = parseShard(it->second);
        if (!spec)
            return scene::makeError(scene::ErrorCode::InvalidValue, p.source, "header lpv:shard",
                                    spec.error().message);
        if (count == 0) {
            count = spec->count;
            byIndex.assign(std::size_t(count), nullptr);
        }
        if (spec->count != count)
            return scene::makeError(scene::ErrorCode::InvalidValue, p.source, "header lpv:shard",
                                    "shard " + it->second + " is one of " + std::to_string(spec->count) +
                                        ", but " + first.source + " is one of " + std::to_string(count));
        if (p.image.width != first.image.width || p.image.height != first.image.height)
            return scene::makeError(scene::ErrorCode::InvalidValue, p.source, "size",
                                    std::to_string(p.image.width) + "x" + std::to_string(p.image.height) +
                                        ", but " + first.source + " is " + std::to_string(first.image.width) +
                                        "x" + std::to_string(first.image.height));
        for (const std::string& key : shardMatchKeys())
            if (attribute(p, key) != attribute(first, key))
                return scene::makeError(scene::ErrorCode::InvalidValue, p.source, "header " + key,
                                        "'" + attribute(p, key) + "' but " + first.source + " has '" +
                                            attribute(first, key) +
                                            "': the shards are not of one reference (same project, "
                                            "camera, size and settings)");
        const ShardPiece*& slot = byIndex[std::size_t(spec->index)];
        if (slot)
            return scene::makeError(scene::ErrorCode::InvalidValue, p.source, "header lpv:shard",
                                    "shard " + it->second + " is given twice (also " + slot->source + ")");
        slot = &p;
    }
    std::vector<bool> present(static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i)
        present[std::size_t(i)] = byIndex[std::size_t(i)] != nullptr;
    if (const std::string missing = describeMissingShards(present); !missing.empty())
        return scene::makeError(scene::ErrorCode::MissingField, "lpv merge", "shards",
                                "incomplete set: " + missing + " (" +
                                    std::to_string(std::ranges::count(present, true)) + " of " +
                                    std::to_string(count) + " given)");

    MergedShards out;
    out.image.resize(first.image.width, first.image.height);
    out.image.samplesPerPixel = first.image.samplesPerPixel;
    double seconds = 0.0;
    for (const ShardPiece* p : byIndex)
        seconds += p->image.seconds;
    out.image.seconds = seconds;
    for (int y = 0; y < out.image.height; ++y)
        for (int x = 0; x < out.image.width; ++x) {
            const ReferenceImage& from = byIndex[std::size_t(shardOfPixel(x, y, count))]->image;
            const std::size_t i = std::size_t(y) * std::size_t(out.image.width) + std::size_t(x);
            out.image.image[i] = from.image[i];
            out.image.indirectOne[i] = from.indirectOne[i];
            out.image.indirectMulti[i] = from.indirectMulti[i];
            out.image.imageVariance[i] = from.imageVariance[i];
            out.image.indirectOneVariance[i] = from.indirectOneVariance[i];
            out.image.indirectMultiVariance[i] = from.indirectMultiVariance[i];
            out.image.coverage[i] = from.coverage[i];
        }
    for (const std::string& key : shardMatchKeys())
        if (auto it = first.attributes.find(key); it != first.attributes.end())
            out.attributes[key] = it->second;
    out.attributes.erase("lpv:shardTile");
    out.attributes["lpv:shards"] = std::to_string(count);
    out.attributes["lpv:seconds"] = std::to_string(seconds);
    return out;
}

} // namespace lpv::reference
