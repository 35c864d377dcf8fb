// Issue #29: saves clean up what killed and failed saves left behind
// (temporary files, texture copies no material names) and nothing else, and
// a save of several steps can take back what it created.
#include "ProjectTestSupport.h"

#include "lpv/scene/ProjectTextures.h"
#include "lpv/scene/SaveCleanup.h"

#include <gtest/gtest.h>

#include <chrono>

#ifndef _WIN32
#include <unistd.h>
#endif

using namespace lpv::scene;
using namespace lpv::test;
namespace fs = std::filesystem;

namespace {

// No process can have this id (Linux allows at most 2^22; others less than 2^31).
const std::string kDeadPid = "2147483646";

Project quadProject() {
    Project p;
    p.name = "p";
    Material m;
    m.name = "m";
    p.scene.materials = {m};
    Mesh quad;
    quad.name = "quad";
    quad.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}};
    quad.normals.assign(3, {0, 0, 1});
    quad.uvs = {{0, 0}, {1, 0}, {1, 1}};
    quad.indices = {0, 1, 2};
    quad.submeshes = {{0, 3, 0}};
    p.scene.meshes = {quad};
    p.scene.objects = {Object{"quad", 0, -1, {}, true, {}}};
    return p;
}

class SaveCleanup : public TempDirTest {
protected:
    SaveCleanup() : TempDirTest("lpv-cleanup-") {}

    fs::path touch(const fs::path& relative, const std::string& bytes = "x") {
        const fs::path file = dir_ / relative;
        fs::create_directories(file.parent_path());
        writeFile(file, bytes);
        return file;
    }
    bool has(const std::string& relative) const { return fs::exists(fs::symlink_status(dir_ / relative)); }
};

} // namespace

TEST(SaveCleanupNames, TemporaryNamesAreOursOnlyInTheirExactForm) {
    const auto t = parseTemporaryName("p.lpvproj.tmp-1234-7");
    ASSERT_TRUE(t);
    EXPECT_EQ(t->base, "p.lpvproj");
    EXPECT_EQ(t->pid, 1234);
    EXPECT_EQ(parseTemporaryName("a.tmp-1-2.tmp-3-4")->base, "a.tmp-1-2");
    for (const char* other :
         {"p.lpvproj", "p.lpvproj.tmp-1234-7.bak", "p.lpvproj.tmp-x-7", "p.lpvproj.tmp-1234-",
          "p.lpvproj.tmp--7", "p.lpvproj.tmp1234-7", ".tmp-1-2", "p.lpvproj.tmp-1234"})
        EXPECT_FALSE(parseTemporaryName(other)) << other;
}

TEST(SaveCleanupNames, TextureCopyNamesAreSixteenLowerCaseHexDigitsADashAndAName) {
    EXPECT_TRUE(isTextureCopyName("0123456789abcdef-brick.png"));
    EXPECT_TRUE(isTextureCopyName("0123456789abcdef-x"));
    for (const char* other : {"0123456789abcdef-", "0123456789ABCDEF-brick.png", "0123456789abcde-brick.png",
                              "0123456789abcdefg-brick.png", "0123456789abcdef_brick.png", "brick.png",
                              "0123456789abcdef-brick.png.tmp-12-0"})
        EXPECT_FALSE(isTextureCopyName(other)) << other;
}

// A save removes the temporary files of killed saves of the same files: the
// project file's, its meshes' and its texture copies'. Not this process's
// (a save may be running in another thread), not a running process's, not
// another file's, not names that only look alike, not folders.
TEST_F(SaveCleanup, KilledSavesTemporaryFilesGoOnTheNextSaveAndNothingElse) {
    const fs::path project = dir_ / "p.lpvproj";
    ASSERT_TRUE(saveProject(quadProject(), project));
    const std::string own = pidText();
    const std::vector<std::string> stale = {
        "p.lpvproj.tmp-" + kDeadPid + "-0",
        "p.assets/meshes/0-0123456789abcdef.lpvmesh.tmp-" + kDeadPid + "-3",
        "p.assets/textures/0123456789abcdef-a.png.tmp-" + kDeadPid + "-2",
    };
    std::vector<std::string> kept = {
        "p.lpvproj.tmp-" + own + "-7",
        "other.lpvproj.tmp-" + kDeadPid + "-0",
        "p.lpvproj.tmp-" + kDeadPid + "-0.bak",
        "p.lpvproj.tmp-x-0",
        "p.lpvproj.tmp" + kDeadPid + "-0",
        "p.assets/meshes/notes.txt.tmp-" + kDeadPid + "-3",
        "p.assets/textures/readme.tmp-" + kDeadPid + "-2",
        "p.assets/p.lpvproj.tmp-" + kDeadPid + "-2",
    };
#ifndef _WIN32
    kept.push_back("p.lpvproj.tmp-" + std::to_string(::getppid()) + "-1"); // a running process
#endif
    for (const std::string& f : stale)
        touch(f);
    for (const std::string& f : kept)
        touch(f);
    fs::create_directories(dir_ / ("p.lpvproj.tmp-" + kDeadPid + "-1"));

    ASSERT_TRUE(saveProject(quadProject(), project));
    for (const std::string& f : stale)
        EXPECT_FALSE(has(f)) << f;
    for (const std::string& f : kept)
        EXPECT_TRUE(has(f)) << f;
    EXPECT_TRUE(fs::is_directory(dir_ / ("p.lpvproj.tmp-" + kDeadPid + "-1")));
}

#ifdef __linux__
// A pid is reused: a temporary file last written before the process that has
// its pid now was started cannot be that process's.
TEST_F(SaveCleanup, ATemporaryFileOlderThanTheProcessWithItsPidIsStale) {
    const std::string pid = std::to_string(::getppid());
    const fs::path old = touch("p.lpvproj.tmp-" + pid + "-4");
    const fs::path recent = touch("p.lpvproj.tmp-" + pid + "-5");
    fs::last_write_time(old, fs::file_time_type::clock::now() - std::chrono::hours(24 * 365 * 30));
    EXPECT_EQ(removeStaleTemporaries(dir_ / "p.lpvproj"), 1u);
    EXPECT_FALSE(fs::exists(old));
    EXPECT_TRUE(fs::exists(recent));
}
#endif

// Texture copies no material names any more (left by a killed import, a
// failed save, or an edit that dropped the texture) go on the next save;
// files of other names, folders, temporary files and copies some slot still
// names (even in another case or folder) stay.
TEST_F(SaveCleanup, OrphanTextureCopiesAreCollectedOnSaveAndNothingElse) {
    const fs::path source = touch("source/brick.png", "brick bytes");
    Project p = quadProject();
    p.scene.materials[0].diffuseTexture = source.string();
    Material other;
    other.name = "other";
    other.normalTexture = "elsewhere/0123456789abcdef-KEPT.png";
    p.scene.materials.push_back(other);
    const fs::path project = dir_ / "p.lpvproj";
    ASSERT_TRUE(copyTexturesIntoProject(p.scene, project));
    const std::string copy = p.scene.materials[0].diffuseTexture;
    ASSERT_TRUE(copy.starts_with("p.assets/textures/")) << copy;
    ASSERT_TRUE(saveProject(p, project));

    const std::string orphan = "p.assets/textures/0123456789abcdef-old.png";
    const std::vector<std::string> kept = {
        copy,
        "p.assets/textures/0123456789abcdef-kept.png",
        "p.assets/textures/0123456789abcdef-old.png.tmp-" + pidText() + "-1",
        "p.assets/textures/0123456789ABCDEF-x.png",
        "p.assets/textures/notes.txt",
        "p.assets/textures/abc-x.png",
        "p.assets/0123456789abcdef-old.png",
        "0123456789abcdef-old.png",
    };
    touch(orphan);
    for (const std::string& f : kept)
        if (!has(f))
            touch(f);
    fs::create_directories(dir_ / "p.assets/textures/0123456789abcdef-folder");

    // A save that fails collects nothing: a file where its mesh folder must go.
    fs::remove_all(dir_ / "p.assets/meshes");
    touch("p.assets/meshes");
    const auto failed = saveProject(p, project);
    ASSERT_FALSE(failed);
    EXPECT_EQ(failed.error().code, ErrorCode::IoError);
    EXPECT_TRUE(has(orphan));
    fs::remove(dir_ / "p.assets/meshes");

    ASSERT_TRUE(saveProject(p, project));
    EXPECT_FALSE(has(orphan));
    for (const std::string& f : kept)
        EXPECT_TRUE(has(f)) << f;
    EXPECT_TRUE(fs::is_directory(dir_ / "p.assets/textures/0123456789abcdef-folder"));

    // An edit drops the texture: its copy goes with the next save.
    p.scene.materials[0].diffuseTexture.clear();
    ASSERT_TRUE(saveProject(p, project));
    EXPECT_FALSE(has(copy));
    EXPECT_TRUE(has("p.assets/textures/0123456789abcdef-kept.png"));
}

// What a save of several steps created goes again; what was there stays.
TEST_F(SaveCleanup, RollbackRemovesWhatTheSaveCreatedAndOnlyThat) {
    const fs::path textures = dir_ / "q.assets" / "textures";
    const fs::path before = touch("q.assets/textures/0123456789abcdef-before.png");
    const fs::path replaced = touch("q.assets/radiosity.lpvrad", "old");
    SaveRollback rollback;
    rollback.watchTextureCopies(textures);
    rollback.willWrite(replaced);
    const fs::path solution = dir_ / "new" / "deeper" / "radiosity.lpvrad";
    rollback.willWrite(solution);

    const fs::path copied = touch("q.assets/textures/fedcba9876543210-new.png");
    const fs::path stranger = touch("q.assets/textures/notes.txt");
    writeFile(replaced, "new");
    touch("new/deeper/radiosity.lpvrad");
    rollback.undo();

    EXPECT_FALSE(fs::exists(copied));
    EXPECT_TRUE(fs::exists(before));
    EXPECT_TRUE(fs::exists(stranger)) << "not a name the save gives";
    EXPECT_EQ(readFile(replaced), "new") << "a replaced file is not restored, nor removed";
    EXPECT_FALSE(fs::exists(dir_ / "new")) << "folders the save created go once empty";
    EXPECT_TRUE(fs::exists(dir_));
}

TEST_F(SaveCleanup, RollbackOfAFolderThatDidNotExistRemovesItWhenEmpty) {
    const fs::path textures = dir_ / "r.assets" / "textures";
    SaveRollback rollback;
    rollback.watchTextureCopies(textures);
    touch("r.assets/textures/0123456789abcdef-a.png");
    touch("r.assets/textures/fedcba9876543210-b.png");
    rollback.undo();
    EXPECT_FALSE(fs::exists(dir_ / "r.assets"));

    SaveRollback keeps;
    keeps.watchTextureCopies(dir_ / "s.assets" / "textures");
    touch("s.assets/textures/0123456789abcdef-a.png");
    touch("s.assets/mine.txt");
    keeps.undo();
    EXPECT_FALSE(fs::exists(dir_ / "s.assets" / "textures"));
    EXPECT_TRUE(fs::exists(dir_ / "s.assets" / "mine.txt")) << "a folder that is not empty stays";
}
