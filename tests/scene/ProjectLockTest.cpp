// Issue #42: saves of one project take turns under its lock, a save refuses
// to replace a project another process wrote since its caller loaded it, and
// a save never writes what the loader would refuse.
#include "ProjectTestSupport.h"

#include "lpv/scene/CameraPathFile.h"
#include "lpv/scene/ProjectLimits.h"
#include "lpv/scene/ProjectLock.h"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

using namespace lpv::scene;
using namespace lpv::test;
namespace fs = std::filesystem;
using std::chrono::milliseconds;

namespace {

// A project of one triangle whose corner sits at `x`, so two saves differ
// in their mesh asset (and so in the asset's file name).
Project triangleProject(float x) {
    Project p;
    p.name = "p";
    Material m;
    m.name = "m";
    p.scene.materials = {m};
    Mesh mesh;
    mesh.name = "tri";
    mesh.positions = {{x, 0, 0}, {x + 1, 0, 0}, {x, 1, 0}};
    mesh.normals.assign(3, {0, 0, 1});
    mesh.uvs = {{0, 0}, {1, 0}, {0, 1}};
    mesh.indices = {0, 1, 2};
    mesh.submeshes = {{0, 3, 0}};
    p.scene.meshes = {mesh};
    p.scene.objects = {Object{"tri", 0, -1, {}, true, {}}};
    return p;
}

class ProjectLockTest : public TempDirTest {
  protected:
    ProjectLockTest() : TempDirTest("lpv-lock-") {}
};

} // namespace

TEST_F(ProjectLockTest, TheLockFileSitsBesideTheProjectAndGoesWithTheLock) {
    const fs::path file = dir_ / "Scene.lpvproj";
    EXPECT_EQ(projectLockFile(file), dir_ / ".Scene.lpvproj.lock");
    {
        auto lock = ProjectLock::acquire(file);
        ASSERT_TRUE(lock) << lock.error().describe();
        EXPECT_TRUE(fs::exists(dir_ / ".Scene.lpvproj.lock"));
    }
    EXPECT_FALSE(fs::exists(dir_ / ".Scene.lpvproj.lock"));
    ASSERT_TRUE(saveProject(triangleProject(0), file));
    EXPECT_EQ(listFiles(dir_).count(".Scene.lpvproj.lock"), 0u);
}

TEST_F(ProjectLockTest, ASecondWriterWaitsABoundedTimeThenSaysWhy) {
    const fs::path file = dir_ / "p.lpvproj";
    auto held = ProjectLock::acquire(file);
    ASSERT_TRUE(held);
    const auto start = std::chrono::steady_clock::now();
    auto second = ProjectLock::acquire(file, milliseconds(200));
    const auto waited = std::chrono::steady_clock::now() - start;
    ASSERT_FALSE(second);
    EXPECT_EQ(second.error().describe(),
              file.string() + ": another process is saving this project (it holds " +
                  (dir_ / ".p.lpvproj.lock").string() +
                  "); waited 200 ms, nothing was saved; try again when it has finished");
    EXPECT_GE(waited, milliseconds(200));
    EXPECT_LT(waited, milliseconds(2000));

    SaveOptions options;
    options.lockWait = milliseconds(100);
    auto saved = saveProject(triangleProject(0), file, options);
    ASSERT_FALSE(saved);
    EXPECT_NE(saved.error().message.find("another process is saving this project"), std::string::npos);
    EXPECT_FALSE(fs::exists(file));
}

TEST_F(ProjectLockTest, AWaitingWriterGetsTheLockWhenTheHolderLetsGo) {
    const fs::path file = dir_ / "p.lpvproj";
    auto held = std::make_optional(*ProjectLock::acquire(file));
    std::thread releaser([&] {
        std::this_thread::sleep_for(milliseconds(100));
        held.reset();
    });
    auto second = ProjectLock::acquire(file, milliseconds(5000));
    releaser.join();
    EXPECT_TRUE(second) << second.error().describe();
}

TEST_F(ProjectLockTest, ASaveRefusesToReplaceAProjectWrittenSinceItsCallerFoundIt) {
    const fs::path file = dir_ / "p.lpvproj";
    const ProjectFileIdentity absent = projectFileIdentity(file);
    EXPECT_FALSE(absent.exists);
    ASSERT_TRUE(saveProject(triangleProject(1), file)); // the other process
    SaveOptions options;
    options.unchangedSince = absent;
    options.operation = "import";
    auto saved = saveProject(triangleProject(2), file, options);
    ASSERT_FALSE(saved);
    EXPECT_EQ(saved.error().describe(),
              file.string() + ": the project was written by another process while this import ran; nothing "
                              "was saved, so that process's work stays (run the import again)");
    auto loaded = loadProject(file);
    ASSERT_TRUE(loaded) << loaded.error().describe();
    EXPECT_EQ(loaded->scene.meshes[0].positions[0].x, 1.0f);

    // Unchanged since it was found: the save goes through.
    options.unchangedSince = projectFileIdentity(file);
    EXPECT_TRUE(saveProject(triangleProject(3), file, options));
    EXPECT_NE(projectFileIdentity(file), *options.unchangedSince);
}

// Before the lock, one save's clean-up deleted the mesh assets the other's
// project file named, and the project did not load.
TEST_F(ProjectLockTest, ConcurrentSavesAlwaysLeaveAProjectThatLoads) {
    const fs::path file = dir_ / "p.lpvproj";
    for (int round = 0; round < 20; ++round) {
        std::thread other([&] { EXPECT_TRUE(saveProject(triangleProject(float(2 * round)), file)); });
        EXPECT_TRUE(saveProject(triangleProject(float(2 * round + 1)), file));
        other.join();
        auto loaded = loadProject(file);
        ASSERT_TRUE(loaded) << "round " << round << ": " << loaded.error().describe();
        EXPECT_EQ(listFiles(dir_ / "p.assets" / "meshes").size(), 1u) << "round " << round;
    }
}

TEST(ProjectLimits, AWriteTheReaderWouldRefuseIsRefusedFirst) {
    EXPECT_TRUE(checkWriteFits(64, ReadLimit{64, "project file"}, "p.lpvproj"));
    auto refused = checkWriteFits(std::uint64_t{158} << 20,
                                  ReadLimit{std::uint64_t{64} << 20, "project file"}, "p.lpvproj");
    ASSERT_FALSE(refused);
    EXPECT_EQ(refused.error().describe(),
              "p.lpvproj: the project file would be 158.0 MiB, more than a project "
              "file can be (64.0 MiB, the most the loader reads); nothing was written");
}

TEST_F(ProjectLockTest, MoreMaterialsThanAProjectHoldsAreRefusedBeforeWriting) {
    Project p = triangleProject(0);
    p.scene.materials.resize(kMaxMaterials + 1, p.scene.materials[0]);
    const fs::path file = dir_ / "p.lpvproj";
    auto saved = saveProject(p, file);
    ASSERT_FALSE(saved);
    EXPECT_EQ(saved.error().describe(),
              file.string() + ": materials: 16385 materials, more than a project can hold (16384)");
    EXPECT_TRUE(listFiles(dir_).empty());
}

// The loader bounds a mesh asset by its counts (48 bytes a vertex, 24 a
// triangle, 1 MiB more): a mesh whose name alone is longer would be saved
// and then refused.
TEST_F(ProjectLockTest, AMeshAssetTheLoaderWouldRefuseIsNotWritten) {
    Project p = triangleProject(0);
    p.scene.meshes[0].name = std::string((std::size_t{1} << 20) + 4096, 'n');
    p.scene.objects[0].name = "tri";
    const fs::path file = dir_ / "p.lpvproj";
    auto saved = saveProject(p, file);
    ASSERT_FALSE(saved);
    EXPECT_EQ(saved.error().location, "meshes[0]");
    EXPECT_NE(saved.error().message.find("more than a mesh asset of 3 vertices and 1 triangles can be"),
              std::string::npos)
        << saved.error().message;
    EXPECT_TRUE(listFiles(dir_).empty());
}
