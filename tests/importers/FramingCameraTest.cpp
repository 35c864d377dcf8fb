// The camera `lpv render` and the editor use for a project without one: inside
// enclosed real scenes, outside a lone object.
#include "TestPaths.h"

#include "lpv/importers/Importer.h"
#include "lpv/scene/FramingCamera.h"

#include <gtest/gtest.h>

#include <filesystem>

using namespace lpv;

namespace {

bool inside(const scene::Bounds& b, const glm::vec3& p) {
    return glm::all(glm::greaterThan(p, b.min)) && glm::all(glm::lessThan(p, b.max));
}

scene::Scene importShared(const char* relative) {
    auto r = importers::importScene(std::filesystem::path(test::kSharedScenesDir) / relative);
    EXPECT_TRUE(r.has_value()) << (r ? "" : r.error().describe());
    return r ? std::move(r->scene) : scene::Scene{};
}

} // namespace

TEST(FramingCamera, StandsInsideSponzaLookingAlongItsLength) {
    const scene::Scene s = importShared("sponza/sponza.obj");
    EXPECT_TRUE(scene::isEnclosed(s));
    const scene::Camera cam = scene::framingCamera(s);
    const scene::Bounds b = s.worldBounds();
    EXPECT_TRUE(inside(b, cam.position)) << cam.position.x << " " << cam.position.y << " " << cam.position.z;
    const glm::vec3 look = glm::normalize(cam.target - cam.position);
    EXPECT_GT(std::abs(look.x), 0.9f) << "Sponza is longest along X";
}

TEST(FramingCamera, StandsInsideSibenik) {
    const scene::Scene s = importShared("sibenik/sibenik.obj");
    EXPECT_TRUE(scene::isEnclosed(s));
    EXPECT_TRUE(inside(s.worldBounds(), scene::framingCamera(s).position));
}

TEST(FramingCamera, LooksAtALoneObjectFromOutside) {
    const scene::Scene s = importShared("4ds/bunny00.4ds");
    EXPECT_FALSE(scene::isEnclosed(s));
    const scene::Camera cam = scene::framingCamera(s);
    EXPECT_FALSE(inside(s.worldBounds(), cam.position));
    EXPECT_LT(glm::length(cam.target - s.worldBounds().center()), 1e-3f);
}
