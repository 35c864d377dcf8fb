// Sharded references (issue #28): the shards of a Cornell box reference,
// traced apart and merged, give the very bits one tracer gives; a merge of
// an incomplete, duplicated or mixed set is refused with the reason.
#include "lpv/reference/EmbreeScene.h"
#include "lpv/reference/PathTracer.h"
#include "lpv/reference/Shards.h"
#include "lpv/scene/CornellBox.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>

using namespace lpv;

namespace {

// Bitwise: -0.0 against 0.0 or two NaNs with different payloads would differ.
template <class T>
bool sameBits(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

reference::PathTracerSettings settings(int shardIndex, int shardCount) {
    reference::PathTracerSettings s;
    s.width = 72; // not a multiple of the 16-pixel tile: edge tiles are cut
    s.height = 40;
    s.samplesPerPixel = 3;
    s.bounces = 2;
    s.threads = 2;
    s.shard = {shardIndex, shardCount};
    return s;
}

std::map<std::string, std::string> header(int index, int count) {
    return {{"lpv:shard", std::to_string(index) + "/" + std::to_string(count)},
            {"lpv:projectHash", "0123456789abcdef"},
            {"lpv:parametersHash", "fedcba9876543210"},
            {"lpv:spp", "3"},
            {"lpv:shardTile", "16"}};
}

std::vector<reference::ShardPiece> blankSet(int count) {
    std::vector<reference::ShardPiece> pieces;
    for (int i = 0; i < count; ++i) {
        reference::ShardPiece p{"shard" + std::to_string(i) + ".exr", {}, header(i, count)};
        p.image.resize(40, 20);
        pieces.push_back(std::move(p));
    }
    return pieces;
}

} // namespace

TEST(Shards, MergedShardsAreBitIdenticalToOneTracer) {
    scene::Project cornell = scene::makeCornellBoxProject();
    auto embree = reference::EmbreeScene::build(cornell.scene, {});
    ASSERT_TRUE(embree);
    const scene::Camera& camera = cornell.scene.cameras.front();
    const auto whole = reference::PathTracer(*embree, cornell.scene, camera, settings(0, 1)).render();
    double lit = 0.0;
    for (const glm::vec3& e : whole.indirectMulti)
        lit += e.g;
    ASSERT_GT(lit, 0.0) << "a black image would match anything";
    for (int count : {2, 3, 5}) {
        std::vector<reference::ShardPiece> pieces;
        for (int i = count - 1; i >= 0; --i) { // any order
            reference::ShardPiece p{"shard" + std::to_string(i), {}, header(i, count)};
            p.image = reference::PathTracer(*embree, cornell.scene, camera, settings(i, count)).render();
            // A shard traces only its own tiles: the others stay black.
            for (int y = 0; y < p.image.height; ++y)
                for (int x = 0; x < p.image.width; ++x) {
                    if (reference::shardOfPixel(x, y, count) != i) {
                        ASSERT_EQ(p.image.indirectMulti[std::size_t(y * p.image.width + x)], glm::vec3(0.0f));
                    }
                }
            pieces.push_back(std::move(p));
        }
        auto merged = reference::mergeShards(pieces);
        ASSERT_TRUE(merged) << merged.error().describe();
        SCOPED_TRACE(count);
        EXPECT_TRUE(sameBits(merged->image.image, whole.image));
        EXPECT_TRUE(sameBits(merged->image.indirectOne, whole.indirectOne));
        EXPECT_TRUE(sameBits(merged->image.indirectMulti, whole.indirectMulti));
        EXPECT_TRUE(sameBits(merged->image.imageVariance, whole.imageVariance));
        EXPECT_TRUE(sameBits(merged->image.indirectOneVariance, whole.indirectOneVariance));
        EXPECT_TRUE(sameBits(merged->image.indirectMultiVariance, whole.indirectMultiVariance));
        EXPECT_TRUE(sameBits(merged->image.coverage, whole.coverage));
        EXPECT_EQ(merged->image.samplesPerPixel, whole.samplesPerPixel);
        EXPECT_EQ(merged->attributes.at("lpv:shards"), std::to_string(count));
    }
}

TEST(Shards, EveryTileBelongsToExactlyOneShardAndEveryShardGetsTiles) {
    for (int count : {1, 2, 4, 7}) {
        std::vector<int> tiles(std::size_t(count), 0);
        for (int ty = 0; ty < 8; ++ty)
            for (int tx = 0; tx < 12; ++tx) {
                int owners = 0;
                for (int i = 0; i < count; ++i)
                    if (reference::shardOwnsTile({i, count}, tx, ty)) {
                        ++owners;
                        ++tiles[std::size_t(i)];
                        EXPECT_EQ(reference::shardOfPixel(tx * 16 + 5, ty * 16 + 15, count), i);
                    }
                EXPECT_EQ(owners, 1);
            }
        // Diagonals: the shards' tile counts of a 12x8 grid differ by little.
        const auto [lo, hi] = std::ranges::minmax(tiles);
        EXPECT_GT(lo, 0);
        EXPECT_LE(hi - lo, 2) << count << " shards";
    }
}

TEST(Shards, ParsesIOverNAndRefusesTheRest) {
    auto ok = reference::parseShard("2/4");
    ASSERT_TRUE(ok);
    EXPECT_EQ(*ok, (reference::ShardSpec{2, 4}));
    EXPECT_EQ(reference::formatShard(*ok), "2/4");
    for (const char* bad : {"4/4", "-1/4", "1/0", "a/b", "3", "1/4/2", "", "1 /4"})
        EXPECT_FALSE(reference::parseShard(bad)) << bad;
}

TEST(Shards, AnIncompleteSetNamesTheMissingShards) {
    auto pieces = blankSet(5);
    pieces.erase(pieces.begin() + 3);
    pieces.erase(pieces.begin() + 1);
    auto merged = reference::mergeShards(pieces);
    ASSERT_FALSE(merged);
    EXPECT_NE(merged.error().message.find("missing shards 1/5, 3/5"), std::string::npos)
        << merged.error().message;
    EXPECT_EQ(reference::describeMissingShards({true, false, true}), "missing shard 1/3");
    EXPECT_EQ(reference::describeMissingShards({true, true}), "");
}

TEST(Shards, ADuplicateOrAMixedSetIsRefused) {
    {
        auto pieces = blankSet(3);
        pieces.push_back(pieces[1]);
        pieces.back().source = "again.exr";
        auto merged = reference::mergeShards(pieces);
        ASSERT_FALSE(merged);
        EXPECT_NE(merged.error().message.find("given twice"), std::string::npos) << merged.error().message;
    }
    {
        auto pieces = blankSet(3);
        pieces[2].attributes["lpv:projectHash"] = "1111111111111111";
        auto merged = reference::mergeShards(pieces);
        ASSERT_FALSE(merged);
        EXPECT_EQ(merged.error().file, "shard2.exr");
        EXPECT_NE(merged.error().location.find("lpv:projectHash"), std::string::npos);
    }
    {
        auto pieces = blankSet(3);
        pieces[1].attributes["lpv:spp"] = "4";
        EXPECT_FALSE(reference::mergeShards(pieces));
    }
    {
        auto pieces = blankSet(3);
        pieces[1].image.resize(40, 21);
        EXPECT_FALSE(reference::mergeShards(pieces));
    }
    {
        auto pieces = blankSet(3);
        pieces[1].attributes["lpv:shard"] = "1/4";
        EXPECT_FALSE(reference::mergeShards(pieces));
    }
    {
        auto pieces = blankSet(3);
        pieces[0].attributes.erase("lpv:shard"); // a whole reference is not a shard
        auto merged = reference::mergeShards(pieces);
        ASSERT_FALSE(merged);
        EXPECT_NE(merged.error().message.find("not a shard"), std::string::npos);
    }
}
