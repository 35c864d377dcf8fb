// The lights' direct light at the patches (issue #27 item 2): the values of
// the reference's light model, shadows, and a session that a sun alone lights.
#include "RadiosityTestScenes.h"

#include "lpv/radiosity/DirectLight.h"
#include "lpv/radiosity/RadiositySession.h"
#include "lpv/scene/CornellBox.h"

#include <gtest/gtest.h>

#include <numbers>

using namespace lpv;

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

scene::Light sun(const glm::vec3& direction, float intensity) {
    scene::Light l;
    l.type = scene::LightType::Directional;
    l.direction = glm::normalize(direction);
    l.intensity = intensity;
    return l;
}

} // namespace

TEST(DirectLight, SamplePointsLieOnThePatchAndAverageToItsCentre) {
    const auto mesh = radiosity::buildPatchMesh(test::parallelSquares(), {1.0f});
    for (const auto& p : mesh.patches) {
        const auto points = radiosity::patchSamplePoints(p, 9);
        ASSERT_EQ(points.size(), 9u);
        glm::vec3 mean(0.0f);
        for (const glm::vec3& q : points) {
            EXPECT_NEAR(glm::dot(q - p.center, p.normal), 0.0f, 1e-6f);
            mean += q / 9.0f;
        }
        if (p.cornerCount == 4) {
            EXPECT_LT(glm::distance(mean, p.center), 1e-5f);
        }
    }
}

TEST(DirectLight, ASunDeliversItsIrradianceTimesTheCosineAndShadows) {
    // Two parallel squares facing each other; a sun 30 degrees off the lower
    // square's normal. The upper square faces away from it: it gets nothing;
    // the lower one is shadowed by the upper where the sun's rays pass
    // through it (y below about 0.42).
    scene::Scene s = test::parallelSquares();
    s.lights = {sun({0.0f, -0.5f, -std::sqrt(3.0f) / 2.0f}, 3.0f)}; // travels toward -z, tilted toward -y
    const auto mesh = radiosity::buildPatchMesh(s, {0.01f});
    const auto direct = radiosity::directLight(mesh, s, {}, 4);
    ASSERT_TRUE(direct.has_value()) << direct.error().describe();
    const float cosine = std::sqrt(3.0f) / 2.0f;
    int lit = 0, shadowed = 0;
    for (std::size_t i = 0; i < mesh.size(); ++i) {
        const auto& p = mesh.patches[i];
        const float e = (*direct)[i].y * kPi;
        if (p.object == 1) {
            EXPECT_EQ(e, 0.0f) << "the upper square faces away from the sun";
            continue;
        }
        // The lower square (z = 0) is hidden where its ray toward the sun
        // crosses the upper square (z = 1) inside [0, 1]^2.
        const glm::vec3 towardSun = -s.lights[0].direction;
        const glm::vec3 atUpper = p.center + towardSun * (1.0f / towardSun.z);
        const bool hidden = atUpper.x > 0.02f && atUpper.x < 0.98f && atUpper.y > 0.02f && atUpper.y < 0.98f;
        const bool open = atUpper.x < -0.02f || atUpper.x > 1.02f || atUpper.y < -0.02f || atUpper.y > 1.02f;
        if (hidden) {
            EXPECT_EQ(e, 0.0f) << "patch at " << p.center.x << ", " << p.center.y;
            ++shadowed;
        } else if (open) {
            EXPECT_NEAR(e, 3.0f * cosine, 1e-4f) << "patch at " << p.center.x << ", " << p.center.y;
            ++lit;
        }
    }
    EXPECT_GT(lit, 10);
    EXPECT_GT(shadowed, 10);
}

TEST(DirectLight, APointLightFallsOffWithTheSquareOfTheDistance) {
    scene::Scene s = test::parallelSquares();
    scene::Light point;
    point.type = scene::LightType::Point;
    point.position = {0.5f, 0.5f, 0.5f};
    point.intensity = 2.0f;
    s.lights = {point};
    const auto mesh = radiosity::buildPatchMesh(s, {0.01f});
    const auto direct = radiosity::directLight(mesh, s, {}, 1);
    ASSERT_TRUE(direct.has_value()) << direct.error().describe();
    for (std::size_t i = 0; i < mesh.size(); ++i) {
        const auto& p = mesh.patches[i];
        const glm::vec3 d = point.position - p.center;
        const float r2 = glm::dot(d, d);
        const float expected = 2.0f * glm::dot(p.normal, glm::normalize(d)) / r2;
        EXPECT_NEAR((*direct)[i].x * kPi, expected, 1e-3f * expected) << "patch " << i;
    }
}

TEST(DirectLight, ASunLitSceneWithoutEmittersSolves) {
    // The Cornell box with its lamp replaced by a sun shining in through the
    // open front (z = 0, the camera stands at z = -8): no emissive surface at
    // all, and the solve still has light.
    scene::Project project = scene::makeCornellBoxProject();
    for (scene::Material& m : project.scene.materials)
        m.emissive = glm::vec3(0.0f);
    project.scene.lights = {sun({0.3f, -0.5f, 1.0f}, 4.0f)};
    auto session = radiosity::RadiositySession::create(project.scene, {}, 0.5f, 1000000);
    ASSERT_TRUE(session.has_value()) << session.error().describe();
    EXPECT_GT(session->directLightSeconds(), 0.0);
    const auto& state = session->solver().state();
    double direct = 0.0;
    for (const glm::vec3& d : state.direct)
        direct += d.x + d.y + d.z;
    EXPECT_GT(direct, 0.0);
    EXPECT_GT(session->solver().residual(), 0.5); // all of it unshot yet: the patches reflect it next
    const auto& b = state.balance;
    EXPECT_NEAR((b.absorbed + session->solver().unshotPower()).y, b.emitted.y, 1e-6 * b.emitted.y);
    for (const glm::vec3& i : state.incident)
        EXPECT_EQ(i, glm::vec3(0.0f)); // nothing shot yet: the direct light is kept apart
}
