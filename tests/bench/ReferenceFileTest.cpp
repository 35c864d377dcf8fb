// The reference file format (bench/ReferenceFile.h) and the hashes that tie
// shards together (bench/ContentHash.h), called directly: a reference
// written and read back is the same image with its header's numbers, a file
// that is not a reference is refused by name, and the hashes change exactly
// when what they stand for changes.
#include "lpv/bench/ContentHash.h"
#include "lpv/bench/ReferenceFile.h"

#include "lpv/importers/ImageIO.h"
#include "lpv/scene/ParameterRegistry.h"

#include "TestFiles.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

using namespace lpv;
using lpv::test::freshTempDir;
namespace fs = std::filesystem;

namespace {

reference::ReferenceImage sampleImage() {
    reference::ReferenceImage image;
    image.resize(3, 2);
    for (std::size_t i = 0; i < image.pixelCount(); ++i) {
        const float f = float(i);
        image.image[i] = {f, f + 0.5f, f + 0.25f};
        image.indirectOne[i] = {0.1f * f, 0.2f, 0.3f};
        image.indirectMulti[i] = {0.2f * f, 0.4f, 0.6f};
        image.indirectMultiVariance[i] = {0.01f, 0.02f, 0.03f * f};
        image.coverage[i] = i % 2 ? 1.0f : 0.0f;
    }
    return image;
}

TEST(ReferenceFile, WrittenAndReadBackIsTheSameImageWithItsHeaderNumbers) {
    const fs::path file = freshTempDir("reference-file", "round-trip") / "ref.exr";
    const reference::ReferenceImage image = sampleImage();
    ASSERT_TRUE(bench::writeReferenceExr(file, image,
                                         {{"lpv:spp", "64"}, {"lpv:seconds", "2.500000"}, {"lpv:bounces", "3"}}));
    const auto loaded = bench::readReferenceExr(file);
    ASSERT_TRUE(loaded) << loaded.error().describe();
    EXPECT_EQ(loaded->image.width, 3);
    EXPECT_EQ(loaded->image.height, 2);
    EXPECT_EQ(loaded->image.samplesPerPixel, 64);
    EXPECT_DOUBLE_EQ(loaded->image.seconds, 2.5);
    EXPECT_EQ(loaded->bounces(), 3);
    EXPECT_EQ(loaded->attributes.at("lpv:spp"), "64");
    EXPECT_EQ(loaded->image.image, image.image);
    EXPECT_EQ(loaded->image.indirectOne, image.indirectOne);
    EXPECT_EQ(loaded->image.indirectMulti, image.indirectMulti);
    EXPECT_EQ(loaded->image.indirectMultiVariance, image.indirectMultiVariance);
    EXPECT_EQ(loaded->image.coverage, image.coverage);
    EXPECT_EQ(bench::describeReferenceFile(file), "3x2, 64 spp in 2.5 s");
    EXPECT_EQ(bench::describeReferenceFile(file.parent_path() / "missing.exr"), "unreadable");
}

TEST(ReferenceFile, HeaderNumbersThatAreNotNumbersReadAsAbsent) {
    const fs::path file = freshTempDir("reference-file", "bad-header") / "ref.exr";
    ASSERT_TRUE(bench::writeReferenceExr(file, sampleImage(), {{"lpv:spp", "64x"}, {"lpv:bounces", "many"}}));
    const auto loaded = bench::readReferenceExr(file);
    ASSERT_TRUE(loaded) << loaded.error().describe();
    EXPECT_EQ(loaded->image.samplesPerPixel, 0);
    EXPECT_DOUBLE_EQ(loaded->image.seconds, 0.0);
    EXPECT_FALSE(loaded->bounces().has_value());
}

TEST(ReferenceFile, AnRgbImageIsNotAReferenceButReadsAsRgb) {
    const fs::path file = freshTempDir("reference-file", "rgb") / "frame.exr";
    importers::FloatChannels rgb{2, 1, {"R", "G", "B"}, {1.0f, 2.0f, 3.0f, 4.0f, 5.0f, 6.0f}, {}};
    ASSERT_TRUE(importers::writeImageChannels(file, rgb, {{"lpv:outputView", "indirect"}}));

    const auto asReference = bench::readReferenceExr(file);
    ASSERT_FALSE(asReference);
    EXPECT_EQ(asReference.error().code, scene::ErrorCode::MissingField);
    EXPECT_NE(asReference.error().describe().find("not a reference image"), std::string::npos)
        << asReference.error().describe();

    const auto asRgb = bench::readRgbExr(file);
    ASSERT_TRUE(asRgb) << asRgb.error().describe();
    EXPECT_EQ(asRgb->outputView, "indirect");
    ASSERT_EQ(asRgb->pixels.size(), 2u);
    EXPECT_EQ(asRgb->pixels[1], glm::vec3(4.0f, 5.0f, 6.0f));
}

TEST(ReferenceFile, AnImageWithoutRgbIsRefusedAsRgb) {
    const fs::path file = freshTempDir("reference-file", "no-rgb") / "y.exr";
    ASSERT_TRUE(importers::writeImageChannels(file, {1, 1, {"Y"}, {0.5f}, {}}));
    const auto rgb = bench::readRgbExr(file);
    ASSERT_FALSE(rgb);
    EXPECT_EQ(rgb.error().code, scene::ErrorCode::MissingField);
}

TEST(ContentHash, FileHashFollowsTheBytes) {
    const fs::path dir = freshTempDir("reference-file", "hash");
    std::ofstream(dir / "a") << "same bytes";
    std::ofstream(dir / "b") << "same bytes";
    std::ofstream(dir / "c") << "other bytes";
    const auto a = bench::fileContentHash(dir / "a");
    ASSERT_TRUE(a);
    EXPECT_EQ(a->size(), 16u);
    EXPECT_EQ(*a, *bench::fileContentHash(dir / "b"));
    EXPECT_NE(*a, *bench::fileContentHash(dir / "c"));
    EXPECT_FALSE(bench::fileContentHash(dir / "missing"));
}

TEST(ContentHash, ParametersHashIgnoresOrderButNotValues) {
    scene::ParameterSet ab, ba, other;
    ASSERT_TRUE(ab.setFromText("lpv.propagationSteps", "8"));
    ASSERT_TRUE(ab.setFromText("lpv.gridSize", "16"));
    ASSERT_TRUE(ba.setFromText("lpv.gridSize", "16"));
    ASSERT_TRUE(ba.setFromText("lpv.propagationSteps", "8"));
    ASSERT_TRUE(other.setFromText("lpv.gridSize", "16"));
    ASSERT_TRUE(other.setFromText("lpv.propagationSteps", "9"));
    EXPECT_EQ(bench::parametersHash(ab), bench::parametersHash(ba));
    EXPECT_NE(bench::parametersHash(ab), bench::parametersHash(other));
    EXPECT_NE(bench::parametersHash(ab), bench::parametersHash(scene::ParameterSet{}));
}

} // namespace
