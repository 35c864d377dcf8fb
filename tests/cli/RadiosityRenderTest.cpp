// `lpv render` and `lpv video` with gi.method = radiosity as a user runs
// them, on a temporary copy of the Cornell box: no solution is a failure
// that says what to do, a solution is drawn, a solution of another scene is
// refused.
#include "CornellCopyTest.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

using namespace lpv::test;
namespace fs = std::filesystem;

namespace {

class RadiosityRender : public CornellCopyTest {
  protected:
    RadiosityRender() : CornellCopyTest("cli-radiosity-render") {}

    void solve() {
        const RunResult r =
            runLpv("radiosity " + project_ + " --set radiosity.maxPatchArea=0.5 --residual 0.1");
        ASSERT_EQ(r.exitCode, 0) << r.output;
        ASSERT_TRUE(fs::exists(dir_ / "cornell" / "cornell-box.assets" / "radiosity.lpvrad")) << r.output;
    }

    RunResult render(const std::string& out) {
        return runLpv("render " + project_ + " -o " + (dir_ / out).string() +
                      " --width 64 --height 48 --frames 2 --set gi.method=radiosity");
    }
};

TEST_F(RadiosityRender, WithoutASolutionTheRenderFailsAndSaysWhatToDo) {
    const RunResult r = render("none.png");
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_TRUE(contains(r.output, "lpv: ")) << r.output;
    EXPECT_TRUE(contains(r.output, "radiosity.lpvrad: no radiosity solution is saved for this project"))
        << r.output;
    EXPECT_TRUE(contains(r.output, "lpv radiosity")) << r.output;
    EXPECT_FALSE(fs::exists(dir_ / "none.png"));
}

TEST_F(RadiosityRender, ASolutionIsDrawnAsTheIndirectLight) {
    solve();
    const RunResult r = render("baked.png");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(fs::exists(dir_ / "baked.png"));
    EXPECT_TRUE(contains(r.output, "radiosity: ")) << r.output;
    EXPECT_TRUE(contains(r.output, "Baked radiosity: on (a baked solution of ")) << r.output;
    EXPECT_TRUE(contains(r.output, "LPV: off (gi.method is radiosity: the indirect light is")) << r.output;
    EXPECT_TRUE(contains(r.output, "radiosityIndirect")) << "timed like every pass: " << r.output;
    EXPECT_FALSE(contains(r.output, "lpvPropagation")) << r.output;
}

// Moving the light after the solve makes the solution another scene's.
TEST_F(RadiosityRender, ASolutionOfAnotherSceneIsRefused) {
    solve();
    nlohmann::json project;
    std::ifstream(project_) >> project;
    project["lights"][0]["position"][0] = 2.0;
    std::ofstream(project_) << project.dump(2);
    const RunResult r = render("moved.png");
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_TRUE(contains(r.output, "the solution was solved for another scene")) << r.output;
    EXPECT_FALSE(fs::exists(dir_ / "moved.png"));
}

// lpv video loads the solution the same way, for either half.
TEST_F(RadiosityRender, AVideoShowsTheSolutionOrFailsWithoutOne) {
    std::ofstream(dir_ / "dolly.json") << kDollyPathFile;
    const RunResult imported = runLpv("path import " + project_ + " " + (dir_ / "dolly.json").string());
    ASSERT_EQ(imported.exitCode, 0) << imported.output;
    const std::string video =
        "video " + project_ + " --path dolly --fps 2 --width 32 --height 24 --warmup 0 -o ";
    const RunResult unsolved =
        runLpv(video + (dir_ / "none").string() + " --compare-set gi.method=radiosity");
    EXPECT_EQ(unsolved.exitCode, 1) << unsolved.output;
    EXPECT_TRUE(contains(unsolved.output, "no radiosity solution is saved for this project"))
        << unsolved.output;
    solve();
    const RunResult r = runLpv(video + (dir_ / "frames").string() + " --set gi.method=radiosity");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(fs::exists(dir_ / "frames" / "frame-00001.png")) << r.output;
}

} // namespace
