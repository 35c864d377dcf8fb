// Project format v1: what is saved loads back exactly, the file looks as
// documented, and saving is deterministic, atomic and tidy.
#include "ProjectTestSupport.h"

#include "lpv/scene/CornellBox.h"
#include "lpv/scene/MeshAsset.h"
#include "lpv/scene/Project.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <set>

using namespace lpv::scene;
using namespace lpv::test;
namespace fs = std::filesystem;

namespace {

class ProjectRoundTrip : public TempDirTest {
protected:
    ProjectRoundTrip() : TempDirTest("lpv-ProjectRoundTrip-") {}
};

Mesh quadMesh(const std::string& name, float offset, std::uint32_t material) {
    Mesh m;
    m.name = name;
    m.positions = {{offset, 0, 0}, {offset + 1, 0, 0}, {offset + 1, 1, 0.5f}, {offset, 1, 0.1f}};
    m.normals.assign(4, {0, 0, 1});
    m.tangents.assign(4, {1, 0, 0, -1});
    m.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    m.indices = {0, 1, 2, 0, 2, 3};
    m.submeshes = {{0, 3, material}, {3, 3, 0}};
    return m;
}

// Sets one parameter of each type to a value other than its default.
void setOneParameterOfEachType(ParameterSet& set) {
    std::set<ParameterType> done;
    for (const ParameterInfo& p : ParameterRegistry::instance().all()) {
        if (done.contains(p.type))
            continue;
        ParameterValue v;
        switch (p.type) {
        case ParameterType::Bool: v = !std::get<bool>(p.defaultValue); break;
        case ParameterType::Int:
            v = static_cast<int>(p.minValue) == std::get<int>(p.defaultValue) ? static_cast<int>(p.maxValue)
                                                                               : static_cast<int>(p.minValue);
            break;
        case ParameterType::Float: v = p.minValue + (p.maxValue - p.minValue) * 0.3; break;
        case ParameterType::Enum: v = p.enumValues.back(); break;
        }
        const auto r = set.set(p.key, v, "test");
        ASSERT_TRUE(r) << r.error().describe();
        done.insert(p.type);
    }
    EXPECT_EQ(set.overrides().size(), 4u) << "the registry should have bool, int, float and enum parameters";
}

Project richProject() {
    Project p;
    p.name = "round trip \xc3\xbc"; // UTF-8 "ü"
    Scene& s = p.scene;

    Material phong;
    phong.name = "phong";
    phong.diffuseColor = {0.8f, 0.1f, 0.25f};
    phong.diffuseTexture = "textures/brick diffuse.png";
    phong.normalTexture = "textures/brick_n.png";
    phong.heightTexture = "textures/brick_h.png";
    phong.specularColor = {0.5f, 0.5f, 0.4f};
    phong.specularTexture = "textures/brick_s.png";
    phong.shininess = 77.5f;
    phong.opacity = 0.3f;
    phong.alphaMode = AlphaMode::Blend;
    phong.translucency = 0.6f;
    phong.twoSided = true;
    phong.alphaTexture = "textures/brick_a.bmp";
    phong.colorKey = true;
    phong.additive = true;
    phong.environmentTexture = "env.bmp";
    phong.environmentRatio = 0.4f;

    Material pbr;
    pbr.name = "pbr";
    pbr.shading = ShadingModel::MetallicRoughness;
    pbr.metallic = 1.0f;
    pbr.roughness = 0.35f;
    // Inside the project's folder: a reference leading out of it is cut to its
    // file name on load (ReadRoots, tests/importers/ReadPolicyTest.cpp).
    pbr.metallicRoughnessTexture = "shared/mr.png";
    pbr.occlusionTexture = "ao.png";
    pbr.emissive = {4.0f, 2.0f, 0.0f};
    pbr.emissiveTexture = "glow.png";
    pbr.alphaMode = AlphaMode::Mask;
    pbr.alphaCutoff = 0.42f;
    pbr.glossiness = 0.9f;

    Material plain;
    plain.name = "";
    s.materials = {phong, pbr, plain};

    Mesh positionsOnly;
    positionsOnly.name = "positions only";
    positionsOnly.positions = {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}};
    positionsOnly.indices = {0, 2, 1};
    s.meshes = {quadMesh("quad a", 0.0f, 1), positionsOnly, quadMesh("quad b", 3.0f, 2), Mesh{}};

    Object root{"root", 0, -1, {}, true, {}};
    root.transform.translation = {1.5f, -2.0f, 3.25f};
    root.transform.rotation = glm::angleAxis(0.7f, glm::normalize(glm::vec3(1, 2, 3)));
    root.transform.scale = {2.0f, 2.0f, -1.0f};
    Object child{"child", 2, 0, {}, false, {}};
    child.transform.rotation = glm::quat(0.5f, 0.5f, -0.5f, 0.5f);
    Object group{"group (no mesh)", -1, 1, {}, true, {}};
    Object other{"other", 1, -1, {}, true, {}};
    other.lods = {{2, 10.0f}, {0, 25.5f}};
    s.objects = {root, child, group, other};

    Light sun;
    sun.name = "sun";
    sun.direction = glm::normalize(glm::vec3(-1, -3, -0.5f));
    sun.color = {1.0f, 0.95f, 0.8f};
    sun.intensity = 3.5f;
    Light bulb;
    bulb.name = "bulb";
    bulb.type = LightType::Point;
    bulb.position = {0, 2.5f, 0};
    bulb.direction = glm::vec3(0.0f); // point lights have none
    bulb.range = 12.0f;
    bulb.castShadows = false;
    Light spot;
    spot.name = "spot";
    spot.type = LightType::Spot;
    spot.innerConeAngle = 0.2f;
    spot.outerConeAngle = std::numbers::pi_v<float> / 2; // the limit, rounded up as a float
    s.lights = {sun, bulb, spot};

    Camera main;
    main.name = "main";
    main.position = {0, 1.7f, 6};
    main.target = {0, 1, 0};
    main.fovY = 1.1f;
    Camera top;
    top.name = "top";
    top.position = {0, 20, 0};
    top.target = {0, 0, 0};
    top.up = {0, 0, -1};
    top.nearPlane = 0.5f;
    top.farPlane = 1000.0f;
    s.cameras = {main, top};

    CameraPath flythrough;
    flythrough.name = "flythrough";
    flythrough.keyframes = {{0.0f, {0, 1, 5}, {1, 0, 0, 0}, 0.8f},
                            {2.5f, {3, 1, 2}, glm::angleAxis(0.5f, glm::vec3(0, 1, 0)), 0.9f},
                            {2.5f, {4, 1, 1}, glm::angleAxis(1.0f, glm::vec3(0, 1, 0)), 1.0f},
                            {7.25f, {5, 2, 0}, glm::quat(0.0f, 0.0f, 1.0f, 0.0f), 0.5f}};
    flythrough.closed = true;
    CameraPath steady{"steady", {{1.0f, {0, 0, 0}, {1, 0, 0, 0}, 0.8f}}};
    steady.constantSpeed = true;
    s.cameraPaths = {flythrough, steady, CameraPath{"empty path", {}}};

    s.sky.color = {0.3f, 0.45f, 0.9f};
    s.sky.intensity = 0.75f;

    setOneParameterOfEachType(p.parameters);

    ParameterPreset bright{"bright \xe2\x98\x80", {}}; // UTF-8 sun
    setOneParameterOfEachType(bright.parameters);
    EXPECT_TRUE(bright.parameters.set("lpv.intensity", 2.5));
    // A preset may pin a value equal to the default; it must stay pinned.
    EXPECT_TRUE(bright.parameters.set("lpv.propagationSteps", 8));
    p.presets = {bright, ParameterPreset{"defaults", {}}};
    return p;
}

} // namespace

TEST_F(ProjectRoundTrip, SaveThenLoadGivesAnEqualProject) {
    const Project original = richProject();
    const fs::path file = dir_ / "rich.lpvproj";
    const auto saved = saveProject(original, file);
    ASSERT_TRUE(saved) << saved.error().describe();
    const auto loaded = loadProject(file);
    ASSERT_TRUE(loaded) << loaded.error().describe();
    EXPECT_EQ(*loaded, original);
    // Spot checks, in case operator== were too lenient.
    EXPECT_EQ(loaded->scene.meshes[0].positions, original.scene.meshes[0].positions);
    EXPECT_EQ(loaded->scene.objects[1].parent, 0);
    EXPECT_EQ(loaded->scene.lights[2].outerConeAngle, std::numbers::pi_v<float> / 2);
    EXPECT_EQ(loaded->parameters.overrides(), original.parameters.overrides());
    ASSERT_EQ(loaded->presets.size(), 2u);
    EXPECT_EQ(loaded->presets[0].name, original.presets[0].name);
    EXPECT_EQ(loaded->presets[0].parameters.overrides(), original.presets[0].parameters.overrides());
    EXPECT_TRUE(loaded->presets[0].parameters.isSet("lpv.propagationSteps"));
    EXPECT_TRUE(loaded->presets[1].parameters.overrides().empty());
}

TEST_F(ProjectRoundTrip, TheFileLooksAsDocumented) {
    ASSERT_TRUE(saveProject(richProject(), dir_ / "doc.lpvproj"));
    const std::string text = readFile(dir_ / "doc.lpvproj");
    EXPECT_EQ(text.rfind("{\n  \"format\": \"lpvstudio-project\",\n  \"version\": 2,\n  \"name\": ", 0), 0u) << text;
    EXPECT_NE(text.find("\"asset\": \"doc.assets/meshes/0-"), std::string::npos);
    // Floats are written as the shortest decimal that reads back exactly.
    EXPECT_NE(text.find("\"opacity\": 0.3,"), std::string::npos);
    EXPECT_NE(text.find("\"rotation\": [\n"), std::string::npos);
    // Presets come last, after the parameters they are alternatives to.
    EXPECT_LT(text.find("\"parameters\": {"), text.find("\"presets\": ["));
    EXPECT_NE(text.find("\"name\": \"defaults\",\n      \"parameters\": {}"), std::string::npos) << text;
    EXPECT_EQ(text.back(), '\n');
    const std::set<std::string> files = listFiles(dir_);
    EXPECT_EQ(files.size(), 5u) << "the project file and four mesh assets";
    for (const std::string& f : files)
        EXPECT_TRUE(f == "doc.lpvproj" || (f.starts_with("doc.assets/meshes/") && f.ends_with(".lpvmesh"))) << f;
}

TEST_F(ProjectRoundTrip, SavingTwiceWritesIdenticalBytes) {
    const Project p = richProject();
    ASSERT_TRUE(saveProject(p, dir_ / "a.lpvproj"));
    const std::string first = readFile(dir_ / "a.lpvproj");
    const std::set<std::string> firstFiles = listFiles(dir_);
    const auto loaded = loadProject(dir_ / "a.lpvproj");
    ASSERT_TRUE(loaded);
    ASSERT_TRUE(saveProject(*loaded, dir_ / "a.lpvproj"));
    EXPECT_EQ(readFile(dir_ / "a.lpvproj"), first);
    EXPECT_EQ(listFiles(dir_), firstFiles);
}

TEST_F(ProjectRoundTrip, FloatsSurviveExactly) {
    Project p;
    p.name = "floats";
    const float tiny = std::numeric_limits<float>::denorm_min();
    // The extremes a project accepts (ValueChecks.h, issue #42): coordinates
    // to +-1e18, scales from 1e-18, quaternions normalisable in float.
    const float huge = 1e18f;
    Object o{"o", -1, -1, {}, true, {}};
    o.transform.translation = {tiny, -huge, -0.0f};
    o.transform.scale = {-1e-18f, 1.0f / 3.0f, 16777217.0f};
    o.transform.rotation = glm::quat(1e-17f, -1e-17f, 0.0f, 0.0f);
    p.scene.objects = {o};
    ASSERT_TRUE(saveProject(p, dir_ / "f.lpvproj"));
    const auto loaded = loadProject(dir_ / "f.lpvproj");
    ASSERT_TRUE(loaded) << loaded.error().describe();
    EXPECT_EQ(*loaded, p);
    EXPECT_TRUE(std::signbit(loaded->scene.objects[0].transform.translation.z)) << "-0 stays -0";
    EXPECT_EQ(loaded->scene.objects[0].transform.translation.x, tiny);
}

TEST_F(ProjectRoundTrip, EqualityNoticesEveryKindOfChange) {
    const Project base = richProject();
    const std::vector<std::pair<const char*, std::function<void(Project&)>>> changes = {
        {"name", [](Project& p) { p.name += "!"; }},
        {"mesh position", [](Project& p) { p.scene.meshes[0].positions[2].y += 1e-6f; }},
        {"mesh uv", [](Project& p) { p.scene.meshes[2].uvs[0].x = 0.5f; }},
        {"mesh name", [](Project& p) { p.scene.meshes[1].name = "x"; }},
        {"submesh", [](Project& p) { p.scene.meshes[0].submeshes[1].materialIndex = 2; }},
        {"material value", [](Project& p) { p.scene.materials[1].roughness = 0.36f; }},
        {"material texture", [](Project& p) { p.scene.materials[0].normalTexture.clear(); }},
        {"object parent", [](Project& p) { p.scene.objects[2].parent = -1; }},
        {"object rotation", [](Project& p) { p.scene.objects[0].transform.rotation.w *= -1.0f; }},
        {"object visibility", [](Project& p) { p.scene.objects[1].visible = true; }},
        {"object lod", [](Project& p) { p.scene.objects[3].lods[1].distance = 26.0f; }},
        {"material colour key", [](Project& p) { p.scene.materials[0].colorKey = false; }},
        {"material alpha map", [](Project& p) { p.scene.materials[0].alphaTexture.clear(); }},
        {"light cone", [](Project& p) { p.scene.lights[2].innerConeAngle = 0.3f; }},
        {"camera", [](Project& p) { p.scene.cameras[1].farPlane = 999.0f; }},
        {"keyframe", [](Project& p) { p.scene.cameraPaths[0].keyframes[3].time = 8.0f; }},
        {"camera path", [](Project& p) { p.scene.cameraPaths.pop_back(); }},
        {"closed path", [](Project& p) { p.scene.cameraPaths[0].closed = false; }},
        {"constant speed", [](Project& p) { p.scene.cameraPaths[1].constantSpeed = false; }},
        {"sky", [](Project& p) { p.scene.sky.intensity = 0.0f; }},
        {"parameter", [](Project& p) { p.parameters = ParameterSet{}; }},
        {"preset name", [](Project& p) { p.presets[1].name = "other"; }},
        {"preset parameter", [](Project& p) { ASSERT_TRUE(p.presets[0].parameters.set("lpv.intensity", 2.0)); }},
        {"preset pinned to its default", [](Project& p) { p.presets[0].parameters.reset("lpv.propagationSteps"); }},
        {"preset order", [](Project& p) { std::swap(p.presets[0], p.presets[1]); }},
        {"preset removed", [](Project& p) { p.presets.pop_back(); }},
    };
    for (const auto& [what, change] : changes) {
        Project changed = base;
        EXPECT_TRUE(changed == base);
        change(changed);
        EXPECT_FALSE(changed == base) << what;
    }
}

TEST_F(ProjectRoundTrip, ResavingDropsAssetsNoLongerReferenced) {
    Project p = richProject();
    const fs::path file = dir_ / "r.lpvproj";
    ASSERT_TRUE(saveProject(p, file));
    p.scene.meshes[0].positions[0].x = 42.0f;
    p.scene.meshes.pop_back();
    ASSERT_TRUE(saveProject(p, file));
    EXPECT_EQ(listFiles(dir_ / "r.assets/meshes").size(), 3u);
    const auto loaded = loadProject(file);
    ASSERT_TRUE(loaded) << loaded.error().describe();
    EXPECT_EQ(*loaded, p);
}

TEST_F(ProjectRoundTrip, UnchangedMeshesAreNotRewritten) {
    Project p = richProject();
    const fs::path file = dir_ / "u.lpvproj";
    ASSERT_TRUE(saveProject(p, file));
    const fs::file_time_type old = fs::file_time_type::clock::now() - std::chrono::hours(24);
    for (const auto& entry : fs::directory_iterator(dir_ / "u.assets/meshes"))
        fs::last_write_time(entry.path(), old);
    p.scene.materials[0].shininess = 5.0f;
    p.scene.meshes[3].name = "renamed"; // names live in the asset too
    ASSERT_TRUE(saveProject(p, file));
    int untouched = 0;
    for (const auto& entry : fs::directory_iterator(dir_ / "u.assets/meshes"))
        untouched += fs::last_write_time(entry.path()) == old ? 1 : 0;
    EXPECT_EQ(untouched, 3);
    const auto loaded = loadProject(file);
    ASSERT_TRUE(loaded);
    EXPECT_EQ(*loaded, p);
}

TEST_F(ProjectRoundTrip, AProjectMovesWithItsAssetsFolder) {
    const Project p = richProject();
    ASSERT_TRUE(saveProject(p, dir_ / "before" / "m.lpvproj"));
    fs::rename(dir_ / "before", dir_ / "after");
    const auto loaded = loadProject(dir_ / "after" / "m.lpvproj");
    ASSERT_TRUE(loaded) << loaded.error().describe();
    EXPECT_EQ(*loaded, p);
}

TEST_F(ProjectRoundTrip, AnEmptyProjectRoundTrips) {
    const Project empty;
    ASSERT_TRUE(saveProject(empty, dir_ / "empty.lpvproj"));
    const auto loaded = loadProject(dir_ / "empty.lpvproj");
    ASSERT_TRUE(loaded) << loaded.error().describe();
    EXPECT_EQ(*loaded, empty);
    EXPECT_EQ(listFiles(dir_), std::set<std::string>{"empty.lpvproj"});
}

// Presets were added to version 1 after it was published (1.1): a file
// without them must load, and a project without presets is written without
// the field, byte for byte as before.
TEST_F(ProjectRoundTrip, AProjectWithoutPresetsHasNoPresetsField) {
    Project p = richProject();
    p.presets.clear();
    ASSERT_TRUE(saveProject(p, dir_ / "old.lpvproj"));
    EXPECT_EQ(readFile(dir_ / "old.lpvproj").find("presets"), std::string::npos);
    const auto loaded = loadProject(dir_ / "old.lpvproj");
    ASSERT_TRUE(loaded) << loaded.error().describe();
    EXPECT_TRUE(loaded->presets.empty());
    EXPECT_EQ(*loaded, p);
}

TEST_F(ProjectRoundTrip, TheCornellBoxRoundTrips) {
    const Project box = makeCornellBoxProject();
    const auto saved = saveProject(box, dir_ / "cornell.lpvproj");
    ASSERT_TRUE(saved) << saved.error().describe();
    const auto loaded = loadProject(dir_ / "cornell.lpvproj");
    ASSERT_TRUE(loaded) << loaded.error().describe();
    EXPECT_EQ(*loaded, box);
}

TEST_F(ProjectRoundTrip, SaveRejectsAnInvalidProjectAndWritesNothing) {
    Project p = richProject();
    p.scene.materials[2].opacity = 1.5f;
    auto saved = saveProject(p, dir_ / "bad.lpvproj");
    ASSERT_FALSE(saved);
    EXPECT_EQ(saved.error().code, ErrorCode::OutOfRange);
    EXPECT_EQ(saved.error().location, "materials[2].opacity");

    p = richProject();
    p.scene.meshes[2].positions[3].y = std::numeric_limits<float>::infinity();
    saved = saveProject(p, dir_ / "bad.lpvproj");
    ASSERT_FALSE(saved);
    EXPECT_EQ(saved.error().code, ErrorCode::NonFinite);
    EXPECT_EQ(saved.error().location, "meshes[2].positions[3].y");

    p = richProject();
    p.scene.objects[0].parent = 2; // 0 -> 2 -> 1 -> 0
    saved = saveProject(p, dir_ / "bad.lpvproj");
    ASSERT_FALSE(saved);
    EXPECT_EQ(saved.error().code, ErrorCode::InvalidValue);

    p = richProject();
    p.scene.lights[1].name = "caf\xe9"; // Latin-1, as in old 8-bit scene files
    saved = saveProject(p, dir_ / "bad.lpvproj");
    ASSERT_FALSE(saved);
    EXPECT_EQ(saved.error().code, ErrorCode::InvalidValue);
    EXPECT_NE(saved.error().message.find("UTF-8"), std::string::npos) << saved.error().message;

    p = richProject();
    p.presets[1].name = p.presets[0].name;
    saved = saveProject(p, dir_ / "bad.lpvproj");
    ASSERT_FALSE(saved);
    EXPECT_EQ(saved.error().code, ErrorCode::InvalidValue);
    EXPECT_EQ(saved.error().location, "presets[1].name");

    p = richProject();
    p.presets[0].name.clear();
    saved = saveProject(p, dir_ / "bad.lpvproj");
    ASSERT_FALSE(saved);
    EXPECT_EQ(saved.error().code, ErrorCode::InvalidValue);
    EXPECT_EQ(saved.error().location, "presets[0].name");

    EXPECT_TRUE(fs::is_empty(dir_)) << "nothing was written";
}

TEST(AtomicFile, ReplacesTheContentAndCreatesFolders) {
    const fs::path dir = fs::path(testing::TempDir()) / "lpv-atomic-replace";
    fs::remove_all(dir);
    const fs::path file = dir / "a" / "b" / "c.txt";
    ASSERT_TRUE(writeFileAtomically(file, "first version"));
    EXPECT_EQ(readFile(file), "first version");
    ASSERT_TRUE(writeFileAtomically(file, "2nd"));
    EXPECT_EQ(readFile(file), "2nd");
    ASSERT_TRUE(writeFileAtomically(file, ""));
    EXPECT_EQ(readFile(file), "");
    EXPECT_EQ(listFiles(dir), std::set<std::string>{"a/b/c.txt"}) << "no temporary files left";
    fs::remove_all(dir);
}

TEST(AtomicFile, AFolderInTheWayFailsAndLeavesNoTemporary) {
    const fs::path dir = fs::path(testing::TempDir()) / "lpv-atomic-folder";
    fs::remove_all(dir);
    fs::create_directories(dir / "target" / "inside");
    const auto written = writeFileAtomically(dir / "target", "bytes");
    ASSERT_FALSE(written);
    EXPECT_EQ(written.error().code, ErrorCode::IoError);
    EXPECT_EQ(written.error().file, (dir / "target").string());
    EXPECT_TRUE(fs::is_directory(dir / "target" / "inside"));
    EXPECT_TRUE(listFiles(dir).empty());
    fs::remove_all(dir);
}

// Issue #26: the editor's view is saved with the project and comes back; a
// project without one has no field (its bytes are as before), and a broken
// one is an error at its place.
TEST_F(ProjectRoundTrip, TheEditorViewRoundTripsAndIsOptional) {
    Project p = richProject();
    EXPECT_FALSE(p.editorView);
    ASSERT_TRUE(saveProject(p, dir_ / "noview.lpvproj"));
    EXPECT_EQ(readFile(dir_ / "noview.lpvproj").find("editorView"), std::string::npos);

    Camera view;
    view.name = "Editor view";
    view.position = {1.25f, 2.5f, -3.75f};
    view.target = {0.1f, 0.2f, 0.3f};
    view.fovY = 0.9f;
    p.editorView = view;
    ASSERT_TRUE(saveProject(p, dir_ / "view.lpvproj"));
    auto loaded = loadProject(dir_ / "view.lpvproj");
    ASSERT_TRUE(loaded) << loaded.error().describe();
    ASSERT_TRUE(loaded->editorView);
    EXPECT_EQ(*loaded->editorView, view);
    EXPECT_EQ(*loaded, p);
    EXPECT_EQ(loaded->scene.cameras, p.scene.cameras) << "the view is not one of the scene's cameras";
    Project other = p;
    other.editorView->position.x += 1.0f;
    EXPECT_FALSE(other == p);

    std::string text = readFile(dir_ / "view.lpvproj");
    const auto at = text.find("\"editorView\"");
    ASSERT_NE(at, std::string::npos);
    const auto pos = text.find("\"position\"", at);
    const auto target = text.find("\"target\"", at);
    ASSERT_NE(pos, std::string::npos);
    ASSERT_NE(target, std::string::npos);
    // The view looking at its own position: refused, with the place named.
    const std::string posValue = text.substr(text.find('[', pos), text.find(']', pos) - text.find('[', pos) + 1);
    const auto targetOpen = text.find('[', target), targetClose = text.find(']', target);
    text.replace(targetOpen, targetClose - targetOpen + 1, posValue);
    std::ofstream(dir_ / "view.lpvproj", std::ios::binary | std::ios::trunc) << text;
    loaded = loadProject(dir_ / "view.lpvproj");
    ASSERT_FALSE(loaded);
    EXPECT_EQ(loaded.error().location, "editorView.target");
}
