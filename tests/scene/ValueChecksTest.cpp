// Values checked as products (issue #42, docs/hard-cases.md): each value
// below is a finite float that passed the reader's per-field checks and
// gave a black or NaN image, a radiosity solve that never ended, or a video
// of 10^9 frames. The reader now refuses it naming the field (the same
// reader checks saves and imports); importers repair it with a warning.
#include "ProjectTestSupport.h"

#include "lpv/scene/CameraPathFile.h"
#include "lpv/scene/Project.h"
#include "lpv/scene/ValueChecks.h"
#include "lpv/scene/ValueRepair.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

using namespace lpv::scene;

namespace {

constexpr float kHuge = 3.4e38f;
constexpr float kTiniest = 1e-45f; // the smallest denormal

Scene oneLight(const Light& light) {
    Scene s;
    s.lights.push_back(light);
    return s;
}

Scene oneCamera(const Camera& camera) {
    Scene s;
    s.cameras.push_back(camera);
    return s;
}

// The error the reader gives for the scene (the check saves and imports run).
Error refusal(Scene scene) {
    const auto valid = validateSceneContent(scene, "hard.obj");
    EXPECT_FALSE(valid.has_value());
    return valid ? Error{} : valid.error();
}

void expectRefused(Scene scene, const std::string& location, ErrorCode code, const std::string& words) {
    const Error e = refusal(std::move(scene));
    EXPECT_EQ(e.file, "hard.obj");
    EXPECT_EQ(e.location, location) << e.describe();
    EXPECT_EQ(e.code, code) << e.describe();
    EXPECT_NE(e.message.find(words), std::string::npos) << e.message;
}

Light areaLight() {
    Light l;
    l.type = LightType::Area;
    l.position = {0, 2, 0};
    return l;
}

} // namespace

TEST(ValueChecks, OverflowingLightIntensityOrColourIsRefusedNamingTheField) {
    Light bright;
    bright.intensity = kHuge;
    expectRefused(
        oneLight(bright), "lights[0].intensity", ErrorCode::OutOfRange,
        "the irradiance (colour x intensity) is 3.39999995e+38, over 1e30: products kept under 1e30 "
        "leave 1e8 of float headroom for exposure, SH constants and sums over lights");
    Light colour;
    colour.color = {1.0f, kHuge, 1.0f};
    expectRefused(oneLight(colour), "lights[0].color[1]", ErrorCode::OutOfRange,
                  "the colour is 3.39999995e+38, over 1e30");
    // Each factor alone is modest; their product is not.
    Light product;
    product.type = LightType::Point;
    product.color = glm::vec3(2e16f);
    product.intensity = 1e16f;
    expectRefused(oneLight(product), "lights[0].color", ErrorCode::OutOfRange,
                  "the radiant intensity (colour x intensity) is 2");
}

TEST(ValueChecks, EachFactorIsBoundedAndASpotConeCannotVanish) {
    Light dark; // colour 3.4e38 at intensity 0: the product is 0, the colour alone is not
    dark.color = {kHuge, 1.0f, 1.0f};
    dark.intensity = 0.0f;
    expectRefused(oneLight(dark), "lights[0].color[0]", ErrorCode::OutOfRange,
                  "the colour is 3.39999995e+38, over 1e30");
    Light spot;
    spot.type = LightType::Spot;
    spot.outerConeAngle = kTiniest;
    expectRefused(oneLight(spot), "lights[0].outerConeAngle", ErrorCode::OutOfRange,
                  "outer cone angle 1.40129846e-45 rad is below 0.001 rad (0.057 degrees)");
    Scene sky;
    sky.sky.color = {0.5f, kHuge, 0.5f};
    sky.sky.intensity = 0.0f;
    expectRefused(sky, "sky.color[1]", ErrorCode::OutOfRange, "the colour is 3.39999995e+38, over 1e30");
}

TEST(ValueChecks, DiffuseColourAndEmissionBeyondTheHeadroomAreRefused) {
    Scene s;
    s.materials.resize(1);
    s.materials[0].diffuseColor = {0.5f, 0.5f, kHuge};
    expectRefused(s, "materials[0].diffuseColor[2]", ErrorCode::OutOfRange,
                  "is over 100: a reflectance is at most 1");
    s.materials[0].diffuseColor = glm::vec3(0.5f);
    s.materials[0].emissive = {kHuge, 0.0f, 0.0f};
    expectRefused(s, "materials[0].emissive[0]", ErrorCode::OutOfRange,
                  "the emitted radiance is 3.39999995e+38, over 1e30");
}

TEST(ValueChecks, AreaLightSizeAndItsPowerAreCheckedAsProducts) {
    Light big = areaLight();
    big.size = {3e38f, 1.0f};
    expectRefused(oneLight(big), "lights[0].size[0]", ErrorCode::OutOfRange, "is outside 1e-18..1e18");
    // 1e15 m x 1e15 m at radiance 1: the emitted power pi x 1e30 overflows the headroom.
    Light wide = areaLight();
    wide.size = {1e15f, 1e15f};
    expectRefused(oneLight(wide), "lights[0].size", ErrorCode::OutOfRange,
                  "the emitted power (colour x intensity x area x pi) is 3.14159");
    // A 1 W light a micrometre across is fine; 1e25 W on it is 3e36 W/(m^2 sr).
    Light tiny = areaLight();
    tiny.unit = AreaUnit::Power;
    tiny.size = {1e-6f, 1e-6f};
    EXPECT_FALSE(checkLight(tiny).has_value());
    tiny.intensity = 1e25f;
    expectRefused(oneLight(tiny), "lights[0].size", ErrorCode::OutOfRange,
                  "the radiance (power / (area x pi))");
}

TEST(ValueChecks, LightDirectionTooShortToNormaliseIsRefused) {
    Light l;
    l.direction = {0.0f, -kTiniest, 0.0f};
    expectRefused(
        oneLight(l), "lights[0].direction", ErrorCode::InvalidValue,
        "the direction is 1.40129846e-45 long, below 1e-18: it cannot be normalised in 32-bit floats");
}

TEST(ValueChecks, CameraUpAlongTheViewOrVanishingIsRefused) {
    Camera parallel;
    parallel.position = {0, 0, 5};
    parallel.target = {0, 10, 5}; // looking straight up, up = +Y
    expectRefused(oneCamera(parallel), "cameras[0].up", ErrorCode::InvalidValue,
                  "the up vector is parallel to the view direction (0 degrees apart, at least 0.06 needed)");
    Camera vanishing;
    vanishing.up = {0.0f, kTiniest, 0.0f};
    expectRefused(oneCamera(vanishing), "cameras[0].up", ErrorCode::InvalidValue,
                  "the up vector is 1.40129846e-45 long, below 1e-18");
}

TEST(ValueChecks, VanishingFieldOfViewIsRefused) {
    for (const float fov : {kTiniest, 1e-30f}) {
        Camera c;
        c.fovY = fov;
        expectRefused(oneCamera(c), "cameras[0].fovY", ErrorCode::OutOfRange,
                      "is outside 1e-4..3.1241 rad (0.0057..179 degrees)");
    }
    Camera telephoto; // 4 m wide at 10 km (ReferenceHardCases.FarCameraStaysFinite)
    telephoto.fovY = 0.0004f;
    EXPECT_FALSE(checkCamera(telephoto).has_value());
}

TEST(ValueChecks, DepthRangeIsBoundAsARatioNotAsLengths) {
    Camera absurd;
    absurd.nearPlane = kTiniest;
    absurd.farPlane = kHuge;
    expectRefused(oneCamera(absurd), "cameras[0].nearPlane", ErrorCode::OutOfRange, "is outside 1e-18..1e18");
    Camera deep;
    deep.nearPlane = 1e-3f;
    deep.farPlane = 1e5f;
    expectRefused(oneCamera(deep), "cameras[0].nearPlane", ErrorCode::OutOfRange,
                  "over 1.6e7: the 32-bit depth buffer cannot tell the far part of the view");
    // Large and small scenes stay: 1 mm to 10 km, a micrometre to 1 m, 1 km to 1e10 km.
    for (const auto& [near, far] : {std::pair{1e-3f, 1e4f}, std::pair{1e-6f, 1.0f}, std::pair{1e6f, 1e13f}}) {
        Camera c;
        c.nearPlane = near;
        c.farPlane = far;
        c.position = {0, 0, far * 0.1f};
        EXPECT_FALSE(checkCamera(c).has_value()) << near << " " << far << ": " << checkCamera(c)->message;
    }
}

TEST(ValueChecks, CameraPathKeyTimesAndPositionsAreBounded) {
    CameraPath path;
    path.name = "fly";
    path.keyframes.resize(2);
    path.keyframes[1].time = 1e30f;
    Scene s;
    s.cameraPaths.push_back(path);
    expectRefused(s, "cameraPaths[0].keyframes[1].time", ErrorCode::OutOfRange,
                  "key time 1.00000002e+30 s is outside 0..86400 (a day)");
    s.cameraPaths[0].keyframes[1].time = 2.0f;
    s.cameraPaths[0].keyframes[1].position.x = -kHuge;
    expectRefused(s, "cameraPaths[0].keyframes[1].position[0]", ErrorCode::OutOfRange, "is beyond +-1e18");
}

TEST(ValueChecks, PlannedFramesAreBoundedAndCsvRowsNeverNegative) {
    const auto why = checkPlannedFrames(1e30, 30.0);
    ASSERT_TRUE(why.has_value());
    EXPECT_EQ(*why,
              "the path lasts 1e+30 s: at 30 fps that is 3e+31 frames, over the limit of 1000000 (9 hours at "
              "30 fps)");
    EXPECT_FALSE(checkPlannedFrames(86400.0, 10.0).has_value());
    EXPECT_TRUE(checkPlannedFrames(86400.0, 30.0).has_value());
    EXPECT_EQ(cameraPathCsvRows(1e30, 30.0), 1000001);
    EXPECT_EQ(cameraPathCsvRows(std::numeric_limits<double>::infinity(), 30.0), 1000001);
    EXPECT_EQ(cameraPathCsvRows(2.0, 30.0), 61);
}

TEST(ValueChecks, ObjectTransformProductsAreBounded) {
    Scene s;
    s.objects.resize(2);
    s.objects[0].transform.scale = glm::vec3(1e10f);
    s.objects[1].parent = 0;
    s.objects[1].transform.translation = {1e10f, 0.0f, 0.0f};
    expectRefused(
        s, "objects[1]", ErrorCode::OutOfRange,
        "its world transform (its and its parents' translation x rotation x scale) reaches 1.00000002e+20");
    s.objects[1].transform.translation = {0.0f, 0.0f, 0.0f};
    s.objects[1].transform.scale = {kTiniest, 1.0f, 1.0f};
    expectRefused(s, "objects[1].scale[0]", ErrorCode::OutOfRange, "is outside 1e-18..1e18");
    s.objects[1].transform.scale = {1.0f, 0.0f, 1.0f};
    expectRefused(s, "objects[1].scale[1]", ErrorCode::OutOfRange,
                  "a scale of 0 flattens the object and makes its normal matrix (the inverse of the scale) "
                  "infinite");
}

TEST(ValueChecks, TheProjectReaderNamesTheFileAndField) {
    const auto dir = std::filesystem::path(testing::TempDir()) / ("value-checks-" + lpv::test::pidText());
    std::filesystem::create_directories(dir);
    Project p;
    p.name = "hard";
    Light sun;
    sun.intensity = 7.25f; // a value the text below can find
    p.scene.lights.push_back(sun);
    const auto file = dir / "hard.lpvproj";
    ASSERT_TRUE(saveProject(p, file));
    std::string text = lpv::test::readFile(file);
    const auto at = text.find("7.25");
    ASSERT_NE(at, std::string::npos);
    text.replace(at, 4, "3.4e38");
    lpv::test::writeFile(file, text);
    const auto loaded = loadProject(file);
    ASSERT_FALSE(loaded);
    EXPECT_EQ(loaded.error().file, file.string());
    EXPECT_EQ(loaded.error().location, "lights[0].intensity");
    EXPECT_EQ(loaded.error().code, ErrorCode::OutOfRange);
    std::filesystem::remove_all(dir);
}

TEST(ValueRepair, ImportedCamerasAreRepairedWithAWarning) {
    Scene s;
    Camera up; // 3DS/CameraRollAnim.3ds after the Z-up conversion: looking along +Y with up +Y
    up.name = "Camera01";
    up.position = {0, 0, 0};
    up.target = {0, 1, 0};
    s.cameras.push_back(up);
    Camera narrow;
    narrow.name = "narrow";
    narrow.fovY = 1e-30f;
    narrow.nearPlane = kTiniest;
    narrow.farPlane = kHuge;
    s.cameras.push_back(narrow);
    Camera lost;
    lost.name = "lost";
    lost.position.x = std::numeric_limits<float>::quiet_NaN();
    s.cameras.push_back(lost);
    const auto notes = repairSceneValues(s);
    ASSERT_EQ(s.cameras.size(), 2u);
    EXPECT_EQ(s.cameras[0].up, glm::vec3(0, 0, 1));
    EXPECT_FLOAT_EQ(s.cameras[1].fovY, 1e-4f);
    EXPECT_EQ(s.cameras[1].farPlane, 1e18f);
    EXPECT_GE(double(s.cameras[1].farPlane) / double(s.cameras[1].nearPlane), 1e7);
    for (const Camera& c : s.cameras)
        EXPECT_FALSE(checkCamera(c).has_value()) << c.name << ": " << checkCamera(c)->message;
    ASSERT_EQ(notes.size(), 4u);
    EXPECT_EQ(notes[0],
              "camera 'Camera01': the up vector was zero, not finite or parallel to the view direction; "
              "set to (0, 0, 1)");
    EXPECT_NE(notes[3].find("camera 'lost': position or target not finite"), std::string::npos) << notes[3];
    EXPECT_TRUE(validateSceneContent(s, "repaired.3ds"));
}

TEST(ValueRepair, ImportedLightsAndMaterialsAreBroughtUnderTheLimits) {
    Scene s;
    Light bright;
    bright.name = "sun";
    bright.intensity = kHuge;
    bright.direction = {0.0f, -kTiniest, 0.0f};
    s.lights.push_back(bright);
    s.materials.resize(1);
    s.materials[0].name = "glow";
    s.materials[0].diffuseColor = glm::vec3(kHuge);
    Light coloured;
    coloured.name = "coloured";
    coloured.color = {kHuge, kHuge / 2.0f, 0.0f};
    s.lights.push_back(coloured);
    const auto notes = repairSceneValues(s);
    ASSERT_EQ(notes.size(), 4u);
    EXPECT_EQ(s.lights[1].color, glm::vec3(1.0f, 0.5f, 0.0f));
    EXPECT_LE(double(s.lights[1].intensity), 1e30);
    EXPECT_GT(double(s.lights[1].intensity), 0.99e30);
    EXPECT_EQ(s.lights[0].direction, glm::vec3(0, -1, 0));
    EXPECT_LE(double(s.lights[0].intensity), 1e30);
    EXPECT_GT(double(s.lights[0].intensity), 0.99e30);
    EXPECT_EQ(s.materials[0].diffuseColor, glm::vec3(100.0f));
    EXPECT_TRUE(validateSceneContent(s, "repaired.3ds"));
}
