// Issue #42: every output a command writes goes through a temporary file
// with checked writes; on a full disk the command fails (exit 1, "No space
// left on device") and leaves neither the output nor a temporary. Before,
// `lpv render -o out.png` printed "wrote out.png", exited 0 and left 0 bytes.
// Like SaveCleanupCommandTest, a real full tmpfs in a mount namespace of
// its own (`unshare -rm`); skipped where that cannot be had.
#include "RunLpv.h"

#include "lpv/scene/Project.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <optional>
#include <string>

using namespace lpv::test;
namespace fs = std::filesystem;

namespace {

// Runs `command` with a one-page tmpfs on `disk`, filled to the last byte
// by the file `fill`; prints "rc=N" and then every path left on the disk.
std::optional<std::string> onFullDisk(const fs::path& disk, const std::string& command) {
    fs::create_directories(disk);
    if (runShell("unshare -rm true").exitCode != 0)
        return std::nullopt;
    const RunResult r = runShell("unshare -rm sh -c \"mount -t tmpfs -o size=4k tmpfs " + quoted(disk) +
                                 " || exit 99; head -c 4096 /dev/zero > " + quoted(disk / "fill") + "; " +
                                 command + "; echo rc=\\$?; cd " + quoted(disk) + " && find . -mindepth 1\"");
    if (r.exitCode == 99)
        return std::nullopt;
    return r.output;
}

void expectCleanFailure(const std::string& out) {
    EXPECT_TRUE(contains(out, "No space left on device")) << out;
    EXPECT_FALSE(contains(out, "wrote ")) << out;
    // Only the filler is left: no output, no temporary.
    EXPECT_TRUE(out.ends_with("rc=1\n./fill\n")) << out;
}

const std::string kSkip = "no small tmpfs here (needs `unshare -rm` and tmpfs mounts in a user namespace)";

} // namespace

TEST(FullDiskOutput, RenderFailsAndLeavesNoImage) {
    const fs::path disk = freshBuildDir("cli-full-disk", "render") / "disk";
    const auto out = onFullDisk(disk, std::string(kLpvExecutable) + " render " + cornellProject() + " -o " +
                                          quoted(disk / "out.png") + " --width 32 --height 32 --frames 1");
    if (!out)
        GTEST_SKIP() << kSkip;
    expectCleanFailure(*out);
}

TEST(FullDiskOutput, CompareFailsAndLeavesNoFlipMap) {
    const fs::path dir = freshBuildDir("cli-full-disk", "compare");
    const RunResult made = runLpv("render " + cornellProject() + " -o " + quoted(dir / "a.png") +
                                  " --width 32 --height 32 --frames 1");
    ASSERT_EQ(made.exitCode, 0) << made.output;
    const auto out = onFullDisk(dir / "disk", std::string(kLpvExecutable) + " compare " +
                                                  quoted(dir / "a.png") + " " + quoted(dir / "a.png") +
                                                  " --flip-map " + quoted(dir / "disk" / "map.png"));
    if (!out)
        GTEST_SKIP() << kSkip;
    expectCleanFailure(*out);
}

TEST(FullDiskOutput, PathExportFailsAndLeavesNoFile) {
    const fs::path dir = freshBuildDir("cli-full-disk", "path-export");
    lpv::scene::Project project;
    project.name = "p";
    project.scene.cameraPaths.push_back({"orbit", {{0.0f, {0, 0, 5}}, {2.0f, {5, 0, 0}}}, false, false});
    ASSERT_TRUE(lpv::scene::saveProject(project, dir / "p.lpvproj"));
    for (const std::string name : {"path.csv", "path.json"}) {
        const auto out = onFullDisk(dir / "disk", std::string(kLpvExecutable) + " path export " +
                                                      quoted(dir / "p.lpvproj") + " --path orbit -o " +
                                                      quoted(dir / "disk" / name));
        if (!out)
            GTEST_SKIP() << kSkip;
        expectCleanFailure(*out);
    }
}

TEST(FullDiskOutput, VideoFailsAndLeavesNoMovieNorFrames) {
    const fs::path dir = freshBuildDir("cli-full-disk", "video");
    auto project = lpv::scene::loadProject(cornellProject());
    ASSERT_TRUE(project) << project.error().describe();
    project->scene.cameraPaths.push_back(
        {"orbit", {{0.0f, {0.0f, 1.0f, 3.5f}}, {0.4f, {0.2f, 1.0f, 3.5f}}}, false, false});
    ASSERT_TRUE(lpv::scene::saveProject(*project, dir / "p.lpvproj"));
    for (const std::string name : {"v.mp4", "frames"}) {
        const auto out =
            onFullDisk(dir / "disk", std::string(kLpvExecutable) + " video " + quoted(dir / "p.lpvproj") +
                                         " --path orbit -o " + quoted(dir / "disk" / name) +
                                         " --width 32 --height 32 --fps 5 --warmup 0");
        if (!out)
            GTEST_SKIP() << kSkip;
        expectCleanFailure(*out);
    }
}
