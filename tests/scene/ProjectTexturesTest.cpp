// Textures copied into the project, scenes appended to scenes, and files
// written before the optional 1.1 fields existed.
#include "ProjectTestSupport.h"

#include "lpv/scene/CornellBox.h"
#include "lpv/scene/ProjectTextures.h"
#include "lpv/scene/SceneMerge.h"

#include <regex>

namespace fs = std::filesystem;
using namespace lpv::scene;
using lpv::test::readFile;
using lpv::test::writeFile;

class ProjectTextures : public lpv::test::TempDirTest {
protected:
    ProjectTextures() : TempDirTest("lpv-textures-") {}
};

TEST_F(ProjectTextures, FilesAreCopiedOnceAndSlotsBecomeRelative) {
    fs::create_directories(dir_ / "source");
    writeFile(dir_ / "source/Brick Wall.BMP", "brick bytes");
    writeFile(dir_ / "source/copy of brick.bmp", "brick bytes"); // same content, other name
    writeFile(dir_ / "source/^detail.png", "detail bytes");
    Scene s;
    Material a, b;
    a.diffuseTexture = (dir_ / "source/Brick Wall.BMP").string();
    a.heightTexture = (dir_ / "source/Brick Wall.BMP").string(); // same file twice
    a.normalTexture = (dir_ / "source/^detail.png").string();
    b.diffuseTexture = (dir_ / "source/copy of brick.bmp").string();
    b.alphaTexture = "NOT THERE.BMP"; // missing: stays as it is
    s.materials = {a, b};

    const fs::path project = dir_ / "out/scene.lpvproj";
    fs::create_directories(project.parent_path());
    auto stats = copyTexturesIntoProject(s, project);
    ASSERT_TRUE(stats.has_value()) << stats.error().describe();
    EXPECT_EQ(stats->copied, 2u) << "brick (stored once for both names) and detail";
    EXPECT_EQ(stats->missing, 1u);
    ASSERT_EQ(stats->missingNames.size(), 1u);
    EXPECT_EQ(stats->missingNames[0], "NOT THERE.BMP");

    const Material& ca = s.materials[0];
    EXPECT_TRUE(ca.diffuseTexture.starts_with("scene.assets/textures/")) << ca.diffuseTexture;
    EXPECT_TRUE(ca.diffuseTexture.ends_with("-Brick Wall.BMP")) << ca.diffuseTexture;
    EXPECT_EQ(ca.heightTexture, ca.diffuseTexture);
    EXPECT_EQ(readFile(project.parent_path() / ca.diffuseTexture), "brick bytes");
    EXPECT_EQ(readFile(project.parent_path() / ca.normalTexture), "detail bytes");
    EXPECT_EQ(readFile(project.parent_path() / s.materials[1].diffuseTexture), "brick bytes");
    EXPECT_EQ(s.materials[1].alphaTexture, "NOT THERE.BMP");
    EXPECT_EQ(lpv::test::listFiles(project.parent_path() / "scene.assets/textures").size(), 2u);

    // Again: everything is already the project's own.
    const Scene before = s;
    auto again = copyTexturesIntoProject(s, project);
    ASSERT_TRUE(again.has_value());
    EXPECT_EQ(again->copied, 0u);
    EXPECT_TRUE(s == before);
}

TEST_F(ProjectTextures, TheProjectOpensWithoutTheSourceFolder) {
    fs::create_directories(dir_ / "source");
    writeFile(dir_ / "source/wall.png", "wall");
    Project p = makeCornellBoxProject();
    p.scene.materials[0].diffuseTexture = (dir_ / "source/wall.png").string();
    const fs::path file = dir_ / "moved/box.lpvproj";
    fs::create_directories(file.parent_path());
    ASSERT_TRUE(copyTexturesIntoProject(p.scene, file).has_value());
    ASSERT_TRUE(saveProject(p, file).has_value());
    fs::remove_all(dir_ / "source");
    fs::rename(dir_ / "moved", dir_ / "elsewhere");
    auto loaded = loadProject(dir_ / "elsewhere/box.lpvproj");
    ASSERT_TRUE(loaded.has_value()) << loaded.error().describe();
    EXPECT_EQ(readFile(dir_ / "elsewhere" / loaded->scene.materials[0].diffuseTexture), "wall");
}

TEST_F(ProjectTextures, UnreadableTextureIsAnErrorAndTheSceneIsUnchanged) {
    fs::create_directories(dir_ / "source/folder.png"); // a folder where a file is expected is "missing"
    writeFile(dir_ / "source/ok.png", "ok");
    Scene s;
    Material m;
    m.diffuseTexture = (dir_ / "source/ok.png").string();
    m.normalTexture = (dir_ / "source/folder.png").string();
    s.materials = {m};
    const Scene before = s;
    fs::create_directories(dir_ / "out");
    writeFile(dir_ / "out/p.assets", "a file where the assets folder should be");
    auto stats = copyTexturesIntoProject(s, dir_ / "out/p.lpvproj");
    ASSERT_FALSE(stats.has_value());
    EXPECT_TRUE(s == before);
}

TEST(SceneMerge, IndicesAreShifted) {
    Scene into = makeCornellBoxProject().scene;
    Scene from = makeCornellBoxProject().scene;
    from.objects[1].parent = 0;
    from.objects[0].lods = {{1, 5.0f}};
    const std::size_t meshes = into.meshes.size(), materials = into.materials.size(), objects = into.objects.size();
    const std::size_t triangles = into.triangleCount();
    appendScene(into, from);
    ASSERT_EQ(into.meshes.size(), 2 * meshes);
    EXPECT_EQ(into.materials.size(), 2 * materials);
    EXPECT_EQ(into.triangleCount(), 2 * triangles);
    EXPECT_EQ(into.objects[objects + 1].parent, int(objects));
    EXPECT_EQ(into.objects[objects].mesh, from.objects[0].mesh + int(meshes));
    EXPECT_EQ(into.objects[objects].lods[0].mesh, 1 + int(meshes));
    EXPECT_EQ(into.meshes[meshes].submeshes[0].materialIndex,
              from.meshes[0].submeshes[0].materialIndex + materials);
    EXPECT_EQ(into.lights.size(), 2 * from.lights.size());
}

class ProjectOptionalFields : public lpv::test::TempDirTest {
protected:
    ProjectOptionalFields() : TempDirTest("lpv-optional-") {}
};

TEST_F(ProjectOptionalFields, AVersionOneFileWithoutThemLoadsWithDefaults) {
    Project p = makeCornellBoxProject();
    const fs::path file = dir_ / "old.lpvproj";
    ASSERT_TRUE(saveProject(p, file).has_value());
    std::string json = readFile(file);
    // Strip the 1.1 fields as an older build would have written the file.
    for (const char* key : {"alphaTexture", "colorKey", "additive", "environmentTexture", "environmentRatio"}) {
        for (std::size_t at; (at = json.find(std::string("\"") + key + "\"")) != std::string::npos;) {
            const std::size_t lineStart = json.rfind('\n', at);
            const std::size_t lineEnd = json.find('\n', at);
            json.erase(lineStart, lineEnd - lineStart);
        }
    }
    ASSERT_EQ(json.find("colorKey"), std::string::npos);
    json = std::regex_replace(json, std::regex(",(\\s*\\})"), "$1"); // the comma before a removed last field
    writeFile(file, json);
    auto loaded = loadProject(file);
    ASSERT_TRUE(loaded.has_value()) << loaded.error().describe();
    EXPECT_FALSE(loaded->scene.materials[0].colorKey);
    EXPECT_TRUE(loaded->scene.materials[0].alphaTexture.empty());
}

TEST_F(ProjectOptionalFields, WrongTypesAreStillErrors) {
    Project p = makeCornellBoxProject();
    p.scene.objects[0].lods = {{0, 3.0f}};
    const fs::path file = dir_ / "p.lpvproj";
    ASSERT_TRUE(saveProject(p, file).has_value());
    std::string json = readFile(file);
    const std::size_t at = json.find("\"colorKey\": false");
    ASSERT_NE(at, std::string::npos) << json.substr(0, 400);
    json.replace(at, 17, "\"colorKey\": 3");
    writeFile(file, json);
    auto loaded = loadProject(file);
    ASSERT_FALSE(loaded.has_value());
    EXPECT_EQ(loaded.error().code, ErrorCode::TypeMismatch);
    EXPECT_NE(loaded.error().location.find("colorKey"), std::string::npos) << loaded.error().location;
}
