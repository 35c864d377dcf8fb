// Area lights in the project format (version 2): a round trip keeps every
// field, a version-1 file still loads (and is written back as version 2), and
// each bad value gets its own error naming the field.
#include "ProjectTestSupport.h"

#include "lpv/scene/Project.h"

#include <gtest/gtest.h>

#include <limits>

using namespace lpv::scene;
using namespace lpv::test;

namespace {

Light areaLight(AreaShape shape) {
    Light l;
    l.name = shape == AreaShape::Disc ? "disc" : "panel";
    l.type = LightType::Area;
    l.shape = shape;
    l.size = {1.3f, 1.05f};
    l.radius = 0.4f;
    l.position = {2.78f, 5.487f, 2.795f};
    l.direction = {0.0f, -1.0f, 0.0f};
    l.tangent = {0.0f, 0.0f, 1.0f};
    l.color = {1.0f, 0.7f, 0.25f};
    l.intensity = 17.0f;
    l.twoSided = shape == AreaShape::Disc;
    l.unit = shape == AreaShape::Disc ? AreaUnit::Power : AreaUnit::Radiance;
    return l;
}

class AreaLightProject : public TempDirTest {
protected:
    AreaLightProject() : TempDirTest("lpv-area-") {}

    // Saves a project with `light`, replaces `from` by `to` in the file, loads it.
    Expected<Project> saveEditLoad(const Light& light, const std::string& from, const std::string& to) {
        Project p;
        p.name = "area";
        p.scene.lights = {light};
        const auto file = dir_ / "p.lpvproj";
        EXPECT_TRUE(saveProject(p, file).has_value());
        std::string text = readFile(file);
        const std::size_t at = text.find(from);
        EXPECT_NE(at, std::string::npos) << from << " not in\n" << text;
        if (at != std::string::npos)
            text.replace(at, from.size(), to);
        writeFile(file, text);
        return loadProject(file);
    }
};

} // namespace

TEST_F(AreaLightProject, EveryFieldSurvivesARoundTrip) {
    Project p;
    p.name = "area";
    p.scene.lights = {areaLight(AreaShape::Rectangle), areaLight(AreaShape::Disc)};
    ASSERT_TRUE(saveProject(p, dir_ / "p.lpvproj").has_value());
    const auto loaded = loadProject(dir_ / "p.lpvproj");
    ASSERT_TRUE(loaded.has_value()) << loaded.error().describe();
    EXPECT_EQ(loaded->scene.lights, p.scene.lights);
    const std::string text = readFile(dir_ / "p.lpvproj");
    EXPECT_NE(text.find("\"version\": 2,"), std::string::npos);
    EXPECT_NE(text.find("\"type\": \"area\""), std::string::npos);
    EXPECT_NE(text.find("\"unit\": \"power\""), std::string::npos);
}

TEST_F(AreaLightProject, AVersionOneFileLoadsAndIsWrittenAsVersionTwo) {
    Light spot;
    spot.name = "spot";
    spot.type = LightType::Spot;
    const auto loaded = saveEditLoad(spot, "\"version\": 2,", "\"version\": 1,");
    ASSERT_TRUE(loaded.has_value()) << loaded.error().describe();
    EXPECT_EQ(loaded->scene.lights.at(0).type, LightType::Spot);
    ASSERT_TRUE(saveProject(*loaded, dir_ / "again.lpvproj").has_value());
    EXPECT_NE(readFile(dir_ / "again.lpvproj").find("\"version\": 2,"), std::string::npos);
}

TEST_F(AreaLightProject, ZeroOrNegativeSizeIsAnErrorNamingTheField) {
    for (const auto& [from, to, location] :
         {std::tuple{"\"size\": [\n        1.3,", "\"size\": [\n        0,", "lights[0].size[0]"},
          std::tuple{"1.05\n      ]", "-2\n      ]", "lights[0].size[1]"}}) {
        const auto loaded = saveEditLoad(areaLight(AreaShape::Rectangle), from, to);
        ASSERT_FALSE(loaded.has_value()) << from;
        EXPECT_EQ(loaded.error().code, ErrorCode::OutOfRange) << loaded.error().describe();
        EXPECT_EQ(loaded.error().location, location) << loaded.error().describe();
    }
}

TEST_F(AreaLightProject, ADiscWithZeroRadiusIsAnError) {
    const auto loaded = saveEditLoad(areaLight(AreaShape::Disc), "\"radius\": 0.4", "\"radius\": 0");
    ASSERT_FALSE(loaded.has_value());
    EXPECT_EQ(loaded.error().code, ErrorCode::OutOfRange) << loaded.error().describe();
    EXPECT_EQ(loaded.error().location, "lights[0].radius");
}

TEST_F(AreaLightProject, NanRadianceIsAnError) {
    // JSON has no NaN; a float too large for the format is the closest a file can get, and NaN
    // written by hand (an extension some writers emit) must fail the parse.
    auto loaded = saveEditLoad(areaLight(AreaShape::Rectangle), "\"intensity\": 17.0", "\"intensity\": NaN");
    ASSERT_FALSE(loaded.has_value());
    loaded = saveEditLoad(areaLight(AreaShape::Rectangle), "\"intensity\": 17.0", "\"intensity\": 1e39");
    ASSERT_FALSE(loaded.has_value());
    EXPECT_EQ(loaded.error().location, "lights[0].intensity") << loaded.error().describe();
}

TEST_F(AreaLightProject, ATangentAlongTheDirectionIsAnError) {
    const auto loaded = saveEditLoad(areaLight(AreaShape::Rectangle), "\"tangent\": [\n        0.0,\n        0.0,\n        1.0",
                                     "\"tangent\": [\n        0.0,\n        -2.0,\n        0.0");
    ASSERT_FALSE(loaded.has_value());
    EXPECT_EQ(loaded.error().location, "lights[0].tangent") << loaded.error().describe();
    EXPECT_NE(loaded.error().message.find("not along its direction"), std::string::npos);
}
