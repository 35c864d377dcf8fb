// `lpv dump`, run as a user would: the slice, geometry-volume, leak, RSM and
// shadow views of a Cornell box lit through its open front, and the errors
// for cascades and slices out of range.
#include "FrontSun.h"
#include "RunLpv.h"

#include "lpv/importers/ImageIO.h"
#include "lpv/scene/CornellBox.h"
#include "lpv/scene/Project.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <unistd.h>

using namespace lpv::test;
namespace fs = std::filesystem;

namespace {

// A temporary folder with the Cornell box plus a sun, saved once for every test here.
class DumpCommand : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        dir_ = freshTempDir("dump-viz");
        lpv::scene::Project project = lpv::scene::makeCornellBoxProject();
        project.scene.lights.push_back(lpv::test::cornellFrontSun());
        // Inside the box, so that the small cascades around the camera hold the lit room.
        project.scene.cameras.front().position = {2.78f, 2.73f, 1.5f};
        project.scene.cameras.front().target = {2.78f, 2.73f, 5.0f};
        ASSERT_TRUE(lpv::scene::saveProject(project, dir_ / "lit.lpvproj").has_value());
    }
    static void TearDownTestSuite() { fs::remove_all(dir_); }

    // Small and quick on llvmpipe: 8^3 cells, two cascades, 64^2 RSM tiles.
    static RunResult dump(const std::string& options, const std::string& out) {
        return runLpv(
            "dump " + (dir_ / "lit.lpvproj").string() + " -o " + (dir_ / out).string() +
            " --width 64 --height 64 --set lpv.gridSize=8 --set lpv.cascades=2 --set rsm.tileSize=64 "
            "--set shadow.mapSize=256 " +
            options);
    }
    static std::optional<lpv::scene::Image8> read(const std::string& name) {
        auto image = lpv::importers::readImage8(dir_ / name);
        if (!image)
            return std::nullopt;
        return *image;
    }

    static inline fs::path dir_;
};

} // namespace

TEST_F(DumpCommand, LpvSliceIsWrittenWithItsLegend) {
    const RunResult r = dump("--what lpv --cascade 1 --axis y --slice 3 --cell-pixels 10", "slice.png");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("CASCADE 1  Y = 3"), std::string::npos) << r.output;
    const auto image = read("slice.png");
    ASSERT_TRUE(image.has_value());
    EXPECT_GE(image->width, 80);
    EXPECT_GT(image->height, 80) << "8 cells of 10 pixels, then the legend";
    // The light inside the box is not one flat colour.
    int lo = 255 * 3, hi = 0;
    for (int y = 0; y < 80; ++y)
        for (int x = 0; x < 80; ++x) {
            const std::uint8_t* p =
                &image->pixels[(std::size_t(y) * std::size_t(image->width) + std::size_t(x)) *
                               std::size_t(image->channels)];
            lo = std::min(lo, p[0] + p[1] + p[2]);
            hi = std::max(hi, p[0] + p[1] + p[2]);
        }
    EXPECT_GT(hi - lo, 100) << r.output;
}

TEST_F(DumpCommand, GeometryLeakRsmAndShadowViews) {
    RunResult r = dump("--what gv --cascade 1 --axis x", "gv.png");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_GE(read("gv.png")->width, 9 * 12) << "the GV has N + 1 cells per axis";
    r = dump("--what leak --cascade 1 --scale log", "leak.png");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    r = dump("--what rsm --cascade 1", "rsm.png");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_GE(read("rsm.png")->width, 3 * 64) << "position, normal and flux side by side";
    r = dump("--what shadow", "shadow.png");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_GE(read("shadow.png")->width, 256);
}

TEST_F(DumpCommand, OutOfRangeRequestsAreUsageErrors) {
    RunResult r = dump("--what lpv --cascade 5", "never.png");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("--cascade 5 is outside 0..1"), std::string::npos) << r.output;
    r = dump("--what lpv --slice 8", "never.png");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("--slice 8 is outside 0..7"), std::string::npos) << r.output;
    r = dump("--what voxels", "never.png");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    r = dump("--what lpv --coefficient 4", "never.png");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_FALSE(fs::exists(dir_ / "never.png"));
    // With GI off there is no LPV to show: a failure that says why.
    r = runLpv("dump " + cornellProject() + " --what lpv -o " + (dir_ / "never.png").string() +
               " --width 32 --height 32 --set gi.method=off");
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("nothing to show: LPV: off (gi.method is off"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir_ / "never.png"));
}

// The default Cornell box's lamp is injected on auto: its LPV dumps out of the box (issue #22).
TEST_F(DumpCommand, TheDefaultCornellBoxHasAnLpvToShow) {
    const fs::path out = dir_ / "cornell-lpv.png";
    const RunResult r = runLpv("dump " + cornellProject() + " --what lpv -o " + out.string() + " --width 32 --height 32");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(fs::exists(out)) << r.output;
    EXPECT_NE(r.output.find("local-light RSM face"), std::string::npos) << r.output;
}
