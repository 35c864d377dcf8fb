// Lengths that scale (issue #41 item 3, docs/renderer.md "Lengths that scale"):
// the shadow maps' planes, the cascades and the sky height map's margin are
// the same fractions of a scene in centimetres, metres and kilometres. Each
// case fails with the metre constants these rules replaced (a 1 m floor under
// a local light's far plane, a 1 mm floor under its near plane, 0.1 mm under
// the cascades' near distance, 1 mm under their depth margin, a 1 m floor
// under the sky map's height). Plain math: no context needed.
#include "passes/direct/ShadowCascades.h"
#include "passes/direct/ShadowLights.h"
#include "passes/lpv/SkyHeightPass.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace lpv;
using namespace lpv::renderer;

namespace {

// The Cornell box's bounds (5.56 x 5.488 x 5.592 m) times s.
scene::Bounds box(double s) {
    scene::Bounds b;
    b.extend(glm::vec3(0.0f));
    b.extend(glm::vec3(glm::dvec3(5.56, 5.488, 5.592) * s));
    return b;
}

glm::vec3 at(const glm::vec3& p, double s) {
    return glm::vec3(glm::dvec3(p) * s);
}

constexpr double kScales[] = {0.01, 1000.0};

void expectScaled(float value, float metre, double s, const char* what) {
    EXPECT_NEAR(double(value), double(metre) * s, 1e-4 * std::abs(double(metre)) * s)
        << what << " at scale " << s;
}

} // namespace

TEST(ShadowScale, LocalLightPlanesAreFractionsOfTheScene) {
    scene::Light spot;
    spot.type = scene::LightType::Spot;
    spot.position = {2.78f, 5.4f, 2.8f};
    spot.direction = {0.0f, -1.0f, 0.0f};
    spot.outerConeAngle = 1.0f;
    const LocalShadowView spotMetre = spotShadowView(spot, box(1.0));
    scene::Light point = spot;
    point.type = scene::LightType::Point;
    const LocalShadowView pointMetre = pointShadowView(point, box(1.0));
    EXPECT_NEAR(spotMetre.nearPlane / spotMetre.farPlane, kLocalShadowNearFraction, 1e-6f);
    for (const double s : kScales) {
        scene::Light sp = spot, pt = point;
        sp.position = pt.position = at(spot.position, s);
        const LocalShadowView v = spotShadowView(sp, box(s));
        expectScaled(v.farPlane, spotMetre.farPlane, s, "spot far");
        expectScaled(v.nearPlane, spotMetre.nearPlane, s, "spot near");
        const LocalShadowView c = pointShadowView(pt, box(s));
        expectScaled(c.farPlane, pointMetre.farPlane, s, "point far");
        expectScaled(c.nearPlane, pointMetre.nearPlane, s, "point near");
        // The same light-space depth for the same (scaled) receiver.
        const glm::vec4 clip = v.viewProj[0] * glm::vec4(at({2.0f, 0.0f, 3.0f}, s), 1.0f);
        const glm::vec4 metreClip = spotMetre.viewProj[0] * glm::vec4(2.0f, 0.0f, 3.0f, 1.0f);
        EXPECT_NEAR(clip.z / clip.w, metreClip.z / metreClip.w, 1e-4f) << s;
    }
    // A light's range still bounds the map, in the scene's units.
    scene::Light ranged = point;
    ranged.range = 2.0f;
    EXPECT_NEAR(pointShadowView(ranged, box(1.0)).farPlane, 2.02f, 1e-5f);
}

// The framing camera inside an enclosed scene has its near plane at 1e-3 of
// the scene's radius: 17 um in a 2 cm room, which the old 0.1 mm floor moved.
TEST(ShadowScale, CascadesScaleWithTheCamera) {
    CascadeCamera camera;
    camera.position = {2.78f, 2.73f, -8.0f};
    camera.forward = {0.0f, 0.0f, 1.0f};
    camera.fovY = 0.7f;
    camera.aspect = 16.0f / 9.0f;
    camera.nearPlane = 1e-3f * 0.5f * glm::length(box(1.0).size());
    camera.farPlane = 4.0f * 0.5f * glm::length(box(1.0).size()) + 8.0f;
    const glm::vec3 sun = glm::normalize(glm::vec3(-0.3f, -1.0f, 0.4f));
    CascadeSettings settings;
    const std::vector<ShadowCascade> metre = buildCascades(camera, sun, box(1.0), settings);
    ASSERT_EQ(metre.size(), 6u);
    // A 2.2 cm box and a 5.7 km one: powers of two, so the stabilised radii
    // (rounded up to 1/16 of their power of two) round alike.
    for (const double s : {1.0 / 256.0, 1024.0}) {
        CascadeCamera c = camera;
        c.position = at(camera.position, s);
        c.nearPlane = float(double(camera.nearPlane) * s);
        c.farPlane = float(double(camera.farPlane) * s);
        const std::vector<ShadowCascade> cascades = buildCascades(c, sun, box(s), settings);
        ASSERT_EQ(cascades.size(), metre.size());
        for (std::size_t k = 0; k < metre.size(); ++k) {
            expectScaled(cascades[k].splitNear, metre[k].splitNear, s, "split near");
            expectScaled(cascades[k].splitFar, metre[k].splitFar, s, "split far");
            expectScaled(cascades[k].texelWorld, metre[k].texelWorld, s, "texel");
            expectScaled(cascades[k].depthRange, metre[k].depthRange, s, "depth range");
        }
    }
}

// A floor under a zenith sun spans no depth: the margin is a thousandth of
// the floor's size (1 mm was a twentieth of a 2 cm floor, 1e-6 of a 1 km one).
TEST(ShadowScale, FlatSceneDepthMarginScales) {
    CascadeCamera camera;
    camera.position = {0.0f, 1.0f, 3.0f};
    camera.forward = glm::normalize(glm::vec3(0.0f, -0.3f, -1.0f));
    camera.nearPlane = 0.01f;
    camera.farPlane = 10.0f;
    CascadeSettings settings;
    settings.count = 2;
    auto floor = [](double s) {
        scene::Bounds b;
        b.extend(at({-2.0f, 0.0f, -2.0f}, s));
        b.extend(at({2.0f, 0.0f, 2.0f}, s));
        return b;
    };
    const glm::vec3 zenith(0.0f, -1.0f, 0.0f);
    const std::vector<ShadowCascade> metre = buildCascades(camera, zenith, floor(1.0), settings);
    for (const double s : {1.0 / 256.0, 1024.0}) {
        CascadeCamera c = camera;
        c.position = at(camera.position, s);
        c.nearPlane = float(double(camera.nearPlane) * s);
        c.farPlane = float(double(camera.farPlane) * s);
        const std::vector<ShadowCascade> cascades = buildCascades(c, zenith, floor(s), settings);
        for (std::size_t k = 0; k < metre.size(); ++k)
            expectScaled(cascades[k].depthRange, metre[k].depthRange, s, "flat depth range");
    }
}

TEST(ShadowScale, SkyHeightMarginScales) {
    const float metre = skyHeightMargin(box(1.0));
    EXPECT_NEAR(metre, 0.05488f, 1e-6f);
    for (const double s : kScales)
        expectScaled(skyHeightMargin(box(s)), metre, s, "sky margin");
    scene::Bounds flat; // a floor alone: a thousandth of its width
    flat.extend(glm::vec3(0.0f));
    flat.extend(glm::vec3(0.02f, 0.0f, 0.02f));
    EXPECT_NEAR(skyHeightMargin(flat), 0.01f * 1e-3f * 0.02f, 1e-10f);
}
