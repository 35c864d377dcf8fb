// A sharded sweep's files and their merge (bench/SweepShard.h), called
// directly on synthetic runs: the shards write and read back their runs and
// pixels, the merge puts the runs in combination order, and every way a set
// can fail to belong together is refused naming the folder at fault.
#include "lpv/bench/SweepShard.h"
#include "lpv/bench/ContentHash.h"
#include "lpv/bench/ReferenceFile.h"

#include "TestFiles.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <unistd.h>

using namespace lpv;
using lpv::test::freshTempDir;
namespace fs = std::filesystem;

namespace {

constexpr int kCombinations = 3; // shard 0/2 runs 0 and 2, shard 1/2 runs 1

bench::SweepRun runOf(int index) {
    bench::SweepRun run;
    run.settings = {{"lpv.propagationSteps", std::to_string(4 * (index + 1))}};
    run.totalMs = 1.5 * index;
    run.indirect.mare = 0.1 * index;
    run.indirectPixels = {glm::vec3(float(index)), glm::vec3(0.5f), glm::vec3(0.25f), glm::vec3(1.0f)};
    run.imagePixels = {glm::vec3(2.0f), glm::vec3(float(index)), glm::vec3(0.0f), glm::vec3(3.0f)};
    return run;
}

bench::SweepShard shardOf(int index, const std::string& machine = "test machine") {
    bench::SweepShard s;
    s.shard = {index, 2};
    s.combinations = kCombinations;
    s.command = "lpv bench p.lpvproj --sweep lpv.propagationSteps=4,8,12";
    s.machine = machine;
    s.width = 2;
    s.height = 2;
    s.referenceFile = "ref.exr";
    s.referenceAbsolute = "/nowhere/ref.exr";
    s.referenceHash = "0123456789abcdef";
    s.display = {{"output.exposure", "2"}};
    for (int i = 0; i < kCombinations; ++i)
        if (bench::shardRunsCombination(s.shard, i)) {
            s.indices.push_back(i);
            s.runs.push_back(runOf(i));
        }
    return s;
}

TEST(SweepShard, EachShardRunsTheCombinationsOfItsResidue) {
    EXPECT_TRUE(bench::shardRunsCombination({0, 2}, 0));
    EXPECT_FALSE(bench::shardRunsCombination({0, 2}, 1));
    EXPECT_TRUE(bench::shardRunsCombination({1, 2}, 3));
    EXPECT_TRUE(bench::shardRunsCombination({0, 1}, 7)) << "one shard runs everything";
}

TEST(SweepShard, WrittenAndReadBackKeepsRunsAndPixels) {
    const fs::path dir = freshTempDir("sweep-shard", "round-trip");
    const auto written = bench::writeSweepShard(dir, shardOf(0));
    ASSERT_TRUE(written) << written.error().describe();
    EXPECT_EQ(*written, dir / "shard.json");
    const auto back = bench::readSweepShard(dir);
    ASSERT_TRUE(back) << back.error().describe();
    EXPECT_EQ(back->shard, (reference::ShardSpec{0, 2}));
    EXPECT_EQ(back->indices, (std::vector<int>{0, 2}));
    ASSERT_EQ(back->runs.size(), 2u);
    EXPECT_EQ(back->runs[1].settings, runOf(2).settings);
    EXPECT_DOUBLE_EQ(back->runs[1].totalMs, 3.0);
    EXPECT_EQ(back->runs[1].indirectPixels, runOf(2).indirectPixels);
    EXPECT_EQ(back->runs[1].imagePixels, runOf(2).imagePixels);
    EXPECT_EQ(back->display, shardOf(0).display);
}

TEST(SweepShard, AFolderWithoutShardJsonIsAShardThatDidNotFinish) {
    const auto missing = bench::readSweepShard(freshTempDir("sweep-shard", "unfinished"));
    ASSERT_FALSE(missing);
    EXPECT_EQ(missing.error().code, scene::ErrorCode::FileNotFound);
    EXPECT_NE(missing.error().message.find("did not finish"), std::string::npos) << missing.error().message;
}

TEST(SweepShard, MergePutsTheRunsInCombinationOrder) {
    const auto merged = bench::mergeSweepShards({shardOf(1), shardOf(0)}, {"b", "a"});
    ASSERT_TRUE(merged) << merged.error().describe();
    ASSERT_EQ(merged->runs.size(), std::size_t(kCombinations));
    for (int i = 0; i < kCombinations; ++i)
        EXPECT_EQ(merged->runs[std::size_t(i)].settings, runOf(i).settings) << i;
    EXPECT_EQ(merged->machineCount, 1u);
    EXPECT_EQ(merged->note, "");
    EXPECT_EQ(merged->display.getFloat("output.exposure"), 2.0f);
}

TEST(SweepShard, ShardsOnTwoMachinesMergeWithANote) {
    const auto merged =
        bench::mergeSweepShards({shardOf(0, "machine A"), shardOf(1, "machine B")}, {"a", "b"});
    ASSERT_TRUE(merged) << merged.error().describe();
    EXPECT_EQ(merged->machineCount, 2u);
    EXPECT_NE(merged->note.find("- machine A"), std::string::npos) << merged->note;
    EXPECT_NE(merged->note.find("- machine B"), std::string::npos) << merged->note;
}

TEST(SweepShard, SetsThatDoNotBelongTogetherAreRefusedNamingTheFolder) {
    auto refusal = [](const std::vector<bench::SweepShard>& shards, const std::vector<std::string>& folders) {
        const auto merged = bench::mergeSweepShards(shards, folders);
        EXPECT_FALSE(merged);
        return merged ? scene::Error{} : merged.error();
    };
    const scene::Error incomplete = refusal({shardOf(0)}, {"a"});
    EXPECT_EQ(incomplete.file, "") << "the set as a whole is at fault";
    EXPECT_NE(incomplete.message.find("incomplete set"), std::string::npos) << incomplete.message;

    const scene::Error twice = refusal({shardOf(0), shardOf(0)}, {"a", "a2"});
    EXPECT_EQ(twice.file, "a2");
    EXPECT_NE(twice.message.find("given twice"), std::string::npos) << twice.message;

    bench::SweepShard other = shardOf(1);
    other.command += " --set lpv.gridSize=16";
    const scene::Error command = refusal({shardOf(0), other}, {"a", "b"});
    EXPECT_EQ(command.file, "b");
    EXPECT_NE(command.message.find("not a shard of the same sweep as a"), std::string::npos)
        << command.message;

    bench::SweepShard otherReference = shardOf(1);
    otherReference.referenceHash = "fedcba9876543210";
    EXPECT_NE(refusal({shardOf(0), otherReference}, {"a", "b"}).message.find("another reference"),
              std::string::npos);

    bench::SweepShard ofThree = shardOf(1);
    ofThree.shard.count = 3;
    EXPECT_NE(refusal({shardOf(0), ofThree}, {"a", "b"}).message.find("is one of 3, but a is one of 2"),
              std::string::npos);

    bench::SweepShard short1 = shardOf(1);
    short1.indices.clear();
    short1.runs.clear();
    EXPECT_NE(refusal({shardOf(0), short1}, {"a", "b"}).message.find("has 0 runs, not its 1 combinations"),
              std::string::npos);
}

TEST(SweepShard, TheReferenceMustBeTheOneMeasuredAgainst) {
    const fs::path dir = freshTempDir("sweep-shard", "reference");
    reference::ReferenceImage image;
    image.resize(2, 2);
    image.indirectMulti[3] = glm::vec3(1.0f);
    ASSERT_TRUE(
        bench::writeReferenceExr(dir / "ref.exr", image, {{"lpv:spp", "16"}, {"lpv:seconds", "0.5"}}));
    bench::SweepShard first = shardOf(0);
    first.referenceAbsolute = (dir / "ref.exr").string();
    first.referenceHash = *bench::fileContentHash(dir / "ref.exr");
    const auto loaded = bench::loadShardsReference(first, std::nullopt);
    ASSERT_TRUE(loaded) << loaded.error().describe();
    EXPECT_EQ(loaded->samplesPerPixel, 16);
    EXPECT_DOUBLE_EQ(loaded->seconds, 0.5);
    EXPECT_EQ(loaded->indirectMulti[3], glm::vec3(1.0f));

    image.indirectMulti[3] = glm::vec3(2.0f);
    ASSERT_TRUE(bench::writeReferenceExr(dir / "other.exr", image, {}));
    const auto other = bench::loadShardsReference(first, dir / "other.exr");
    ASSERT_FALSE(other);
    EXPECT_EQ(other.error().file, (dir / "other.exr").string());
    EXPECT_NE(other.error().message.find("not the reference the shards were measured against"),
              std::string::npos);
}

} // namespace
