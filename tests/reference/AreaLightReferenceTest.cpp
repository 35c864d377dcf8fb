// Area lights in the path tracer (issue #22): sampled directly (next-event
// estimation), one-sided unless flagged, their irradiance equal to Lambert's
// formula; what the renderer's shader twin computes for the same light.
#include "lpv/reference/PathTracer.h"
#include "GreyFloor.h"
#include "lpv/scene/AreaLight.h"
#include "lpv/scene/Primitives.h"

#include "ReferenceTestScenes.h"
#include "Sampling.h"

#include <glm/gtc/quaternion.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace {

using namespace lpv;

scene::Scene floorWithPanel(bool twoSided) {
    scene::Scene s = test::greyFloor(0.5f, 100.0f);
    scene::Light panel;
    panel.type = scene::LightType::Area;
    panel.size = {1.2f, 0.8f};
    panel.position = {0.3f, 1.5f, -0.2f};
    panel.direction = {0.0f, -1.0f, 0.0f};
    panel.tangent = {1.0f, 0.0f, 0.0f};
    panel.intensity = 4.0f;
    panel.twoSided = twoSided;
    s.lights.push_back(panel);
    return s;
}

// The mean of `n` one-point estimates of the direct irradiance.
glm::dvec3 meanIrradiance(const reference::PathTracer& tracer, const glm::vec3& p, const glm::vec3& n, int count) {
    reference::Rng rng(1u, 2u, 3u);
    glm::dvec3 sum(0.0);
    for (int i = 0; i < count; ++i)
        sum += glm::dvec3(tracer.directIrradiance(p, n, n, &rng));
    return sum / double(count);
}

double lambert(const scene::Light& light, const glm::dvec3& p, const glm::dvec3& n) {
    std::vector<glm::dvec3> polygon;
    for (const glm::vec3& v : scene::areaLightPolygon(light))
        polygon.emplace_back(v);
    return scene::polygonCosineSolidAngle(p, n, polygon);
}

} // namespace

TEST(AreaLightReference, IrradianceUnderARectangleIsLambertsFormula) {
    const scene::Scene s = floorWithPanel(false);
    auto embree = reference::EmbreeScene::build(s, {});
    ASSERT_TRUE(embree) << embree.error().describe();
    reference::PathTracerSettings settings;
    const reference::PathTracer tracer(*embree, s, test::lookingDown(), settings);
    const scene::Light& light = s.lights.front();
    for (const glm::vec3 p : {glm::vec3(0.0f), glm::vec3(1.5f, 0.0f, 0.4f)}) {
        const double expected = 4.0 * lambert(light, glm::dvec3(p), {0, 1, 0});
        const glm::dvec3 e = meanIrradiance(tracer, p, {0, 1, 0}, 40000);
        EXPECT_NEAR(e.r, expected, 0.01 * expected) << p.x;
        // The renderer's shader twin sees the same light.
        EXPECT_NEAR(4.0 * scene::areaLightIrradianceFactor(light, p, {0, 1, 0}), expected, 0.01 * expected);
    }
}

TEST(AreaLightReference, NothingReachesTheBackOfAOneSidedEmitter) {
    // A point above the downward-facing panel, looking up at its back.
    const scene::Scene s = floorWithPanel(false);
    auto embree = reference::EmbreeScene::build(s, {});
    ASSERT_TRUE(embree);
    const reference::PathTracer tracer(*embree, s, test::lookingDown(), {});
    EXPECT_EQ(meanIrradiance(tracer, {0.3f, 3.0f, -0.2f}, {0, -1, 0}, 1000), glm::dvec3(0.0));

    // Flagged two-sided, it lights both sides alike.
    const scene::Scene both = floorWithPanel(true);
    auto embreeBoth = reference::EmbreeScene::build(both, {});
    ASSERT_TRUE(embreeBoth);
    const reference::PathTracer twoSided(*embreeBoth, both, test::lookingDown(), {});
    const double expected = 4.0 * lambert(both.lights.front(), {0.3, 3.0, -0.2}, {0, -1, 0});
    EXPECT_NEAR(meanIrradiance(twoSided, {0.3f, 3.0f, -0.2f}, {0, -1, 0}, 40000).r, expected, 0.01 * expected);
}

TEST(AreaLightReference, ABlockerCastsASoftShadow) {
    scene::Scene s = floorWithPanel(false);
    s.meshes.push_back(scene::makeBox());
    scene::Object blocker;
    blocker.mesh = 1;
    blocker.transform.translation = {0.3f, 0.75f, -0.2f};
    blocker.transform.scale = glm::vec3(0.3f);
    s.objects.push_back(blocker);
    auto embree = reference::EmbreeScene::build(s, {});
    ASSERT_TRUE(embree);
    const reference::PathTracer tracer(*embree, s, test::lookingDown(), {});
    const double open = 4.0 * lambert(s.lights.front(), {0.3, 0.0, -0.2}, {0, 1, 0});
    const double shadowed = meanIrradiance(tracer, {0.3f, 0.0f, -0.2f}, {0, 1, 0}, 20000).r;
    // Partly blocked: a penumbra, neither fully lit nor black.
    EXPECT_GT(shadowed, 0.05 * open);
    EXPECT_LT(shadowed, 0.8 * open);
}

TEST(AreaLightReference, AOneSidedEmissiveSurfaceLightsNothingBelowItsBack) {
    // An emissive panel 1 m above the floor facing up (makePlane's normal is +y): its back faces the floor.
    scene::Scene s = floorWithPanel(false);
    s.lights.clear();
    scene::Mesh panelMesh = scene::makePlane();
    for (scene::Submesh& sub : panelMesh.submeshes)
        sub.materialIndex = 1;
    s.meshes.push_back(panelMesh);
    scene::Material lamp;
    lamp.emissive = glm::vec3(5.0f);
    s.materials.push_back(lamp);
    scene::Object panel;
    panel.mesh = 1;
    panel.transform.translation = {0.0f, 1.0f, 0.0f};
    s.objects.push_back(panel);
    // A camera low at the side looks at the floor under the panel.
    scene::Camera side;
    side.position = {3.0f, 0.3f, 0.0f};
    side.target = {0.0f, 0.0f, 0.0f};
    reference::PathTracerSettings settings;
    settings.emissiveLight = true;
    settings.width = settings.height = 9;
    settings.bounces = 1;
    auto radianceUnderThePanel = [&](const scene::Scene& scene) {
        auto embree = reference::EmbreeScene::build(scene, {});
        EXPECT_TRUE(embree);
        const reference::PathTracer tracer(*embree, scene, side, settings);
        double sum = 0.0;
        for (int i = 0; i < 64; ++i)
            sum += tracer.samplePixel(4, 4, i).radiance.r;
        return sum / 64.0;
    };
    EXPECT_EQ(radianceUnderThePanel(s), 0.0) << "one-sided: the back of the lamp lights nothing";
    s.materials[1].twoSided = true;
    EXPECT_GT(radianceUnderThePanel(s), 0.01) << "flagged two-sided, the panel lights what is under it";
}

namespace {

// A floor, a white wall at x = -1 facing +x, and a 1 x 1 panel at height 1.5 facing down
// (black: it reflects nothing). `emissive`: the panel glows with radiance 4; otherwise an
// area light of the same radiance lies on it.
scene::Scene panelRoom(bool emissive) {
    scene::Scene s;
    s.sky.intensity = 0.0f;
    s.meshes.push_back(scene::makePlane());
    scene::Mesh panelMesh = scene::makePlane();
    for (scene::Submesh& sub : panelMesh.submeshes)
        sub.materialIndex = 1;
    s.meshes.push_back(panelMesh);
    scene::Material white;
    white.diffuseColor = glm::vec3(0.8f);
    scene::Material panelMaterial;
    panelMaterial.diffuseColor = glm::vec3(0.0f);
    panelMaterial.emissive = emissive ? glm::vec3(4.0f) : glm::vec3(0.0f);
    s.materials = {white, panelMaterial};
    scene::Object floor;
    floor.mesh = 0;
    floor.transform.scale = glm::vec3(20.0f, 1.0f, 20.0f);
    scene::Object wall;
    wall.mesh = 0;
    wall.transform.translation = {-1.0f, 0.0f, 0.0f};
    wall.transform.rotation = glm::angleAxis(glm::radians(-90.0f), glm::vec3(0, 0, 1)); // +y to +x
    wall.transform.scale = glm::vec3(20.0f, 1.0f, 20.0f);
    scene::Object panel;
    panel.mesh = 1;
    panel.transform.translation = {0.0f, 1.5f, 0.0f};
    panel.transform.rotation = glm::angleAxis(glm::radians(180.0f), glm::vec3(1, 0, 0)); // facing down
    s.objects = {floor, wall, panel};
    if (!emissive) {
        scene::Light l;
        l.type = scene::LightType::Area;
        l.position = {0.0f, 1.5f, 0.0f};
        l.direction = {0.0f, -1.0f, 0.0f};
        l.size = {1.0f, 1.0f};
        l.intensity = 4.0f;
        s.lights = {l};
    }
    return s;
}

struct Layers {
    double image = 0.0, one = 0.0, multi = 0.0, oneVariance = 0.0;
};

Layers meanLayers(const scene::Scene& s, int bounces) {
    auto embree = reference::EmbreeScene::build(s, {});
    EXPECT_TRUE(embree);
    scene::Camera side;
    side.position = {3.0f, 1.0f, 0.0f};
    side.target = {0.0f, 0.3f, 0.0f};
    reference::PathTracerSettings settings;
    settings.emissiveLight = true;
    settings.width = settings.height = 8;
    settings.samplesPerPixel = 256;
    settings.bounces = bounces;
    settings.threads = 2;
    const reference::ReferenceImage image = reference::PathTracer(*embree, s, side, settings).render();
    Layers m;
    const double n = double(image.pixelCount());
    for (std::size_t i = 0; i < image.pixelCount(); ++i) {
        m.image += image.image[i].r / n;
        m.one += image.indirectOne[i].r / n;
        m.multi += image.indirectMulti[i].r / n;
        m.oneVariance += image.indirectOneVariance[i].r / (n * n);
    }
    return m;
}

} // namespace

// The emitter's direct light is direct (issue #22): with no other surface to reflect it
// (the wall taken away, the panel black), nothing lands in the indirect layers.
TEST(AreaLightReference, EmittedLightReachingThePrimaryHitDirectlyIsNotIndirect) {
    scene::Scene s = panelRoom(true);
    s.objects.erase(s.objects.begin() + 1); // no wall
    const Layers m = meanLayers(s, 4);
    EXPECT_GT(m.image, 0.01) << "the floor is lit directly";
    EXPECT_EQ(m.one, 0.0);
    EXPECT_EQ(m.multi, 0.0);
}

// `bounces N` means N reflections for every light kind: a glowing panel and an area light
// of the same radiance on it give the same one-bounce layer and the same image.
TEST(AreaLightReference, AnEmissivePanelAndAnAreaLightBounceAlike) {
    const Layers panel = meanLayers(panelRoom(true), 1), light = meanLayers(panelRoom(false), 1);
    ASSERT_GT(light.one, 0.0) << "the wall reflects the lamp's light onto the floor";
    const double tolerance = 4.0 * std::sqrt(panel.oneVariance + light.oneVariance);
    EXPECT_NEAR(panel.one, light.one, tolerance) << "one-bounce layers";
    EXPECT_NEAR(panel.image, light.image, 0.05 * light.image) << "images";
    EXPECT_EQ(light.one, light.multi) << "with one bounce the layers agree";
}
