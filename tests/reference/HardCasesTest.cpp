// Numerical hard cases of the reference path tracer (issue #11 item 6, the
// reference's share): each asserts finiteness and a bound, with its reason.
#include "lpv/reference/PathTracer.h"
#include "lpv/scene/Primitives.h"

#include "ReferenceTestScenes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using namespace lpv;

scene::Scene plane(float size, float albedo = 0.5f) {
    scene::Scene s;
    s.meshes.push_back(scene::makePlane());
    scene::Material m;
    m.diffuseColor = glm::vec3(albedo);
    s.materials.push_back(m);
    scene::Object o;
    o.mesh = 0;
    o.transform.scale = glm::vec3(size, 1.0f, size);
    s.objects.push_back(o);
    return s;
}

reference::PathTracerSettings tiny() {
    reference::PathTracerSettings t;
    t.width = 8;
    t.height = 8;
    t.samplesPerPixel = 2;
    t.threads = 1;
    return t;
}

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Light is linear: 1e-6 and 1e6 suns give the same image up to the factor, no
// underflow to 0, no overflow to inf (float has 38 decades; these use 12).
TEST(ReferenceHardCases, ExtremeSunIntensitiesScaleLinearly) {
    scene::Camera c;
    c.position = {0.0f, 3.0f, 0.0f};
    c.target = {0.0f, 0.0f, 0.0f};
    c.up = {0.0f, 0.0f, -1.0f};
    std::vector<float> centre;
    for (float intensity : {1e-6f, 1.0f, 1e6f}) {
        scene::Scene s = plane(50.0f);
        scene::Light sun;
        sun.intensity = intensity;
        sun.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.0f));
        s.lights.push_back(sun);
        auto embree = reference::EmbreeScene::build(s, {});
        ASSERT_TRUE(embree);
        const auto image = reference::PathTracer(*embree, s, c, tiny()).render();
        for (const auto& p : image.image)
            ASSERT_TRUE(finite(p));
        centre.push_back(image.image[4 * 8 + 4].r / intensity);
    }
    EXPECT_GT(centre[1], 0.0f);
    EXPECT_NEAR(centre[0] / centre[1], 1.0f, 1e-5f);
    EXPECT_NEAR(centre[2] / centre[1], 1.0f, 1e-5f);
}

// A sun 0.05 degrees above the horizon: E cos(89.95 deg) is tiny but positive
// and exact to float precision; a sun 0.05 degrees below gives exactly 0.
TEST(ReferenceHardCases, GrazingSunGivesECosThetaAndNothingBelowTheHorizon) {
    scene::Scene s = plane(1000.0f);
    const float below = glm::radians(0.05f);
    scene::Light sun;
    sun.direction = glm::vec3(std::cos(below), -std::sin(below), 0.0f);
    s.lights.push_back(sun);
    auto embree = reference::EmbreeScene::build(s, {});
    ASSERT_TRUE(embree);
    const reference::PathTracer tracer(*embree, s, scene::Camera{}, tiny());
    const glm::vec3 e = tracer.directIrradiance({0, 0, 0}, {0, 1, 0}, {0, 1, 0});
    EXPECT_NEAR(e.r, std::sin(below), 1e-6f);
    EXPECT_GT(e.r, 0.0f);
    s.lights[0].direction.y = std::sin(below);
    const reference::PathTracer under(*embree, s, scene::Camera{}, tiny());
    EXPECT_EQ(under.directIrradiance({0, 0, 0}, {0, 1, 0}, {0, 1, 0}), glm::vec3(0.0f));
}

// Two planes 1 mm apart in a scene 100 m across (ray offset 1e-4 of the
// diagonal = 14 mm would jump the gap if it were applied toward the light
// from the lower plane's far side): the lower plane stays in full shadow.
TEST(ReferenceHardCases, ThinWallDoesNotLeakSunlight) {
    scene::Scene s = plane(100.0f);
    scene::Object roof = s.objects.front();
    roof.transform.translation.y = 0.001f;
    roof.transform.scale = glm::vec3(10.0f, 1.0f, 10.0f);
    s.objects.push_back(roof);
    scene::Light sun;
    s.lights.push_back(sun); // straight down
    auto embree = reference::EmbreeScene::build(s, {});
    ASSERT_TRUE(embree);
    const reference::PathTracer tracer(*embree, s, scene::Camera{}, tiny());
    // Under the roof, on the lower plane's upper side: the shadow ray starts
    // above the lower plane and must still hit the roof 1 mm up.
    EXPECT_EQ(tracer.directIrradiance({1.0f, 0.0f, 1.0f}, {0, 1, 0}, {0, 1, 0}), glm::vec3(0.0f));
    EXPECT_NEAR(tracer.directIrradiance({8.0f, 0.0f, 8.0f}, {0, 1, 0}, {0, 1, 0}).r, 1.0f, 1e-6f);
}

// A camera 10 km from a 2 m object: float positions keep 1 mm there, the
// object still covers the same pixels, and nothing becomes NaN.
TEST(ReferenceHardCases, FarCameraStaysFinite) {
    scene::Scene s;
    s.meshes.push_back(scene::makeBox());
    scene::Object o;
    o.mesh = 0;
    o.transform.scale = glm::vec3(2.0f);
    s.objects.push_back(o);
    scene::Light sun;
    sun.direction = glm::normalize(glm::vec3(-1.0f, -1.0f, -1.0f));
    s.lights.push_back(sun);
    scene::Camera c;
    c.position = {0.0f, 0.0f, 1e4f};
    c.fovY = 0.0004f; // 4 m wide at 10 km
    c.farPlane = 2e4f;
    auto embree = reference::EmbreeScene::build(s, {});
    ASSERT_TRUE(embree);
    const auto image = reference::PathTracer(*embree, s, c, tiny()).render();
    int covered = 0;
    for (std::size_t i = 0; i < image.pixelCount(); ++i) {
        ASSERT_TRUE(finite(image.image[i]) && finite(image.indirectMulti[i]));
        covered += image.coverage[i] > 0.5f;
    }
    // The box spans half the 4 m view: 4x4 of the 8x8 pixels.
    EXPECT_EQ(covered, 16);
}

// Reflectance near 1 in a closed box: multi-bounce light grows like 1 / (1 - a)
// (100x at a = 0.99); with 64 bounces and Russian roulette the estimate stays
// finite and below the infinite-bounce bound.
TEST(ReferenceHardCases, NearOneReflectanceStaysFiniteAndBounded) {
    const scene::Scene s = test::furnaceBox(0.99f, 1.0f);
    scene::Camera c;
    c.position = {0.0f, 0.0f, 1.0f};
    auto settings = tiny();
    settings.bounces = 64;
    settings.samplesPerPixel = 16;
    settings.emissiveLight = true;
    auto embree = reference::EmbreeScene::build(s, {});
    ASSERT_TRUE(embree);
    const auto image = reference::PathTracer(*embree, s, c, settings).render();
    double mean = 0.0;
    for (const auto& p : image.image) {
        ASSERT_TRUE(finite(p));
        mean += p.r;
    }
    mean /= double(image.pixelCount());
    // Exact with 64 bounces: sum_{k=0}^{64} 0.99^k = 47.8; Russian roulette keeps the mean, not each sample.
    const double exact = (1.0 - std::pow(0.99, 65)) / 0.01;
    EXPECT_GT(mean, 0.5 * exact);
    EXPECT_LT(mean, 2.0 * exact);
}

} // namespace
