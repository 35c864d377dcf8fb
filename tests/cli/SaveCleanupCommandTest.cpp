// Issue #29: `lpv import` and `lpv radiosity -o` on a failing disk leave
// nothing behind. The failures are made two ways: structurally (a file or
// folder where the save must put something else; works as root, unlike a
// read-only folder) and, where the system lets a user mount a small tmpfs in
// a namespace of its own (`unshare -rm`), on a real full disk.
#include "RunLpv.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <string>

using namespace lpv::test;
namespace fs = std::filesystem;

namespace {

// Everything under `root`, relative, folders with a trailing '/'.
std::set<std::string> listAll(const fs::path& root) {
    std::set<std::string> out;
    for (const auto& e : fs::recursive_directory_iterator(root))
        out.insert(e.path().lexically_relative(root).generic_string() + (e.is_directory() ? "/" : ""));
    return out;
}

// A fresh folder for one test.
// One textured triangle: quad.obj, quad.mtl and an 8 KiB tex.png (a 1x1 PNG
// padded after its end, exactly two pages of a tmpfs).
fs::path writeTexturedObj(const fs::path& dir) {
    std::ofstream(dir / "quad.obj") << "mtllib quad.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\n"
                                       "usemtl brick\nf 1/1 2/2 3/3\n";
    std::ofstream(dir / "quad.mtl") << "newmtl brick\nKd 1 1 1\nmap_Kd tex.png\n";
    const std::string hex =
        "89504e470d0a1a0a0000000d4948445200000001000000010802000000907753de0000000c4944415478"
        "9c63f8cfc0000003010100c9fe92ef0000000049454e44ae426082";
    std::string png;
    for (std::size_t i = 0; i < hex.size(); i += 2)
        png.push_back(static_cast<char>(std::stoi(hex.substr(i, 2), nullptr, 16)));
    png.resize(8192, '\0');
    std::ofstream(dir / "tex.png", std::ios::binary) << png;
    return dir / "quad.obj";
}

// Runs `command` with a tmpfs of `size` mounted on `mountPoint`, in a mount
// namespace of its own (the mount goes with it); prints "rc=N" and then
// every path left under the mount point. Empty when it cannot be done here.
std::optional<std::string> onSmallDisk(const fs::path& mountPoint, const std::string& size,
                                       const std::string& command) {
    fs::create_directories(mountPoint);
    if (runShell("unshare -rm true").exitCode != 0)
        return std::nullopt;
    const RunResult r = runShell("unshare -rm sh -c \"mount -t tmpfs -o size=" + size + " tmpfs " +
                                 quoted(mountPoint) + " || exit 99; " + command + "; echo rc=\\$?; cd " +
                                 quoted(mountPoint) + " && find . -mindepth 1\"");
    if (r.exitCode == 99)
        return std::nullopt;
    return r.output;
}

const std::string kCoarse = " --set radiosity.maxPatchArea=0.5 --residual 0.3 --cpu";

} // namespace

// A file where the mesh folder must go: the textures were copied, then the
// save failed; the copies go again (they were left behind).
TEST(SaveCleanupCommand, AnImportWhoseSaveFailsTakesBackTheTexturesItCopied) {
    const fs::path dir = freshBuildDir("cli-save-cleanup", "import-structural");
    const fs::path obj = writeTexturedObj(dir);
    fs::create_directories(dir / "out" / "p.assets");
    std::ofstream(dir / "out" / "p.assets" / "meshes") << "in the way";

    const RunResult r = runLpv("import " + quoted(obj) + " --no-sun -o " + quoted(dir / "out" / "p.lpvproj"));
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_TRUE(contains(r.output, "cannot create the folder")) << r.output;
    EXPECT_TRUE(contains(r.output, "lpv: nothing was saved")) << r.output;
    EXPECT_EQ(listAll(dir / "out"), (std::set<std::string>{"p.assets/", "p.assets/meshes"}));
}

// A real full disk: room for the texture copy (two pages), none for the mesh.
TEST(SaveCleanupCommand, AnImportOnAFullDiskLeavesNothing) {
    const fs::path dir = freshBuildDir("cli-save-cleanup", "import-full");
    const fs::path obj = writeTexturedObj(dir);
    const fs::path disk = dir / "disk";
    const auto out = onSmallDisk(disk, "8k",
                                 std::string(kLpvExecutable) + " import " + quoted(obj) + " --no-sun -o " +
                                     quoted(disk / "p.lpvproj"));
    if (!out)
        GTEST_SKIP() << "no small tmpfs here (needs `unshare -rm` and tmpfs mounts in a user namespace)";
    EXPECT_TRUE(contains(*out, "No space left on device")) << *out;
    EXPECT_TRUE(contains(*out, "rc=1\n")) << *out;
    EXPECT_TRUE(out->ends_with("rc=1\n")) << "files were left on the disk:\n" << *out;
}

// The solution is an asset of the new project: it is written first, so a
// failure writing it leaves no project (the project used to be written
// first and stay without its solution).
TEST(SaveCleanupCommand, RadiosityWritesTheSolutionBeforeTheProject) {
    const fs::path dir = freshBuildDir("cli-save-cleanup", "radiosity-solution-fails");
    fs::create_directories(dir / "q.assets" / "radiosity.lpvrad" / "in the way");
    const RunResult r =
        runLpv("radiosity " + cornellProject() + kCoarse + " -o " + quoted(dir / "q.lpvproj"));
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_TRUE(contains(r.output, "lpv: nothing was saved")) << r.output;
    EXPECT_EQ(listAll(dir), (std::set<std::string>{"q.assets/", "q.assets/radiosity.lpvrad/",
                                                   "q.assets/radiosity.lpvrad/in the way/"}));
}

// The project cannot be written (a folder has its name): the solution
// written before it goes again, with the folders made for it.
TEST(SaveCleanupCommand, RadiosityTakesBackTheSolutionWhenTheProjectCannotBeSaved) {
    const fs::path dir = freshBuildDir("cli-save-cleanup", "radiosity-project-fails");
    fs::create_directories(dir / "q.lpvproj" / "in the way");
    const RunResult r =
        runLpv("radiosity " + cornellProject() + kCoarse + " -o " + quoted(dir / "q.lpvproj"));
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_TRUE(contains(r.output, "cannot replace the file")) << r.output;
    EXPECT_EQ(listAll(dir), (std::set<std::string>{"q.lpvproj/", "q.lpvproj/in the way/"}));
}

// A real full disk of 56 KiB: the Cornell box's solution (about 49 KB) fits,
// its meshes after it do not. Before, the project and meshes (about 12 KB)
// were written, the solution failed, and the project stayed without it.
TEST(SaveCleanupCommand, RadiosityOnAFullDiskLeavesNothing) {
    const fs::path dir = freshBuildDir("cli-save-cleanup", "radiosity-full");
    const fs::path disk = dir / "disk";
    const auto out = onSmallDisk(disk, "56k",
                                 std::string(kLpvExecutable) + " radiosity " + cornellProject() + kCoarse +
                                     " -o " + quoted(disk / "q.lpvproj"));
    if (!out)
        GTEST_SKIP() << "no small tmpfs here (needs `unshare -rm` and tmpfs mounts in a user namespace)";
    EXPECT_TRUE(contains(*out, "No space left on device")) << *out;
    EXPECT_TRUE(contains(*out, "lpv: nothing was saved")) << *out;
    EXPECT_TRUE(out->ends_with("rc=1\n")) << "files were left on the disk:\n" << *out;
}
