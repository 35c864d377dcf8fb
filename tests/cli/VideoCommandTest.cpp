// `lpv video` and `lpv path` as a user runs them, on a temporary copy of the
// Cornell box (the committed project has no camera path).
#include "CornellCopyTest.h"

#include "lpv/scene/CameraPathFile.h"
#include "lpv/scene/Project.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <unistd.h>

using namespace lpv::test;
namespace fs = std::filesystem;

namespace {

class VideoCommand : public CornellCopyTest {
  protected:
    VideoCommand() : CornellCopyTest("cli-video") {}
    void SetUp() override {
        CornellCopyTest::SetUp();
        std::ofstream(dir_ / "dolly.json") << kDollyPathFile;
    }

    // Imports the dolly path into the copy.
    void importDolly() {
        const RunResult r = runLpv("path import " + project_ + " " + (dir_ / "dolly.json").string());
        ASSERT_EQ(r.exitCode, 0) << r.output;
    }
};

} // namespace

TEST_F(VideoCommand, HelpNamesTheOptions) {
    const RunResult help = runLpv("video --help");
    EXPECT_EQ(help.exitCode, 0);
    for (const char* option : {"--path NAME", "--fps", "--width", "--height", "--set", "--compare-set",
                               "--label-a", "--label-b", "%05d"})
        EXPECT_TRUE(contains(help.output, option)) << option;
    const RunResult all = runLpv("--help");
    EXPECT_TRUE(contains(all.output, "video PROJECT --path NAME -o OUT.mp4")) << all.output;
    EXPECT_TRUE(contains(all.output, "path export PROJECT")) << all.output;
    EXPECT_TRUE(contains(all.output, "path import PROJECT")) << all.output;
    EXPECT_EQ(runLpv("path --help").exitCode, 0);
    EXPECT_EQ(runLpv("help path").exitCode, 0);
}

TEST_F(VideoCommand, UsageErrorsExitTwo) {
    importDolly();
    const std::string base = "video " + project_ + " --path dolly";
    const std::string mp4 = (dir_ / "x.mp4").string();
    for (const std::string& args : {
             "video " + project_ + " -o " + mp4,                               // no --path
             base,                                                             // no -o
             base + " -o " + mp4 + " --width 161 --height 120",                // odd size for H.264
             base + " -o " + mp4 + " --fps 0",                                 // frame rate
             base + " -o " + mp4 + " --set lpv.noSuchKey=1",                   // registry
             base + " -o " + mp4 + " --compare-set output.exposure=99",        // out of range
             base + " -o " + mp4 + " --set output.exposure",                   // no '='
             base + " -o " + (dir_ / "x.mov").string(),                        // format
             base + " -o " + mp4 + " --label-a A",                             // label without comparison
             base + " -o " + mp4 + " --bogus",                                 // unknown option
             "video " + project_ + " " + project_ + " --path dolly -o " + mp4, // two projects
         }) {
        const RunResult r = runLpv(args);
        EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.output;
    }
    EXPECT_TRUE(contains(runLpv(base + " -o " + mp4 + " --width 161 --height 120").output, "even width"));
    EXPECT_FALSE(fs::exists(mp4));
}

TEST_F(VideoCommand, FailuresExitOneNamingTheProblem) {
    importDolly();
    const RunResult noPath = runLpv("video " + project_ + " --path tour -o " + (dir_ / "x.mp4").string());
    EXPECT_EQ(noPath.exitCode, 1);
    EXPECT_TRUE(contains(noPath.output, "no camera path named \"tour\" (paths: \"dolly\")")) << noPath.output;
    const RunResult noProject =
        runLpv("video /nonexistent/p.lpvproj --path dolly -o " + (dir_ / "x.mp4").string());
    EXPECT_EQ(noProject.exitCode, 1);
    EXPECT_TRUE(contains(noProject.output, "/nonexistent/p.lpvproj")) << noProject.output;
}

TEST_F(VideoCommand, WritesAnMp4AndReportsProgress) {
    importDolly();
    const fs::path mp4 = dir_ / "out" / "dolly.mp4";
    const RunResult r = runLpv("video " + project_ + " --path dolly -o " + mp4.string() +
                               " --width 96 --height 64 --fps 20 --warmup 0");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(fs::is_regular_file(mp4));
    EXPECT_GT(fs::file_size(mp4), 1000u);
    // Not a terminal: one line per 10%, the last one complete.
    EXPECT_TRUE(contains(r.output, "20 frames at 20 fps, 96x64")) << r.output;
    EXPECT_TRUE(contains(r.output, "frame 2/20, ")) << r.output;
    EXPECT_TRUE(contains(r.output, "frame 20/20, ")) << r.output;
    EXPECT_TRUE(contains(r.output, " s elapsed, ~")) << r.output;
    EXPECT_FALSE(contains(r.output, "frame 3/20")) << r.output;
    EXPECT_FALSE(contains(r.output, "\r"));
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 12) << r.output;
    std::set<std::string> left;
    for (const auto& e : fs::directory_iterator(dir_ / "out"))
        left.insert(e.path().filename().string());
    EXPECT_EQ(left, std::set<std::string>{"dolly.mp4"});
}

TEST_F(VideoCommand, SideBySidePngSequence) {
    importDolly();
    const RunResult r = runLpv("video " + project_ + " --path dolly -o " + (dir_ / "ab").string() +
                               " --width 64 --height 32 --fps 4 --warmup 0 --set output.exposure=-2"
                               " --compare-set output.exposure=2 --label-a \"EV -2\" --label-b \"EV +2\"");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(contains(r.output, "side by side")) << r.output;
    for (int i = 0; i < 4; ++i)
        EXPECT_TRUE(fs::exists(dir_ / "ab" / ("frame-0000" + std::to_string(i) + ".png"))) << i;
    EXPECT_FALSE(fs::exists(dir_ / "ab" / "frame-00004.png"));
}

TEST_F(VideoCommand, PathExportImportRoundTrip) {
    importDolly();
    const fs::path json = dir_ / "exported.json";
    RunResult r = runLpv("path export " + project_ + " --path dolly -o " + json.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto exported = lpv::scene::loadCameraPathFile(json);
    ASSERT_TRUE(exported) << exported.error().describe();
    const auto original = lpv::scene::loadCameraPathFile(dir_ / "dolly.json");
    ASSERT_TRUE(original);
    EXPECT_EQ(*exported, *original);

    // Import under another name: the project then has both, equal but for the name.
    r = runLpv("path import " + project_ + " " + json.string() + " --name copy");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(contains(r.output, "added path 'copy' (3 keyframes)")) << r.output;
    auto project = lpv::scene::loadProject(project_);
    ASSERT_TRUE(project) << project.error().describe();
    ASSERT_EQ(project->scene.cameraPaths.size(), 2u);
    lpv::scene::CameraPath renamed = project->scene.cameraPaths[1];
    EXPECT_EQ(renamed.name, "copy");
    renamed.name = "dolly";
    EXPECT_EQ(renamed, project->scene.cameraPaths[0]);

    // Importing again replaces rather than adds.
    r = runLpv("path import " + project_ + " " + json.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(contains(r.output, "replaced path 'dolly'")) << r.output;
    EXPECT_EQ(lpv::scene::loadProject(project_)->scene.cameraPaths.size(), 2u);

    // CSV: one row per frame, both ends included.
    r = runLpv("path export " + project_ + " --path dolly -o " + (dir_ / "dolly.csv").string() + " --fps 24");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const std::string csv = readText(dir_ / "dolly.csv");
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 25);
    EXPECT_TRUE(csv.starts_with("time,px,py,pz,qx,qy,qz,qw,fovY_deg\n0,2.78,2.73,-8,")) << csv.substr(0, 120);
}

TEST_F(VideoCommand, BadPathFileChangesNothing) {
    importDolly();
    const std::string before = readText(project_);
    std::string text = kDollyPathFile;
    text.replace(text.find("\"time\": 1,"), 10, "\"time\": 0.2,");
    std::ofstream(dir_ / "unsorted.json") << text;
    const RunResult r = runLpv("path import " + project_ + " " + (dir_ / "unsorted.json").string());
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_TRUE(contains(r.output, "keyframes[2].time")) << r.output;
    EXPECT_EQ(readText(project_), before);

    EXPECT_EQ(runLpv("path export " + project_ + " --path dolly -o " + (dir_ / "x.txt").string()).exitCode,
              2);
    EXPECT_EQ(
        runLpv("path export " + project_ + " --path dolly -o " + (dir_ / "x.json").string() + " --fps 10")
            .exitCode,
        2);
    const RunResult missing =
        runLpv("path export " + project_ + " --path nope -o " + (dir_ / "x.json").string());
    EXPECT_EQ(missing.exitCode, 1);
    EXPECT_TRUE(contains(missing.output, "no camera path named 'nope' (paths: 'dolly')")) << missing.output;
    EXPECT_EQ(runLpv("path frobnicate " + project_).exitCode, 2);
    EXPECT_EQ(runLpv("path").exitCode, 2);
}
