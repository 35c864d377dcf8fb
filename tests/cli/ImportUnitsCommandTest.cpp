// `lpv import --unit/--scale` as a user runs it (issue #41): the lengths of
// the project it writes, the usage errors, the size note, and a scene far
// from the origin. Scaled copies of ../shared/scenes are written into the
// test's temporary folder at run time, never committed.
#include "RunLpv.h"

#include "lpv/scene/Project.h"
#include "lpv/scene/WorldMatrices.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

using namespace lpv::test;
namespace fs = std::filesystem;

namespace {

fs::path scenes() {
    return fs::path(kSharedScenesDir);
}

lpv::scene::Scene loadScene(const fs::path& project) {
    auto loaded = lpv::scene::loadProject(project);
    EXPECT_TRUE(loaded.has_value()) << (loaded ? "" : loaded.error().describe());
    return loaded ? loaded->scene : lpv::scene::Scene{};
}

// The world bounds of objects [first, last) of a scene.
lpv::scene::Bounds boundsOfObjects(const lpv::scene::Scene& s, std::size_t first, std::size_t last) {
    lpv::scene::Bounds b;
    const std::vector<glm::mat4> world = lpv::scene::worldMatrices(s);
    for (std::size_t i = first; i < last; ++i) {
        const int m = s.objects[i].mesh;
        if (m < 0)
            continue;
        for (const glm::vec3& p : s.meshes[std::size_t(m)].positions)
            b.extend(glm::vec3(world[i] * glm::vec4(p, 1.0f)));
    }
    return b;
}

void expectScaled(const lpv::scene::Bounds& scaled, const lpv::scene::Bounds& metres, double s) {
    ASSERT_FALSE(metres.empty());
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(scaled.min[k], s * metres.min[k], 1e-6 * std::max(1.0, std::abs(double(metres.min[k]))))
            << k;
        EXPECT_NEAR(scaled.max[k], s * metres.max[k], 1e-6 * std::max(1.0, std::abs(double(metres.max[k]))))
            << k;
    }
}

// The Cornell box OBJ with every vertex times `factor`, beside a copy of its
// material library, in `dir`.
fs::path scaledCornell(const fs::path& dir, double factor) {
    const fs::path source = scenes() / "cornell";
    fs::copy_file(source / "CornellBox-Original.mtl", dir / "CornellBox-Original.mtl",
                  fs::copy_options::overwrite_existing);
    std::ifstream in(source / "CornellBox-Original.obj");
    const fs::path file = dir / "CornellBox-Scaled.obj";
    std::ofstream out(file);
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream words(line);
        std::string tag;
        double x = 0, y = 0, z = 0;
        if (words >> tag && tag == "v" && words >> x >> y >> z)
            out << "v " << x * factor << " " << y * factor << " " << z * factor << "\n";
        else
            out << line << "\n";
    }
    return file;
}

} // namespace

TEST(ImportUnitsCommand, UnitCmGivesAHundredthOfTheMetreImport) {
    const fs::path dir = freshTempDir("import-units", "cm");
    const fs::path obj = scenes() / "cornell/CornellBox-Original.obj";
    const RunResult metres = runLpv("import " + quoted(obj) + " -o " + quoted(dir / "m.lpvproj"));
    ASSERT_EQ(metres.exitCode, 0) << metres.output;
    const RunResult cm = runLpv("import " + quoted(obj) + " --unit cm -o " + quoted(dir / "cm.lpvproj"));
    ASSERT_EQ(cm.exitCode, 0) << cm.output;
    EXPECT_NE(cm.output.find("; lengths x0.01 into metres (--unit cm)"), std::string::npos) << cm.output;
    EXPECT_EQ(metres.output.find("lengths x"), std::string::npos) << metres.output;
    const lpv::scene::Scene m = loadScene(dir / "m.lpvproj");
    const lpv::scene::Scene c = loadScene(dir / "cm.lpvproj");
    expectScaled(c.worldBounds(), m.worldBounds(), 0.01);
    // The area light the ceiling panel became shrinks with it.
    ASSERT_EQ(m.lights.size(), c.lights.size());
    for (std::size_t i = 0; i < m.lights.size(); ++i) {
        EXPECT_NEAR(c.lights[i].position.y, 0.01f * m.lights[i].position.y, 1e-6f);
        EXPECT_NEAR(c.lights[i].size.x, 0.01f * m.lights[i].size.x, 1e-6f);
        EXPECT_EQ(c.lights[i].direction, m.lights[i].direction);
        EXPECT_EQ(c.lights[i].intensity, m.lights[i].intensity);
    }
    // --scale 0.01 is the same import.
    const RunResult scale = runLpv("import " + quoted(obj) + " --scale 0.01 -o " + quoted(dir / "s.lpvproj"));
    ASSERT_EQ(scale.exitCode, 0) << scale.output;
    EXPECT_NE(scale.output.find("lengths x0.01 into metres (--scale 0.01)"), std::string::npos)
        << scale.output;
    const lpv::scene::Scene s = loadScene(dir / "s.lpvproj");
    EXPECT_EQ(s.worldBounds().min, c.worldBounds().min);
    EXPECT_EQ(s.worldBounds().max, c.worldBounds().max);
    fs::remove_all(dir);
}

TEST(ImportUnitsCommand, AddingToAProjectScalesOnlyTheNewPart) {
    const fs::path dir = freshTempDir("import-units", "add");
    const fs::path obj = scenes() / "cornell/CornellBox-Original.obj";
    const fs::path project = dir / "p.lpvproj";
    ASSERT_EQ(runLpv("import " + quoted(obj) + " -o " + quoted(project)).exitCode, 0);
    const lpv::scene::Scene first = loadScene(project);
    const RunResult add = runLpv("import " + quoted(obj) + " --unit mm -o " + quoted(project));
    ASSERT_EQ(add.exitCode, 0) << add.output;
    const lpv::scene::Scene both = loadScene(project);
    const std::size_t n = first.objects.size();
    ASSERT_EQ(both.objects.size(), 2 * n);
    const lpv::scene::Bounds old = boundsOfObjects(both, 0, n);
    EXPECT_EQ(old.min, boundsOfObjects(first, 0, n).min);
    EXPECT_EQ(old.max, boundsOfObjects(first, 0, n).max);
    expectScaled(boundsOfObjects(both, n, 2 * n), old, 0.001);
    fs::remove_all(dir);
}

TEST(ImportUnitsCommand, UnitAndScaleTogetherOrBadValuesAreUsageErrors) {
    const fs::path dir = freshTempDir("import-units", "usage");
    const std::string obj = quoted(scenes() / "cornell/CornellBox-Original.obj");
    const std::string out = " -o " + quoted(dir / "x.lpvproj");
    const RunResult both = runLpv("import " + obj + " --unit cm --scale 0.01" + out);
    EXPECT_EQ(both.exitCode, 2) << both.output;
    EXPECT_NE(both.output.find("--unit and --scale"), std::string::npos) << both.output;
    const RunResult km = runLpv("import " + obj + " --unit km" + out);
    EXPECT_EQ(km.exitCode, 2) << km.output;
    EXPECT_NE(km.output.find("--unit: 'km' is not one of mm, cm, m, in, ft"), std::string::npos) << km.output;
    for (const char* bad : {"0", "-1", "nan", "inf", "1e400", "abc", "2x", "''"}) {
        const RunResult r = runLpv("import " + obj + " --scale " + bad + out);
        EXPECT_EQ(r.exitCode, 2) << bad << ": " << r.output;
        EXPECT_NE(r.output.find("is not a finite number above 0"), std::string::npos)
            << bad << ": " << r.output;
    }
    EXPECT_EQ(runLpv("import " + obj + " --scale" + out).exitCode, 2);
    EXPECT_FALSE(fs::exists(dir / "x.lpvproj"));
    fs::remove_all(dir);
}

TEST(ImportUnitsCommand, SizeNoteForTheCornellBoxInCentimetres) {
    const fs::path dir = freshTempDir("import-units", "note");
    const fs::path obj = scaledCornell(dir, 100.0);
    const RunResult r = runLpv("import " + quoted(obj) + " -o " + quoted(dir / "big.lpvproj"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(
        r.output.find("  the scene is 203 units across: if these are centimetres, import with --unit cm"),
        std::string::npos)
        << r.output;
    // Following the advice gives the box in metres again, without the note.
    const RunResult cm = runLpv("import " + quoted(obj) + " --unit cm -o " + quoted(dir / "cm.lpvproj"));
    ASSERT_EQ(cm.exitCode, 0) << cm.output;
    EXPECT_EQ(cm.output.find("units across"), std::string::npos) << cm.output;
    const lpv::scene::Bounds b = loadScene(dir / "cm.lpvproj").worldBounds();
    EXPECT_NEAR(b.max.y, 1.99f, 1e-5f);
    // The original box gets no note.
    const RunResult metres = runLpv("import " + quoted(scenes() / "cornell/CornellBox-Original.obj") +
                                    " -o " + quoted(dir / "m.lpvproj"));
    EXPECT_EQ(metres.output.find("units across"), std::string::npos) << metres.output;
    fs::remove_all(dir);
}

// A 2 m box 100 km out along x: its mesh is stored around its centre and the
// offset lives in the object's translation, so the world stays in place.
TEST(ImportUnitsCommand, AFarBoxIsRecentred) {
    const fs::path dir = freshTempDir("import-units", "far");
    const fs::path obj = dir / "far.obj";
    {
        std::ofstream out(obj);
        for (int i = 0; i < 8; ++i)
            out << "v " << (i & 1 ? 100001 : 99999) << " " << (i & 2 ? 2 : 0) << " " << (i & 4 ? 1 : -1)
                << "\n";
        out << "f 1 2 4 3\nf 5 7 8 6\nf 1 5 6 2\nf 3 4 8 7\nf 1 3 7 5\nf 2 6 8 4\n";
    }
    const RunResult r = runLpv("import " + quoted(obj) + " -o " + quoted(dir / "far.lpvproj"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("1 mesh far from the origin"), std::string::npos) << r.output;
    const lpv::scene::Scene s = loadScene(dir / "far.lpvproj");
    const double rounding = 4.0 * 1e5 * std::ldexp(1.0, -23);
    const lpv::scene::Bounds b = s.worldBounds();
    EXPECT_NEAR(b.min.x, 99999.0, rounding);
    EXPECT_NEAR(b.max.x, 100001.0, rounding);
    EXPECT_NEAR(b.min.z, -1.0, 1e-6);
    for (const auto& mesh : s.meshes)
        for (const glm::vec3& p : mesh.positions)
            EXPECT_LE(glm::length(p), 2.0f);
    fs::remove_all(dir);
}

TEST(ImportUnitsCommand, HelpNamesTheOptions) {
    const RunResult r = runLpv("import --help");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("--unit mm|cm|m|in|ft"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("--scale S"), std::string::npos) << r.output;
}
