// No NaN or infinity reaches Embree (issue #42): Assimp's 3DS camera test
// models gave a camera whose up vector lay along its view, its rays were
// NaN, and Embree's `Assertion 'ray.valid()' failed` aborted `lpv import`
// while it placed the added sun. A camera with any NaN field now yields no
// ray, and EmbreeScene refuses a ray Embree would assert on.
#include "lpv/reference/CameraRays.h"
#include "lpv/reference/EmbreeScene.h"
#include "lpv/reference/SunPlacement.h"
#include "lpv/scene/Primitives.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

namespace {

using namespace lpv;

constexpr float kNan = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Every field of a camera set to NaN or infinity in turn, and the 3DS case.
std::vector<scene::Camera> brokenCameras() {
    std::vector<scene::Camera> out;
    for (const float bad : {kNan, kInf, -kInf})
        for (int field = 0; field < 12; ++field) {
            scene::Camera c;
            switch (field) {
            case 0:
                c.position.x = bad;
                break;
            case 1:
                c.position.z = bad;
                break;
            case 2:
                c.target.y = bad;
                break;
            case 3:
                c.target.z = bad;
                break;
            case 4:
                c.up.x = bad;
                break;
            case 5:
                c.up.y = bad;
                break;
            case 6:
                c.fovY = bad;
                break;
            case 7:
                c.nearPlane = bad;
                break;
            case 8:
                c.farPlane = bad;
                break;
            case 9:
                c.position = glm::vec3(bad);
                break;
            case 10:
                c.up = glm::vec3(bad);
                break;
            default:
                c.nearPlane = c.farPlane = bad;
                break;
            }
            out.push_back(c);
        }
    scene::Camera upAlongView; // CameraRollAnim.3ds before the importer's fix
    upAlongView.position = {0, 0, 0};
    upAlongView.target = {0, 1, 0};
    out.push_back(upAlongView);
    return out;
}

} // namespace

TEST(CameraRays, ACameraWithNanFieldsCannotProduceANonFiniteRay) {
    int rays = 0;
    for (const scene::Camera& c : brokenCameras())
        for (const float x : {-1.0f, -0.3f, 0.0f, 0.7f, 1.0f})
            for (const float y : {-1.0f, 0.0f, 0.5f}) {
                const auto ray = reference::CameraRays(c, 16.0f / 9.0f).through(x, y);
                if (!ray)
                    continue;
                ++rays;
                EXPECT_TRUE(finite(ray->origin) && finite(ray->direction) && std::isfinite(ray->length));
                EXPECT_TRUE(reference::embreeAcceptsRay(ray->origin, ray->direction, 0.0f, ray->length));
            }
    // Some broken cameras (an infinite far plane) still give finite rays; none gives a bad one.
    std::printf("[ figures ] %d finite rays from %zu broken cameras\n", rays, brokenCameras().size());
}

TEST(CameraRays, AGoodCameraGivesUnitRaysFromTheNearPlane) {
    scene::Camera c;
    const auto ray = reference::CameraRays(c, 1.0f).through(0.0f, 0.0f);
    ASSERT_TRUE(ray.has_value());
    EXPECT_NEAR(ray->origin.z, 5.0f - c.nearPlane, 1e-5f);
    EXPECT_NEAR(glm::length(ray->direction), 1.0f, 1e-6f);
    EXPECT_NEAR(ray->direction.z, -1.0f, 1e-6f);
    // The far point comes through the inverse projection in float: 1e-4 relative.
    EXPECT_NEAR(ray->length, c.farPlane - c.nearPlane, 1e-4f * c.farPlane);
}

TEST(CameraRays, EmbreeSceneRefusesRaysEmbreeWouldAssertOn) {
    scene::Scene s;
    s.meshes = {scene::makeBox()};
    s.materials.emplace_back();
    scene::Object box;
    box.mesh = 0;
    s.objects = {box};
    const auto embree = reference::EmbreeScene::build(s, {});
    ASSERT_TRUE(embree.has_value());
    const glm::vec3 origin(0, 0, 5), dir(0, 0, -1);
    ASSERT_TRUE(embree->intersect(origin, dir, 0.0f, 100.0f).has_value()); // the box is there
    EXPECT_FALSE(reference::embreeAcceptsRay({kNan, 0, 5}, dir, 0.0f, 100.0f));
    EXPECT_FALSE(reference::embreeAcceptsRay(origin, {0, 0, -kInf}, 0.0f, 100.0f));
    EXPECT_FALSE(reference::embreeAcceptsRay({2e18f, 0, 0}, dir, 0.0f, 100.0f));
    EXPECT_FALSE(reference::embreeAcceptsRay(origin, dir, kNan, 100.0f));
    EXPECT_TRUE(reference::embreeAcceptsRay(origin, dir, 0.0f, kInf));
    // Without the guard each of these aborted the process in a debug Embree.
    EXPECT_FALSE(embree->intersect({kNan, 0, 5}, dir, 0.0f, 100.0f).has_value());
    EXPECT_FALSE(embree->intersect(origin, glm::vec3(kNan), 0.0f, 100.0f).has_value());
    EXPECT_TRUE(embree->occluded(origin, glm::vec3(kNan), 0.0f, 100.0f)); // no light along no direction
}

TEST(CameraRays, SunPlacementWithABrokenCameraStaysFinite) {
    scene::Scene s;
    s.meshes = {scene::makePlane()};
    s.materials.emplace_back();
    scene::Object floor;
    floor.mesh = 0;
    floor.transform.scale = glm::vec3(40.0f, 1.0f, 40.0f);
    s.objects = {floor};
    const auto embree = reference::EmbreeScene::build(s, {});
    ASSERT_TRUE(embree.has_value());
    for (const scene::Camera& c : brokenCameras()) {
        const glm::vec3 fallback = glm::normalize(glm::vec3(-0.35f, -1.0f, -0.25f));
        const reference::SunChoice choice = reference::chooseSunDirection(*embree, c, fallback);
        EXPECT_TRUE(finite(choice.direction));
        EXPECT_TRUE(std::isfinite(choice.litFraction));
    }
}
