// Units at import (issue #41): scene::scaleSceneLengths, the unit names of
// `lpv import --unit`, the size note, recentring of meshes far from their
// origin, and the units formats state (FBX UnitScaleFactor, Collada <unit>),
// through importScene on real files. docs/importers.md, "Units (issue #41)".
#include "lpv/importers/ImportUnits.h"
#include "TestPaths.h"
#include "lpv/importers/Importer.h"
#include "lpv/scene/SceneScale.h"
#include "lpv/scene/WorldMatrices.h"

#include <gtest/gtest.h>

#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <unistd.h>

using namespace lpv;
namespace fs = std::filesystem;

namespace {

fs::path scenes() {
    return fs::path(test::kSharedScenesDir);
}

fs::path tempDir(const std::string& name) {
    fs::path p = fs::temp_directory_path() / ("lpv-units-" + name + "-" + std::to_string(::getpid()));
    fs::remove_all(p);
    fs::create_directories(p);
    return p;
}

// A box of the given size, centred on `centre`, in mesh coordinates.
scene::Mesh box(const glm::vec3& centre, float size, const std::string& name = "box") {
    scene::Mesh m;
    m.name = name;
    for (int i = 0; i < 8; ++i)
        m.positions.push_back(centre +
                              0.5f * size * glm::vec3(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1));
    m.indices = {0, 1, 3, 0, 3, 2, 4, 6, 7, 4, 7, 5, 0, 4, 5, 0, 5, 1,
                 2, 3, 7, 2, 7, 6, 0, 2, 6, 0, 6, 4, 1, 5, 7, 1, 7, 3};
    m.submeshes.push_back({0, std::uint32_t(m.indices.size()), 0});
    scene::computeFlatAwareNormals(m);
    return m;
}

// Every vertex of every object's main mesh and LODs in world space, in double.
std::vector<glm::dvec3> worldVertices(const scene::Scene& s) {
    std::vector<glm::dvec3> out;
    const std::vector<glm::mat4> world = scene::worldMatrices(s);
    for (std::size_t i = 0; i < s.objects.size(); ++i) {
        std::vector<int> meshes{s.objects[i].mesh};
        for (const auto& lod : s.objects[i].lods)
            meshes.push_back(lod.mesh);
        for (int m : meshes)
            if (m >= 0)
                for (const glm::vec3& p : s.meshes[std::size_t(m)].positions)
                    out.push_back(glm::dvec3(world[i] * glm::vec4(p, 1.0f)));
    }
    return out;
}

// A scene with a parent chain (rotated, scaled), a shared mesh, a LOD, every
// light kind, a camera and a camera path.
scene::Scene richScene() {
    scene::Scene s;
    s.materials.emplace_back();
    s.meshes.push_back(box({0.5f, 1.0f, -0.25f}, 2.0f, "main"));
    s.meshes.push_back(box({0.5f, 1.0f, -0.25f}, 2.5f, "lod"));
    scene::Object root;
    root.name = "root";
    root.mesh = 0;
    root.transform.translation = {3.0f, -1.0f, 2.0f};
    root.transform.rotation = glm::angleAxis(0.7f, glm::normalize(glm::vec3(1, 2, 3)));
    root.transform.scale = {2.0f, 0.5f, 1.5f};
    root.lods.push_back({1, 25.0f});
    s.objects.push_back(root);
    scene::Object child;
    child.name = "child";
    child.mesh = 0;
    child.parent = 0;
    child.transform.translation = {-1.0f, 4.0f, 0.5f};
    child.transform.rotation = glm::angleAxis(-1.1f, glm::vec3(0, 1, 0));
    s.objects.push_back(child);
    scene::Light sun;
    sun.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
    sun.color = {1.0f, 0.9f, 0.8f};
    sun.intensity = 3.0f;
    s.lights.push_back(sun);
    scene::Light spot;
    spot.type = scene::LightType::Spot;
    spot.position = {1.0f, 5.0f, -2.0f};
    spot.direction = glm::normalize(glm::vec3(0.0f, -1.0f, 0.1f));
    spot.range = 12.0f;
    spot.outerConeAngle = 0.6f;
    s.lights.push_back(spot);
    scene::Light area;
    area.type = scene::LightType::Area;
    area.position = {0.0f, 1.98f, 0.0f};
    area.size = {0.5f, 0.25f};
    area.radius = 0.3f;
    area.intensity = 17.0f;
    s.lights.push_back(area);
    scene::Camera cam;
    cam.position = {0.0f, 1.0f, 6.0f};
    cam.target = {0.0f, 1.0f, 0.0f};
    cam.nearPlane = 0.1f;
    cam.farPlane = 100.0f;
    s.cameras.push_back(cam);
    scene::CameraPath path;
    path.name = "dolly";
    path.keyframes.push_back({0.0f, {0.0f, 1.0f, 6.0f}, glm::angleAxis(0.2f, glm::vec3(0, 1, 0)), 0.8f});
    path.keyframes.push_back({2.0f, {1.0f, 1.5f, 4.0f}, glm::angleAxis(0.4f, glm::vec3(0, 1, 0)), 0.7f});
    s.cameraPaths.push_back(path);
    return s;
}

double largestSide(const scene::Bounds& b) {
    const glm::vec3 size = b.size();
    return std::max({size.x, size.y, size.z});
}

} // namespace

// ---- scaleSceneLengths -------------------------------------------------------

TEST(SceneScale, WorldBoundsScaleByExactlyAPowerOfTwo) {
    const scene::Scene before = richScene();
    scene::Scene after = before;
    scene::scaleSceneLengths(after, 2.0);
    const scene::Bounds b0 = before.worldBounds(), b1 = after.worldBounds();
    ASSERT_FALSE(b0.empty());
    EXPECT_EQ(b1.min, 2.0f * b0.min);
    EXPECT_EQ(b1.max, 2.0f * b0.max);
    // Every world vertex, the LOD's too, moves to twice where it was.
    const auto v0 = worldVertices(before), v1 = worldVertices(after);
    ASSERT_EQ(v0.size(), v1.size());
    for (std::size_t i = 0; i < v0.size(); ++i)
        EXPECT_LE(glm::length(v1[i] - 2.0 * v0[i]), 1e-5 * glm::length(v0[i])) << i;
}

TEST(SceneScale, EveryLengthScalesAndNothingElseChanges) {
    const scene::Scene before = richScene();
    scene::Scene after = before;
    const double s = 0.01;
    scene::scaleSceneLengths(after, s);
    const scene::Bounds b0 = before.worldBounds(), b1 = after.worldBounds();
    EXPECT_NEAR(largestSide(b1), s * largestSide(b0), 1e-6 * largestSide(b0));
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(b1.min[k], s * b0.min[k], 1e-6 * std::abs(b0.min[k]) + 1e-9);
        EXPECT_NEAR(b1.max[k], s * b0.max[k], 1e-6 * std::abs(b0.max[k]) + 1e-9);
    }
    for (std::size_t i = 0; i < before.objects.size(); ++i) {
        const auto& o0 = before.objects[i].transform;
        const auto& o1 = after.objects[i].transform;
        EXPECT_EQ(o1.translation, glm::vec3(glm::dvec3(o0.translation) * s));
        EXPECT_EQ(o1.rotation, o0.rotation);
        EXPECT_EQ(o1.scale, o0.scale);
    }
    EXPECT_FLOAT_EQ(after.objects[0].lods[0].distance, 0.25f);
    for (std::size_t m = 0; m < before.meshes.size(); ++m) {
        EXPECT_EQ(after.meshes[m].normals, before.meshes[m].normals);
        EXPECT_EQ(after.meshes[m].indices, before.meshes[m].indices);
    }
    for (std::size_t i = 0; i < before.lights.size(); ++i) {
        const auto& l0 = before.lights[i];
        const auto& l1 = after.lights[i];
        EXPECT_EQ(l1.direction, l0.direction);
        EXPECT_EQ(l1.tangent, l0.tangent);
        EXPECT_EQ(l1.color, l0.color);
        EXPECT_EQ(l1.intensity, l0.intensity);
        EXPECT_EQ(l1.outerConeAngle, l0.outerConeAngle);
        EXPECT_EQ(l1.position, glm::vec3(glm::dvec3(l0.position) * s));
        EXPECT_FLOAT_EQ(l1.range, float(l0.range * s));
        EXPECT_FLOAT_EQ(l1.size.x, float(l0.size.x * s));
        EXPECT_FLOAT_EQ(l1.radius, float(l0.radius * s));
    }
    const auto& c0 = before.cameras[0];
    const auto& c1 = after.cameras[0];
    EXPECT_EQ(c1.up, c0.up);
    EXPECT_EQ(c1.fovY, c0.fovY);
    EXPECT_FLOAT_EQ(c1.position.z, 0.06f);
    EXPECT_FLOAT_EQ(c1.target.y, 0.01f);
    EXPECT_FLOAT_EQ(c1.nearPlane, 0.001f);
    EXPECT_FLOAT_EQ(c1.farPlane, 1.0f);
    const auto& k0 = before.cameraPaths[0].keyframes[1];
    const auto& k1 = after.cameraPaths[0].keyframes[1];
    EXPECT_EQ(k1.orientation, k0.orientation);
    EXPECT_EQ(k1.time, k0.time);
    EXPECT_EQ(k1.fovY, k0.fovY);
    EXPECT_FLOAT_EQ(k1.position.z, 0.04f);
    EXPECT_EQ(after.sky, before.sky);
    EXPECT_EQ(after.materials, before.materials);
}

TEST(SceneScale, CameraPlanesTheFileDidNotSetStay) {
    scene::Scene s = richScene();
    scene::scaleSceneLengths(s, 0.01, {.cameraPlanes = false});
    EXPECT_EQ(s.cameras[0].nearPlane, 0.1f);
    EXPECT_EQ(s.cameras[0].farPlane, 100.0f);
    EXPECT_FLOAT_EQ(s.cameras[0].position.z, 0.06f);
}

// ---- unit names and the size note ------------------------------------------

TEST(ImportUnits, UnitNames) {
    EXPECT_EQ(importers::metresPerUnit("mm"), 0.001);
    EXPECT_EQ(importers::metresPerUnit("cm"), 0.01);
    EXPECT_EQ(importers::metresPerUnit("m"), 1.0);
    EXPECT_EQ(importers::metresPerUnit("in"), 0.0254);
    EXPECT_EQ(importers::metresPerUnit("ft"), 0.3048);
    EXPECT_FALSE(importers::metresPerUnit("km"));
    EXPECT_FALSE(importers::metresPerUnit("CM"));
    EXPECT_FALSE(importers::metresPerUnit(""));
}

namespace {
scene::Bounds sized(glm::vec3 size) {
    scene::Bounds b;
    b.extend(glm::vec3(5.0f));
    b.extend(glm::vec3(5.0f) + size);
    return b;
}
} // namespace

TEST(ImportUnits, SizeNoteSuggestsAUnitOnlyWhenTheSizeCallsForIt) {
    using importers::sizeNote;
    using importers::UnitKnowledge;
    // Metre-sized scenes: the Cornell box, Sponza, a flat 600 m terrain.
    EXPECT_FALSE(sizeNote(sized({2.0f, 2.0f, 2.0f}), UnitKnowledge::Assumed));
    EXPECT_FALSE(sizeNote(sized({35.0f, 16.0f, 15.0f}), UnitKnowledge::Assumed));
    EXPECT_FALSE(sizeNote(sized({600.0f, 40.0f, 600.0f}), UnitKnowledge::Assumed));
    EXPECT_FALSE(sizeNote(sized({0.06f, 0.01f, 0.02f}), UnitKnowledge::Assumed));
    // The Cornell box in centimetres: 200 units along every side.
    auto cube = sizeNote(sized({202.0f, 199.0f, 203.0f}), UnitKnowledge::Assumed);
    ASSERT_TRUE(cube);
    EXPECT_EQ(*cube, "the scene is 203 units across: if these are centimetres, import with --unit cm "
                     "(metres were assumed)");
    auto sponzaCm = sizeNote(sized({3800.0f, 1500.0f, 2200.0f}), UnitKnowledge::Assumed);
    ASSERT_TRUE(sponzaCm);
    EXPECT_NE(sponzaCm->find("3,800 units across"), std::string::npos) << *sponzaCm;
    EXPECT_NE(sponzaCm->find("--unit cm"), std::string::npos) << *sponzaCm;
    auto mm = sizeNote(sized({2.0e6f, 10.0f, 10.0f}), UnitKnowledge::Assumed);
    ASSERT_TRUE(mm);
    EXPECT_NE(mm->find("2,000,000 units across"), std::string::npos) << *mm;
    EXPECT_NE(mm->find("--unit mm"), std::string::npos) << *mm;
    auto tiny = sizeNote(sized({0.02f, 0.01f, 0.01f}), UnitKnowledge::Assumed);
    ASSERT_TRUE(tiny);
    EXPECT_NE(tiny->find("0.02 units across"), std::string::npos) << *tiny;
    EXPECT_NE(tiny->find("--scale"), std::string::npos) << *tiny;
    // A stated unit is believed unless absurd; the user's always.
    EXPECT_FALSE(sizeNote(sized({3800.0f, 1500.0f, 2200.0f}), UnitKnowledge::StatedByFile));
    EXPECT_FALSE(sizeNote(sized({0.02f, 0.01f, 0.01f}), UnitKnowledge::StatedByFile));
    EXPECT_TRUE(sizeNote(sized({2.0e6f, 10.0f, 10.0f}), UnitKnowledge::StatedByFile));
    EXPECT_TRUE(sizeNote(sized({0.0005f, 0.0001f, 0.0001f}), UnitKnowledge::StatedByFile));
    EXPECT_FALSE(sizeNote(sized({2.0e6f, 10.0f, 10.0f}), UnitKnowledge::GivenByUser));
    EXPECT_FALSE(sizeNote(scene::Bounds{}, UnitKnowledge::Assumed));
}

// ---- recentring --------------------------------------------------------------

// Float rounding of a world position near `magnitude`: a few units in the
// last place of the largest coordinate.
double floatRounding(double magnitude) {
    return 4.0 * magnitude * std::ldexp(1.0, -23);
}

TEST(Recentre, TwoMetreBoxAHundredKilometresOutKeepsItsWorldPositions) {
    scene::Scene s;
    s.materials.emplace_back();
    s.meshes.push_back(box({1.0e5f, 1.0f, 0.0f}, 2.0f));
    scene::Object o;
    o.mesh = 0;
    s.objects.push_back(o);
    const auto before = worldVertices(s);
    const importers::RecentreStats stats = importers::recentreFarMeshes(s);
    EXPECT_EQ(stats.meshes, 1u);
    EXPECT_NEAR(stats.farthest, 1.0e5, 1.0);
    const auto after = worldVertices(s);
    ASSERT_EQ(before.size(), after.size());
    for (std::size_t i = 0; i < before.size(); ++i)
        EXPECT_LE(glm::length(after[i] - before[i]), floatRounding(1.0e5)) << i;
    // The vertices now sit within the box's size of 0; the offset is in the translation.
    for (const glm::vec3& p : s.meshes[0].positions)
        EXPECT_LE(glm::length(p), 2.0f) << p.x << " " << p.y << " " << p.z;
    EXPECT_NEAR(s.objects[0].transform.translation.x, 1.0e5, 1e-3);
    // Relative to each other, the corners are exact again: 2 m apart.
    const scene::Bounds local = s.meshes[0].computeBounds();
    EXPECT_EQ(local.size(), glm::vec3(2.0f));
}

TEST(Recentre, SharedMeshesLodsParentsAndChildrenStayInPlace) {
    scene::Scene s;
    s.materials.emplace_back();
    const glm::vec3 far(-3.0e4f, 2.0e4f, 8.0e4f);
    s.meshes.push_back(box(far, 2.0f, "shared"));
    s.meshes.push_back(box(far + glm::vec3(0.5f), 3.0f, "lod"));
    s.meshes.push_back(box({0.0f, 3.0f, 0.0f}, 2.0f, "near"));
    s.meshes.push_back(box(far, 2.0f, "unused"));
    scene::Object parent;
    parent.name = "parent";
    parent.mesh = 0;
    parent.lods.push_back({1, 50.0f});
    parent.transform.translation = {10.0f, 0.0f, -5.0f};
    parent.transform.rotation = glm::angleAxis(0.9f, glm::normalize(glm::vec3(1, 1, 0)));
    parent.transform.scale = {1.5f, 2.0f, 0.75f};
    s.objects.push_back(parent);
    scene::Object child; // sits in the parent's frame and draws a mesh near its own origin
    child.name = "child";
    child.mesh = 2;
    child.parent = 0;
    child.transform.translation = far;
    s.objects.push_back(child);
    scene::Object other; // draws the shared mesh elsewhere
    other.name = "other";
    other.mesh = 0;
    other.transform.translation = {0.0f, 100.0f, 0.0f};
    other.transform.rotation = glm::angleAxis(2.0f, glm::vec3(0, 0, 1));
    s.objects.push_back(other);
    const auto before = worldVertices(s);
    const scene::Mesh unused = s.meshes[3];
    const importers::RecentreStats stats = importers::recentreFarMeshes(s);
    EXPECT_EQ(stats.meshes, 2u); // shared and lod; near is near, unused is left alone
    EXPECT_EQ(s.meshes[3], unused);
    const auto after = worldVertices(s);
    ASSERT_EQ(before.size(), after.size());
    double magnitude = 0.0;
    for (const auto& p : before)
        magnitude = std::max(magnitude, glm::length(p));
    for (std::size_t i = 0; i < before.size(); ++i)
        EXPECT_LE(glm::length(after[i] - before[i]), floatRounding(magnitude)) << i;
    // The LOD moved by the same offset as the main mesh (the centre of both):
    // their centres still differ by 0.5 per axis, the main one at -0.5.
    const glm::vec3 mainCentre = s.meshes[0].computeBounds().center();
    const glm::vec3 lodCentre = s.meshes[1].computeBounds().center();
    EXPECT_LE(glm::length(mainCentre + glm::vec3(0.5f)), 1e-2f);
    EXPECT_LE(glm::length(lodCentre - mainCentre - glm::vec3(0.5f)), 1e-2f);
    // The near mesh kept its vertices.
    EXPECT_NEAR(s.meshes[2].computeBounds().center().y, 3.0f, 1e-6f);
}

TEST(Recentre, MeshesNearTheirOriginStay) {
    scene::Scene s = richScene();
    s.meshes.push_back(box({10.0f, 0.0f, 0.0f}, 2.0f)); // 10 m out, 1.7 m radius: near
    scene::Object o;
    o.mesh = 2;
    s.objects.push_back(o);
    const scene::Scene before = s;
    EXPECT_EQ(importers::recentreFarMeshes(s).meshes, 0u);
    EXPECT_EQ(s, before);
}

// ---- through importScene -------------------------------------------------------

TEST(ImportUnits, UnitCmGivesAHundredthOfTheMetreImport) {
    const fs::path file = scenes() / "cornell/CornellBox-Original.obj";
    auto metres = importers::importScene(file);
    ASSERT_TRUE(metres) << metres.error().describe();
    importers::ImportOptions options;
    options.metresPerUnit = 0.01;
    options.unitSource = "--unit cm";
    auto cm = importers::importScene(file, options);
    ASSERT_TRUE(cm) << cm.error().describe();
    const scene::Bounds b0 = metres->scene.worldBounds(), b1 = cm->scene.worldBounds();
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(b1.min[k], 0.01 * b0.min[k], 1e-6);
        EXPECT_NEAR(b1.max[k], 0.01 * b0.max[k], 1e-6);
    }
    EXPECT_EQ(cm->stats.lengthScale.factor, 0.01);
    EXPECT_EQ(cm->stats.lengthScale.source, "--unit cm");
    EXPECT_EQ(metres->stats.lengthScale.factor, 1.0);
    EXPECT_EQ(metres->stats.lengthScale.knew, importers::UnitKnowledge::Assumed);
    // The emissive ceiling panel became an area light either way, 100 times smaller.
    ASSERT_EQ(metres->scene.lights.size(), cm->scene.lights.size());
    for (std::size_t i = 0; i < metres->scene.lights.size(); ++i)
        EXPECT_NEAR(cm->scene.lights[i].size.x, 0.01f * metres->scene.lights[i].size.x, 1e-6f);
    for (const std::string& note : metres->notes)
        EXPECT_EQ(note.find("units across"), std::string::npos) << note;
}

TEST(ImportUnits, FarBoxObjIsRecentredOnImport) {
    const fs::path dir = tempDir("farbox");
    const fs::path file = dir / "far.obj";
    {
        std::ofstream out(file);
        for (int i = 0; i < 8; ++i)
            out << "v " << (i & 1 ? 100001 : 99999) << " " << (i & 2 ? 2 : 0) << " " << (i & 4 ? 1 : -1)
                << "\n";
        out << "f 1 2 4 3\nf 5 7 8 6\nf 1 5 6 2\nf 3 4 8 7\nf 1 3 7 5\nf 2 6 8 4\n";
    }
    auto r = importers::importScene(file);
    ASSERT_TRUE(r) << r.error().describe();
    EXPECT_EQ(r->stats.meshesRecentred, 1u);
    const scene::Bounds world = r->scene.worldBounds();
    EXPECT_NEAR(world.min.x, 99999.0, floatRounding(1e5));
    EXPECT_NEAR(world.max.x, 100001.0, floatRounding(1e5));
    EXPECT_NEAR(world.max.y, 2.0, 1e-6);
    for (const scene::Mesh& m : r->scene.meshes)
        for (const glm::vec3& p : m.positions)
            EXPECT_LE(glm::length(p), 2.0f);
    bool noted = false;
    for (const std::string& note : r->notes)
        noted |= note.find("far from the origin") != std::string::npos;
    EXPECT_TRUE(noted);
    fs::remove_all(dir);
}

namespace {
fs::path assimpModels() {
    return fs::path(LPV_TEST_ASSIMP_MODELS_DIR);
}
} // namespace

// FBX's UnitScaleFactor is centimetres per unit; global_settings.fbx says 500.
TEST(ImportUnits, FbxIsReadInItsUnitScaleFactor) {
    const fs::path file = assimpModels() / "FBX/global_settings.fbx";
    if (!fs::exists(file))
        GTEST_SKIP() << file << " is not installed (Debian: assimp-testmodels)";
    auto stated = importers::importScene(file);
    ASSERT_TRUE(stated) << stated.error().describe();
    importers::ImportOptions raw;
    raw.metresPerUnit = 1.0;
    raw.unitSource = "--unit m";
    auto asIs = importers::importScene(file, raw);
    ASSERT_TRUE(asIs) << asIs.error().describe();
    EXPECT_EQ(stated->stats.lengthScale.factor, 5.0);
    EXPECT_EQ(stated->stats.lengthScale.source, "the file's UnitScaleFactor 500: 500 cm per unit");
    EXPECT_EQ(stated->stats.lengthScale.knew, importers::UnitKnowledge::StatedByFile);
    EXPECT_NEAR(largestSide(stated->scene.worldBounds()), 5.0 * largestSide(asIs->scene.worldBounds()),
                1e-5 * largestSide(stated->scene.worldBounds()));
    // The user's unit replaced the file's, and the import said so.
    bool said = false;
    for (const std::string& note : asIs->notes)
        said |= note.find("--unit m replaces the unit the file states") != std::string::npos;
    EXPECT_TRUE(said);
}

// Collada's <unit meter="0.01"> is applied (by Assimp); --unit replaces it.
TEST(ImportUnits, ColladaIsReadInItsUnitAndTheUsersReplacesIt) {
    const fs::path file = assimpModels() / "Collada/cube_triangulate.dae";
    if (!fs::exists(file))
        GTEST_SKIP() << file << " is not installed (Debian: assimp-testmodels)";
    auto stated = importers::importScene(file);
    ASSERT_TRUE(stated) << stated.error().describe();
    importers::ImportOptions raw;
    raw.metresPerUnit = 1.0;
    auto asIs = importers::importScene(file, raw);
    ASSERT_TRUE(asIs) << asIs.error().describe();
    EXPECT_EQ(stated->stats.lengthScale.knew, importers::UnitKnowledge::StatedByFile);
    EXPECT_NEAR(largestSide(asIs->scene.worldBounds()), 100.0 * largestSide(stated->scene.worldBounds()),
                1e-4 * largestSide(asIs->scene.worldBounds()));
}

TEST(ImportUnits, GltfIsInMetresWithoutANote) {
    for (const auto& entry : fs::recursive_directory_iterator(scenes() / "gltf-small")) {
        const fs::path file = entry.path();
        if (file.extension() != ".gltf" && file.extension() != ".glb")
            continue;
        auto r = importers::importScene(file);
        ASSERT_TRUE(r) << r.error().describe();
        EXPECT_EQ(r->stats.lengthScale.factor, 1.0) << file;
        EXPECT_EQ(r->stats.lengthScale.knew, importers::UnitKnowledge::StatedByFile) << file;
        for (const std::string& note : r->notes)
            EXPECT_EQ(note.find("units across"), std::string::npos) << file << ": " << note;
    }
}
