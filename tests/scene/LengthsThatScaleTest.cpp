// Lengths that scale (issue #41 item 3, docs/renderer.md "Lengths that
// scale"): the framing camera's planes, fitted clip planes and the test that
// a surface is an area light's own are fractions of the scene, the same in
// millimetres, centimetres and kilometres, and 100 km from the origin.
#include "lpv/scene/AreaLight.h"
#include "lpv/scene/CornellBox.h"
#include "lpv/scene/FramingCamera.h"
#include "lpv/scene/SceneScale.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace lpv;

namespace {

// The scene's lengths times s (lpv import --scale's function).
scene::Scene scaled(scene::Scene sc, double s) {
    scene::scaleSceneLengths(sc, s);
    sc.cameras.clear(); // the framing camera's turn
    return sc;
}

const scene::Scene& cornell() {
    static const scene::Scene s = scene::makeCornellBoxProject().scene;
    return s;
}

// View depths of every vertex of the scene seen by `c`, in front of it.
std::vector<float> depths(const scene::Scene& s, const scene::Camera& c) {
    std::vector<float> out;
    const glm::mat4 view = c.view();
    for (const scene::Mesh& m : s.meshes)
        for (const glm::vec3& p : m.positions) {
            const float z = -(view * glm::vec4(p, 1.0f)).z;
            if (z > 0.0f)
                out.push_back(z);
        }
    return out;
}

} // namespace

// The framing camera looks at the open box from outside: every vertex in
// front of it lies between its planes, whose ratios to the box are the same
// for a 0.7 mm, a 2 cm and a 5.6 km box (the radius was floored at 1 mm).
TEST(LengthsThatScale, FramingCameraHoldsTheBoxAtEveryScale) {
    const scene::Camera metre = scene::framingCamera(scaled(cornell(), 1.0));
    for (const double s : {1.0 / 8192.0, 1.0 / 275.0, 1000.0}) {
        const scene::Scene sc = scaled(cornell(), s);
        const scene::Camera c = scene::framingCamera(sc);
        EXPECT_NEAR(c.nearPlane, metre.nearPlane * s, 1e-5 * metre.nearPlane * s) << s;
        EXPECT_NEAR(c.farPlane, metre.farPlane * s, 1e-5 * metre.farPlane * s) << s;
        const std::vector<float> z = depths(sc, c);
        ASSERT_FALSE(z.empty());
        for (const float d : z) {
            EXPECT_GT(d, c.nearPlane) << s;
            EXPECT_LT(d, c.farPlane) << s;
        }
    }
}

// A scene far from the origin is framed as at the origin, moved: at 1,000 km
// the probe rays in float world space slipped through the box's walls and
// put the camera inside it (issue #41).
TEST(LengthsThatScale, FramingCameraFramesABoxAThousandKilometresAwayAsAtTheOrigin) {
    const scene::Camera here = scene::framingCamera(scaled(cornell(), 1.0));
    for (const double km : {100.0, 1000.0}) {
        scene::Scene far = scaled(cornell(), 1.0);
        const glm::dvec3 offset(km * 1000.0, 0.0, -km * 1000.0);
        for (scene::Object& o : far.objects)
            o.transform.translation = glm::vec3(glm::dvec3(o.transform.translation) + offset);
        for (scene::Light& l : far.lights)
            l.position = glm::vec3(glm::dvec3(l.position) + offset);
        const scene::Camera c = scene::framingCamera(far);
        // Float positions out there are 6 cm apart at 1,000 km: the same camera within that.
        const double ulp = 2.0 * std::ldexp(1.0, int(std::ceil(std::log2(km * 1000.0))) - 24);
        EXPECT_NEAR(glm::length(glm::dvec3(c.position) - offset - glm::dvec3(here.position)), 0.0, 2.0 * ulp) << km;
        EXPECT_NEAR(glm::length(glm::dvec3(c.target) - offset - glm::dvec3(here.target)), 0.0, 2.0 * ulp) << km;
        EXPECT_FLOAT_EQ(c.nearPlane, here.nearPlane);
    }
}

// A camera that kept the Camera defaults (0.05 m near, 500 m far) sees none
// of a 2 cm box from 3 cm away and cuts a 2 km one; fitted to the bounds it
// holds both, with the same ratios.
TEST(LengthsThatScale, FittedPlanesHoldA2CmAndA2KmBox) {
    auto published = [](double s) { // the template's camera, 8 m in front of the box
        scene::Camera c;
        c.position = glm::vec3(glm::dvec3(2.78, 2.73, -8.0) * s);
        c.target = glm::vec3(glm::dvec3(2.78, 2.73, 0.0) * s);
        return c;
    };
    scene::Camera metre = published(1.0);
    scene::fitClipPlanes(metre, cornell().worldBounds());
    EXPECT_NEAR(metre.nearPlane, 4.0f, 1e-4f); // half the 8 m to the box's front
    for (const double s : {1.0 / 275.0, 360.0}) {
        const scene::Scene sc = scaled(cornell(), s);
        scene::Camera c = published(s);
        const std::vector<float> z = depths(sc, c);
        const auto [lo, hi] = std::minmax_element(z.begin(), z.end());
        EXPECT_TRUE(*lo < c.nearPlane || *hi > c.farPlane) << "the defaults clip the box at scale " << s;
        scene::fitClipPlanes(c, sc.worldBounds());
        EXPECT_LT(c.nearPlane, *lo) << s;
        EXPECT_GT(c.farPlane, *hi) << s;
        EXPECT_NEAR(c.nearPlane, metre.nearPlane * s, 1e-5 * metre.nearPlane * s) << s;
        EXPECT_NEAR(c.farPlane, metre.farPlane * s, 1e-5 * metre.farPlane * s) << s;
    }
    scene::Camera inside; // from inside the box: far past every corner, near 1e-4 of it
    inside.position = {2.0f, 2.0f, 2.0f};
    scene::fitClipPlanes(inside, cornell().worldBounds());
    EXPECT_NEAR(inside.nearPlane, inside.farPlane * 1e-4f, 1e-9f);
    EXPECT_GT(inside.farPlane, glm::length(glm::vec3(5.56f, 5.488f, 5.592f) - inside.position));
}

// The Cornell lamp's quad is its area light's own surface (counted once) in
// centimetres and 100 km away; a quad 0.5 mm under the 1 cm-scale lamp (5 cm
// under the real one) is not. The 1 mm floor of the slack counted it, and
// 100 km out the quad's corners, rounded to 8 mm steps, fell outside it.
TEST(LengthsThatScale, AnAreaLightsOwnSurfaceIsFoundAtEveryScaleAndDistance) {
    const glm::vec3 q[4] = {
        {3.43f, 5.487f, 2.27f}, {3.43f, 5.487f, 3.32f}, {2.13f, 5.487f, 3.32f}, {2.13f, 5.487f, 2.27f}};
    auto onLight = [&](double s, const glm::dvec3& offset, double drop) {
        std::vector<scene::Light> lights = cornell().lights;
        lights[0].position = glm::vec3(glm::dvec3(lights[0].position) * s + offset);
        lights[0].size = glm::vec2(glm::dvec2(lights[0].size) * s);
        auto at = [&](int i) {
            return glm::vec3(glm::dvec3(q[i]) * s + offset - glm::dvec3(0.0, drop, 0.0));
        };
        return scene::liesOnAnAreaLight(lights, at(0), at(1), at(2)) &&
               scene::liesOnAnAreaLight(lights, at(0), at(2), at(3));
    };
    for (const double s : {0.01, 1.0, 1000.0}) {
        EXPECT_TRUE(onLight(s, glm::dvec3(0.0), 0.0)) << s;
        EXPECT_FALSE(onLight(s, glm::dvec3(0.0), 0.05 * s)) << s;
    }
    EXPECT_TRUE(onLight(1.0, {100000.0, 0.0, -100000.0}, 0.0));
    EXPECT_TRUE(onLight(0.01, {100000.0, 0.0, 0.0}, 0.0));
}
