// Names that are not UTF-8 (Assimp's own OBJ/box_mat_with_spaces.obj and
// regr01.obj, written in a Windows code page) are read as Windows-1250 with
// a warning, so the import saves instead of failing on one byte (issue #42).
#include "lpv/importers/Importer.h"
#include "lpv/scene/Project.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace lpv;

TEST(LegacyNames, ALatin1MaterialNameIsReadAsWindows1250AndTheProjectSavesAndLoads) {
    const fs::path dir = fs::temp_directory_path() / ("lpv-legacy-names-" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::ofstream(dir / "box.mtl") << "newmtl Mat\xe9riau\nKd 0.5 0.5 0.5\n";
    std::ofstream(dir / "box.obj") << "mtllib box.mtl\no Caf\xe9\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                      "usemtl Mat\xe9riau\nf 1 2 3\n";
    auto imported = importers::importScene(dir / "box.obj");
    ASSERT_TRUE(imported.has_value()) << imported.error().describe();
    bool found = false;
    for (const auto& m : imported->scene.materials)
        found |= m.name == "Mat\xc3\xa9riau"; // é in UTF-8
    EXPECT_TRUE(found);
    bool warned = false;
    for (const auto& w : imported->warnings)
        warned |= w.find("were not UTF-8 and were read as Windows-1250") != std::string::npos;
    EXPECT_TRUE(warned);

    scene::Project project;
    project.name = "box";
    project.scene = imported->scene;
    const fs::path file = dir / "box.lpvproj";
    const auto saved = scene::saveProject(project, file);
    ASSERT_TRUE(saved.has_value()) << saved.error().describe();
    const auto loaded = scene::loadProject(file);
    ASSERT_TRUE(loaded.has_value()) << loaded.error().describe();
    EXPECT_EQ(loaded->scene.materials, project.scene.materials);
    fs::remove_all(dir);
}
