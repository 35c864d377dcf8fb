// The sun `lpv import` adds to a scene without lights (issue #22): the
// candidate direction that lights the most of what the camera sees.
#include "lpv/reference/SunPlacement.h"
#include "lpv/scene/Primitives.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using namespace lpv;

// A floor with a 10 m wall just beyond (+z of) the patch the camera looks down at.
scene::Scene walledFloor() {
    scene::Scene s;
    s.meshes = {scene::makePlane(), scene::makeBox()};
    s.materials.emplace_back();
    scene::Object floor;
    floor.mesh = 0;
    floor.transform.scale = glm::vec3(40.0f, 1.0f, 40.0f);
    scene::Object wall;
    wall.mesh = 1;
    wall.transform.translation = {0.0f, 5.0f, 2.0f};
    wall.transform.scale = {40.0f, 10.0f, 0.2f};
    s.objects = {floor, wall};
    return s;
}

scene::Camera lookingDown() {
    scene::Camera c;
    c.position = {0.0f, 4.0f, -0.5f};
    c.target = {0.0f, 0.0f, -0.5f};
    c.up = {0.0f, 0.0f, -1.0f};
    c.fovY = 0.6f;
    return c;
}

glm::vec3 fromAzimuthElevation(float azimuthDegrees, float elevationDegrees) {
    const float az = glm::radians(azimuthDegrees), el = glm::radians(elevationDegrees);
    return -glm::vec3(std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az));
}

} // namespace

TEST(SunPlacement, TheChosenSunLightsWhatTheWallWouldShadow) {
    const scene::Scene s = walledFloor();
    auto embree = reference::EmbreeScene::build(s, {});
    ASSERT_TRUE(embree) << embree.error().describe();
    // A low sun from behind the wall (+z) leaves the patch in its shadow...
    const reference::SunChoice behind = reference::sunlitShare(*embree, lookingDown(), fromAzimuthElevation(0.0f, 20.0f));
    EXPECT_GT(behind.viewHits, 1000);
    EXPECT_LT(behind.litFraction, 0.05f);
    // ... so the choice, starting from that direction, moves the sun and lights all of it.
    const reference::SunChoice best =
        reference::chooseSunDirection(*embree, lookingDown(), fromAzimuthElevation(0.0f, 20.0f));
    EXPECT_GT(best.litFraction, 0.99f);
    EXPECT_LT(-best.direction.z, 0.5f) << "not from behind the wall";
    EXPECT_NEAR(glm::length(best.direction), 1.0f, 1e-5f);
}

TEST(SunPlacement, AFallbackThatLightsEverythingIsKept) {
    const scene::Scene s = walledFloor();
    auto embree = reference::EmbreeScene::build(s, {});
    ASSERT_TRUE(embree);
    const glm::vec3 overhead{0.0f, -1.0f, 0.0f};
    const reference::SunChoice best = reference::chooseSunDirection(*embree, lookingDown(), overhead);
    EXPECT_GT(best.litFraction, 0.99f);
    EXPECT_EQ(best.direction, overhead) << "ties go to the direction used so far";
    EXPECT_NEAR(best.elevationDegrees, 90.0f, 1e-3f);
}
