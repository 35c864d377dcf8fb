// The path tracer against analytic answers (pbrt's habit): a lit plane's
// direct irradiance is E cos(theta), a closed emitting box of albedo a (a
// furnace) converges to Le / (1 - a), masked texels let rays through, and
// the image does not depend on the number of threads.
#include "lpv/reference/PathTracer.h"
#include "GreyFloor.h"
#include "ReferenceTestScenes.h"
#include "lpv/scene/CornellBox.h"
#include "lpv/scene/Primitives.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using namespace lpv;
constexpr float kPi = 3.14159265358979f;

scene::Scene planeScene(float albedo) { return test::greyFloor(albedo, 100.0f); }

reference::PathTracerSettings small(int spp, int bounces = 4) {
    reference::PathTracerSettings s;
    s.width = 16;
    s.height = 16;
    s.samplesPerPixel = spp;
    s.bounces = bounces;
    s.threads = 2;
    return s;
}

TEST(PathTracer, LitPlaneDirectIrradianceIsECosTheta) {
    scene::Scene s = planeScene(0.5f);
    scene::Light sun;
    sun.intensity = 3.0f;
    const float theta = 0.6f;
    sun.direction = glm::normalize(glm::vec3(std::sin(theta), -std::cos(theta), 0.0f));
    s.lights.push_back(sun);
    auto embree = reference::EmbreeScene::build(s, {});
    ASSERT_TRUE(embree) << embree.error().describe();
    const reference::PathTracer tracer(*embree, s, test::lookingDown(), small(4));
    const glm::vec3 e = tracer.directIrradiance({1.0f, 0.0f, 2.0f}, {0, 1, 0}, {0, 1, 0});
    EXPECT_NEAR(e.x, 3.0f * std::cos(theta), 1e-5f);

    // Lambertian, nothing to bounce off: radiance = albedo / pi * E cos, indirect exactly 0.
    const reference::ReferenceImage image = tracer.render();
    ASSERT_EQ(image.samplesPerPixel, 4);
    const std::size_t centre = 8 * 16 + 8;
    EXPECT_FLOAT_EQ(image.coverage[centre], 1.0f);
    EXPECT_NEAR(image.image[centre].g, 0.5f / kPi * 3.0f * std::cos(theta), 1e-5f);
    EXPECT_EQ(image.indirectMulti[centre], glm::vec3(0.0f));
    EXPECT_EQ(image.imageVariance[centre], glm::vec3(0.0f));
}

TEST(PathTracer, PointLightFallsOffWithDistanceSquaredAndShadows) {
    scene::Scene s = planeScene(0.5f);
    scene::Light point;
    point.type = scene::LightType::Point;
    point.intensity = 8.0f;
    point.position = {0.0f, 2.0f, 0.0f};
    s.lights.push_back(point);
    // A small box between the light and (0, 0, 0) casts a shadow there, not at (1.5, 0, 0).
    s.meshes.push_back(scene::makeBox());
    scene::Object blocker;
    blocker.mesh = 1;
    blocker.transform.translation = {0.0f, 1.0f, 0.0f};
    blocker.transform.scale = glm::vec3(0.2f);
    s.objects.push_back(blocker);
    auto embree = reference::EmbreeScene::build(s, {});
    ASSERT_TRUE(embree);
    const reference::PathTracer tracer(*embree, s, test::lookingDown(), small(1));
    EXPECT_EQ(tracer.directIrradiance({0, 0, 0}, {0, 1, 0}, {0, 1, 0}), glm::vec3(0.0f));
    const glm::vec3 p{1.5f, 0.0f, 0.0f};
    const float d2 = glm::dot(point.position - p, point.position - p);
    const float cosTheta = 2.0f / std::sqrt(d2);
    EXPECT_NEAR(tracer.directIrradiance(p, {0, 1, 0}, {0, 1, 0}).r, 8.0f / d2 * cosTheta, 1e-4f);
}

// The camera inside a closed box whose walls all emit Le and reflect a:
// L = Le (1 + a + a^2 + ...) = Le / (1 - a); the irradiance at any wall from
// the others is pi Le after one bounce and pi Le (1 + ... + a^(B-1)) after B.
TEST(PathTracer, FurnaceBoxConvergesToAnalyticRadiance) {
    const float a = 0.5f, le = 1.0f;
    const scene::Scene s = test::furnaceBox(a, le);
    scene::Camera c;
    c.position = {0.0f, 0.0f, 1.0f};
    c.target = {0.0f, 0.0f, -1.0f};
    auto embree = reference::EmbreeScene::build(s, {});
    ASSERT_TRUE(embree);
    const int bounces = 40;
    auto settings = small(64, bounces);
    settings.emissiveLight = true;
    const reference::ReferenceImage image = reference::PathTracer(*embree, s, c, settings).render();
    settings.emissiveLight = false; // the renderer's convention: emission is seen, it lights nothing
    const reference::ReferenceImage seen = reference::PathTracer(*embree, s, c, settings).render();
    EXPECT_EQ(seen.image[0], glm::vec3(le));
    EXPECT_EQ(seen.indirectMulti[0], glm::vec3(0.0f));
    double sumImage = 0.0, sumOne = 0.0, sumMulti = 0.0, sumVar = 0.0, sumVarOne = 0.0;
    for (std::size_t i = 0; i < image.pixelCount(); ++i) {
        ASSERT_EQ(image.coverage[i], 1.0f);
        sumImage += image.image[i].r;
        sumOne += image.indirectOne[i].r;
        sumMulti += image.indirectMulti[i].r;
        sumVar += image.imageVariance[i].r;
        sumVarOne += image.indirectOneVariance[i].r;
    }
    const double n = double(image.pixelCount());
    // Light reflected once: the walls' emission (E = pi Le at a wall) reflected by a wall,
    // pi a Le; the wall's direct light itself is not indirect. The emitters are sampled by
    // area, so the estimate has its own noise (4 standard errors).
    EXPECT_NEAR(sumOne / n, kPi * a * le, 4.0 * std::sqrt(sumVarOne / n / n) + 1e-4);
    // The mean over pixels has standard error sqrt(mean variance / n); allow 4 of them plus the a^40 tail.
    const double tolerance = 4.0 * std::sqrt(sumVar / n / n) + 1e-6;
    const double expected = le / (1.0 - a);
    EXPECT_NEAR(sumImage / n, expected, tolerance);
    // Every reflected order: pi Le (a + a^2 + ...) = pi Le a / (1 - a).
    EXPECT_NEAR(sumMulti / n, kPi * le * a / (1.0 - a), kPi * tolerance / a);
    EXPECT_GT(sumVar, 0.0)
        << "Russian roulette makes the multi-bounce estimate noisy; its variance must show it";
}

TEST(PathTracer, OneBounceIsMultiBounceWithOneBounce) {
    scene::Project cornell = scene::makeCornellBoxProject();
    auto embree = reference::EmbreeScene::build(cornell.scene, {});
    ASSERT_TRUE(embree);
    ASSERT_FALSE(cornell.scene.cameras.empty());
    auto settings = small(2, 1);
    const reference::ReferenceImage image =
        reference::PathTracer(*embree, cornell.scene, cornell.scene.cameras.front(), settings).render();
    double lit = 0.0;
    for (std::size_t i = 0; i < image.pixelCount(); ++i) {
        EXPECT_EQ(image.indirectOne[i], image.indirectMulti[i]);
        EXPECT_TRUE(std::isfinite(image.image[i].r));
        lit += image.indirectOne[i].g;
    }
    EXPECT_GT(lit, 0.0) << "the Cornell box's sunlit walls must light each other";
}

TEST(PathTracer, SameImageWhateverTheThreadCount) {
    scene::Project cornell = scene::makeCornellBoxProject();
    auto embree = reference::EmbreeScene::build(cornell.scene, {});
    ASSERT_TRUE(embree);
    auto one = small(2, 3);
    one.threads = 1;
    auto three = one;
    three.threads = 3;
    const auto& camera = cornell.scene.cameras.front();
    const auto a = reference::PathTracer(*embree, cornell.scene, camera, one).render();
    const auto b = reference::PathTracer(*embree, cornell.scene, camera, three).render();
    EXPECT_EQ(a.image, b.image);
    EXPECT_EQ(a.indirectMulti, b.indirectMulti);
}

TEST(PathTracer, StopsAtTheTimeBudgetOrWhenTheCallbackSaysSo) {
    scene::Project cornell = scene::makeCornellBoxProject();
    auto embree = reference::EmbreeScene::build(cornell.scene, {});
    ASSERT_TRUE(embree);
    auto settings = small(1000, 2);
    settings.maxSeconds = 1e-9; // the first pass always runs, then the budget is spent
    const auto& camera = cornell.scene.cameras.front();
    EXPECT_EQ(reference::PathTracer(*embree, cornell.scene, camera, settings).render().samplesPerPixel, 1);
    settings.maxSeconds = 0.0;
    int calls = 0;
    const auto image = reference::PathTracer(*embree, cornell.scene, camera, settings)
                           .render([&](const reference::TraceProgress& p) {
                               ++calls;
                               EXPECT_EQ(p.samplesTarget, 1000);
                               return p.samplesDone < 3;
                           });
    EXPECT_EQ(image.samplesPerPixel, 3);
    EXPECT_EQ(calls, 3);
}

TEST(PathTracer, MaskedTexelsLetRaysThrough) {
    // A fully transparent masked plane above a lit plane: the sun still reaches the lower one.
    scene::Scene s = planeScene(0.5f);
    scene::Material hole;
    hole.alphaMode = scene::AlphaMode::Mask;
    hole.opacity = 0.0f;
    s.materials.push_back(hole);
    scene::Mesh cover = scene::makePlane();
    cover.submeshes.front().materialIndex = 1;
    s.meshes.push_back(cover);
    scene::Object o;
    o.mesh = 1;
    o.transform.translation = {0.0f, 1.0f, 0.0f};
    o.transform.scale = glm::vec3(50.0f, 1.0f, 50.0f);
    s.objects.push_back(o);
    scene::Light sun;
    s.lights.push_back(sun);
    auto embree = reference::EmbreeScene::build(s, {});
    ASSERT_TRUE(embree);
    const reference::PathTracer tracer(*embree, s, test::lookingDown(), small(1));
    EXPECT_NEAR(tracer.directIrradiance({0, 0, 0}, {0, 1, 0}, {0, 1, 0}).r, 1.0f, 1e-6f);
    const auto hit = embree->intersect({0, 5, 0}, {0, -1, 0}, 0.0f, 100.0f);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->position.y, 0.0f, 1e-5f);
}

TEST(EmbreeScene, LeavesOutNonFiniteTriangles) {
    scene::Scene s = planeScene(0.5f);
    scene::Mesh bad = scene::makePlane();
    bad.positions[0] = glm::vec3(std::nanf(""), 0.0f, 0.0f);
    s.meshes.push_back(bad);
    scene::Object o;
    o.mesh = 1;
    s.objects.push_back(o);
    std::size_t clean = 0; // triangles of the bad plane that do not use vertex 0
    for (std::size_t k = 0; k < bad.indices.size(); k += 3)
        clean += bad.indices[k] != 0 && bad.indices[k + 1] != 0 && bad.indices[k + 2] != 0;
    auto embree = reference::EmbreeScene::build(s, {});
    ASSERT_TRUE(embree);
    EXPECT_EQ(embree->triangleCount(), s.meshes[0].triangleCount() + clean);
    EXPECT_LT(clean, bad.triangleCount());
}

} // namespace

// The live view (issue #26): the image after pass k is the image of a render
// with k samples per pixel, bit for bit.
TEST(PathTracer, EachPassImageIsTheRenderOfThatManySamples) {
    scene::Project cornell = scene::makeCornellBoxProject();
    auto embree = reference::EmbreeScene::build(cornell.scene, {});
    ASSERT_TRUE(embree);
    const auto& camera = cornell.scene.cameras.front();
    std::vector<reference::ReferenceImage> passes;
    const auto full = reference::PathTracer(*embree, cornell.scene, camera, small(3, 2))
                          .render({}, [&](const reference::ReferenceImage& image) { passes.push_back(image); });
    ASSERT_EQ(passes.size(), 3u);
    for (int k = 1; k <= 3; ++k) {
        const auto direct = reference::PathTracer(*embree, cornell.scene, camera, small(k, 2)).render();
        EXPECT_EQ(passes[std::size_t(k - 1)].samplesPerPixel, k);
        EXPECT_EQ(passes[std::size_t(k - 1)].image, direct.image) << k;
        EXPECT_EQ(passes[std::size_t(k - 1)].indirectMultiVariance, direct.indirectMultiVariance) << k;
    }
    EXPECT_EQ(passes.back().image, full.image);
}
