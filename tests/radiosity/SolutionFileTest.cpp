#include "RadiosityTestScenes.h"

#include "lpv/radiosity/SolutionFile.h"

#include "TestPaths.h"

#include <gtest/gtest.h>

#include <filesystem>

using namespace lpv;

namespace {

radiosity::StoredSolution solvedBox() {
    const auto scene = test::closedBox(glm::vec3(0.6f), glm::vec3(2.0f));
    radiosity::StoredSolution s;
    s.mesh = radiosity::buildPatchMesh(scene, {0.25f});
    const auto surfaces = radiosity::surfaceProperties(s.mesh, scene, {});
    radiosity::CpuFormFactors ff(s.mesh, false);
    radiosity::ProgressiveSolver solver(s.mesh, surfaces);
    for (int i = 0; i < 5; ++i)
        EXPECT_TRUE(solver.step(ff, 3).has_value());
    s.state = solver.state();
    s.sceneSignature = radiosity::sceneSignature(s.mesh, surfaces);
    s.maxPatchArea = 0.25f;
    return s;
}

} // namespace

TEST(SolutionFile, RoundTripKeepsPatchesRadiosityAndCounters) {
    const auto s = solvedBox();
    const std::string bytes = radiosity::encodeSolution(s);
    const auto back = radiosity::decodeSolution(bytes, "box.lpvrad", 2, 6);
    ASSERT_TRUE(back.has_value()) << back.error().describe();
    EXPECT_EQ(back->state, s.state);
    EXPECT_EQ(back->sceneSignature, s.sceneSignature);
    ASSERT_EQ(back->mesh.size(), s.mesh.size());
    for (std::size_t i = 0; i < s.mesh.size(); ++i) {
        EXPECT_EQ(back->mesh.patches[i].corners, s.mesh.patches[i].corners);
        EXPECT_EQ(back->mesh.patches[i].area, s.mesh.patches[i].area);
    }
    EXPECT_EQ(back->mesh.neighbours, s.mesh.neighbours);
}

TEST(SolutionFile, FlippedByteIsAChecksumError) {
    std::string bytes = radiosity::encodeSolution(solvedBox());
    bytes[bytes.size() / 2] ^= 0x40;
    const auto back = radiosity::decodeSolution(bytes, "box.lpvrad", 2, 6);
    ASSERT_FALSE(back.has_value());
    EXPECT_EQ(back.error().code, scene::ErrorCode::ChecksumMismatch);
    EXPECT_EQ(back.error().describe(),
              "box.lpvrad: byte offset 48: the payload's checksum does not match the header");
}

TEST(SolutionFile, TruncatedFileAndForeignFileAreErrors) {
    const std::string bytes = radiosity::encodeSolution(solvedBox());
    const auto cut =
        radiosity::decodeSolution(std::string_view(bytes).substr(0, bytes.size() - 10), "box.lpvrad", 2, 6);
    ASSERT_FALSE(cut.has_value());
    EXPECT_EQ(cut.error().code, scene::ErrorCode::Truncated);
    const auto foreign = radiosity::decodeSolution(std::string(64, 'x'), "box.lpvrad", 2, 6);
    ASSERT_FALSE(foreign.has_value());
    EXPECT_EQ(foreign.error().code, scene::ErrorCode::UnknownFormat);
}

TEST(SolutionFile, PatchNamingAMissingMaterialIsRejected) {
    const auto back = radiosity::decodeSolution(radiosity::encodeSolution(solvedBox()), "box.lpvrad", 1, 6);
    ASSERT_FALSE(back.has_value());
    EXPECT_EQ(back.error().code, scene::ErrorCode::IndexOutOfRange);
}

TEST(SolutionFile, SavedNextToTheProjectAndLoadedBack) {
    const auto dir = std::filesystem::path(test::kBinaryDir) / "tests" / "radiosity-solution-file";
    std::filesystem::remove_all(dir);
    const auto path = radiosity::solutionPath(dir / "Box.lpvproj");
    EXPECT_EQ(path, dir / "Box.assets" / "radiosity.lpvrad");
    const auto s = solvedBox();
    ASSERT_TRUE(radiosity::saveSolution(s, path).has_value());
    const auto back = radiosity::loadSolution(path, 2, 6);
    ASSERT_TRUE(back.has_value()) << back.error().describe();
    EXPECT_EQ(back->state, s.state);
    EXPECT_FALSE(radiosity::loadSolution(dir / "missing.lpvrad", 2, 6).has_value());
}
