#include "../scene/FieldChanges.h"
#include "RadiosityTestScenes.h"

#include "lpv/radiosity/SolutionFile.h"
#include "lpv/scene/MeshAsset.h"

#include "TestPaths.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

#ifndef _WIN32
#include <sys/stat.h>
#endif

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
    s.sceneSignature = radiosity::sceneSignature(s.mesh, surfaces, {});
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

namespace {

// Writes `v` at `at` and seals the payload's checksum again (header bytes 40-47),
// so only the edit is wrong.
template <class T>
std::string edited(std::string bytes, std::size_t at, T v) {
    std::memcpy(bytes.data() + at, &v, sizeof v);
    const std::uint64_t sum = scene::contentHash64(std::string_view(bytes).substr(48));
    std::memcpy(bytes.data() + 40, &sum, sizeof sum);
    return bytes;
}

scene::Error decodeFails(const std::string& bytes) {
    const auto back = radiosity::decodeSolution(bytes, "box.lpvrad", 2, 6);
    EXPECT_FALSE(back.has_value());
    return back ? scene::Error{} : back.error();
}

} // namespace

// Issue #29: counts and values a solution file cannot mean, each with a valid
// checksum, are refused before anything is allocated for them.
TEST(SolutionFile, ImpossibleCountsVersionsAndValuesAreRefused) {
    const std::string bytes = radiosity::encodeSolution(solvedBox());
    const std::size_t payload = bytes.size() - 48;

    for (std::uint32_t count : {0x80000000u, 0x9C09C09u}) {
        const scene::Error e = decodeFails(edited(bytes, 12, count));
        EXPECT_EQ(e.code, scene::ErrorCode::Truncated);
        EXPECT_EQ(e.describe(), "box.lpvrad: byte offset 12: the header announces " + std::to_string(count) +
                                    " patches; the " + std::to_string(payload) + "-byte payload holds at most " +
                                    std::to_string(payload / 137));
    }
    EXPECT_EQ(decodeFails(edited(bytes, 8, std::uint32_t{0})).describe(),
              "box.lpvrad: byte offset 8: version 0 does not exist (versions start at 1)");

    // The last 72 bytes are the emitted, absorbed and escaped totals (three dvec3).
    const scene::Error nan = decodeFails(edited(bytes, bytes.size() - 72, std::nan("")));
    EXPECT_EQ(nan.code, scene::ErrorCode::NonFinite);
    EXPECT_EQ(nan.location, "byte offset " + std::to_string(bytes.size() - 72));
    EXPECT_EQ(nan.message, "the energy totals (emitted, absorbed, escaped) must be finite and at least 0");

    // Patch 0's radiosity follows every patch record (137 bytes less its 48 of light).
    const auto box = solvedBox();
    const std::size_t light = 48 + box.mesh.size() * (137 - 48);
    const scene::Error negative = decodeFails(edited(bytes, light, -1.0f));
    EXPECT_EQ(negative.code, scene::ErrorCode::OutOfRange);
    EXPECT_EQ(negative.describe(), "box.lpvrad: byte offset " + std::to_string(light) +
                                       ": radiosity of patch 0 is negative: light is never below 0");
}

// fuzz_radiosity_solution: finite corners far enough apart overflow the
// geometry the decoder derives from them (in float, as for a meshed scene);
// the solver would then multiply light by an infinite area. Each patch
// record is 89 bytes: its corner count, then per corner xyz and uv.
TEST(SolutionFile, CornersTooFarApartForAFiniteAreaOrCentreAreRefused) {
    const std::string bytes = radiosity::encodeSolution(solvedBox());
    constexpr std::size_t kRecord = 89;
    const std::size_t patch3 = 48 + 3 * kRecord;
    // The reproducer: one corner at x = -1.7e32, the others about 1 m away.
    const scene::Error area = decodeFails(edited(bytes, patch3 + 1, -1.7e32f));
    EXPECT_EQ(area.code, scene::ErrorCode::NonFinite);
    EXPECT_EQ(area.describe(), "box.lpvrad: byte offset " + std::to_string(patch3) +
                                   ": patch 3's corners are too far apart: its area is not finite");

    // Every corner of patch 5 at (3e38, 3e38, 3e38): no area, but their sum overflows the centre.
    std::string far = bytes;
    const std::size_t patch5 = 48 + 5 * kRecord;
    const auto corners = std::uint8_t(far[patch5]);
    for (std::size_t k = 0; k < corners; ++k)
        for (std::size_t axis = 0; axis < 3; ++axis)
            far = edited(far, patch5 + 1 + 20 * k + 4 * axis, 3e38f);
    const scene::Error centre = decodeFails(far);
    EXPECT_EQ(centre.code, scene::ErrorCode::NonFinite);
    EXPECT_EQ(centre.describe(), "box.lpvrad: byte offset " + std::to_string(patch5) +
                                     ": patch 5's corners are too far apart: its centre is not finite");

    // Far out but within reach of float: loaded, with finite geometry.
    const auto farButFine = radiosity::decodeSolution(edited(bytes, patch3 + 1, -1e17f), "box.lpvrad", 2, 6);
    ASSERT_TRUE(farButFine.has_value()) << farButFine.error().describe();
    const radiosity::Patch& p = farButFine->mesh.patches[3];
    EXPECT_TRUE(std::isfinite(p.area) && p.area > 1e16f) << p.area;
}

#ifndef _WIN32
TEST(SolutionFile, AFifoOrASparseGiantIsRefusedBeforeReading) {
    const auto dir = std::filesystem::path(test::kBinaryDir) / "tests" / "radiosity-solution-special";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const auto fifo = dir / "fifo.lpvrad";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    const auto a = radiosity::loadSolution(fifo, 2, 6);
    ASSERT_FALSE(a.has_value());
    EXPECT_EQ(a.error().message, "is a FIFO (named pipe), not a regular file: only regular files are read");
    const auto giant = dir / "giant.lpvrad";
    std::ofstream(giant) << "x";
    std::filesystem::resize_file(giant, std::uintmax_t{100} << 30);
    const auto b = radiosity::loadSolution(giant, 2, 6);
    ASSERT_FALSE(b.has_value());
    EXPECT_EQ(b.error().message, "the file is 100.0 GiB, more than a radiosity solution can be (1.0 GiB); "
                                 "refused before reading");
    std::filesystem::remove_all(dir);
}
#endif

// Every light field but the name is part of the signature, through the
// light's field table (SceneFields.h): a field added there cannot be
// forgotten here, which would let a stale solution be loaded as current.
TEST(SolutionFile, EveryLightFieldButItsNameChangesTheSignature) {
    const auto scene = test::closedBox(glm::vec3(0.6f), glm::vec3(2.0f));
    const radiosity::PatchMesh mesh = radiosity::buildPatchMesh(scene, {0.5f});
    const auto surfaces = radiosity::surfaceProperties(mesh, scene, {});
    const auto signature = [&](const scene::Light& l) {
        return radiosity::sceneSignature(mesh, surfaces, {&l, 1});
    };
    scene::Light base;
    base.type = scene::LightType::Area;
    const auto missed = test::fieldsNotAffecting(
        base, [&](const scene::Light& a, const scene::Light& b) { return signature(a) != signature(b); });
    EXPECT_EQ(missed, std::vector<std::string>{"name"});
}
