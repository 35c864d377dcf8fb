// Area lights' numerical hard cases (docs/hard-cases.md, `ctest -L hardcase`):
// the shader twin stays finite and within 1% of Lambert's formula where it is
// defined, at the light's own plane and edge, for a 1e-6 m and a 1e4 m light,
// and seen exactly edge-on.
#include "lpv/scene/AreaLight.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace lpv::scene;

namespace {

Light square(float side, float height) {
    Light l;
    l.type = LightType::Area;
    l.size = {side, side};
    l.position = {0.0f, height, 0.0f};
    l.direction = {0.0f, -1.0f, 0.0f};
    l.tangent = {1.0f, 0.0f, 0.0f};
    return l;
}

double lambert(const Light& light, const glm::dvec3& p, const glm::dvec3& n) {
    std::vector<glm::dvec3> polygon;
    for (const glm::vec3& v : areaLightPolygon(light))
        polygon.emplace_back(v);
    return polygonCosineSolidAngle(p, n, polygon);
}

} // namespace

TEST(AreaLightHardCases, APointOnTheLightsOwnPlaneGetsNothing) {
    const Light l = square(1.0f, 0.0f);
    // Inside the outline, outside it, and facing every way: the emitter's cosine is 0 there.
    for (const glm::vec3 p : {glm::vec3(0.1f, 0.0f, 0.1f), glm::vec3(3.0f, 0.0f, 0.0f)})
        for (const glm::vec3 n : {glm::vec3(0, -1, 0), glm::vec3(0, 1, 0), glm::vec3(1, 0, 0)}) {
            const float f = areaLightIrradianceFactor(l, p, n);
            EXPECT_TRUE(std::isfinite(f));
            EXPECT_EQ(f, 0.0f);
        }
}

TEST(AreaLightHardCases, APointUnderTheEdgeAndUnderACornerIsFiniteAndExact) {
    const Light l = square(1.0f, 1e-4f); // the point almost touches the light's plane
    for (const glm::vec3 p : {glm::vec3(0.5f, 0.0f, 0.0f), glm::vec3(0.5f, 0.0f, 0.5f), glm::vec3(0.5f, 0.0f, 0.2f)}) {
        const float f = areaLightIrradianceFactor(l, p, {0, 1, 0});
        const double exact = lambert(l, glm::dvec3(p), {0, 1, 0});
        ASSERT_TRUE(std::isfinite(f));
        EXPECT_NEAR(f, exact, 1e-2 * exact) << p.x << " " << p.z;
    }
    // Exactly on the edge line and on a corner, in the plane: finite and 0.
    const Light flat = square(1.0f, 0.0f);
    EXPECT_EQ(areaLightIrradianceFactor(flat, {0.5f, 0.0f, 0.0f}, {0, -1, 0}), 0.0f);
    EXPECT_EQ(areaLightIrradianceFactor(flat, {0.5f, 0.0f, 0.5f}, {0, -1, 0}), 0.0f);
}

TEST(AreaLightHardCases, AMicrometreLightIsAPointAndAKilometreLightFillsTheSky) {
    const Light tiny = square(1e-6f, 1.0f);
    const double exactTiny = lambert(tiny, {0.3, 0.0, 0.0}, {0, 1, 0});
    const float fTiny = areaLightIrradianceFactor(tiny, {0.3f, 0.0f, 0.0f}, {0, 1, 0});
    ASSERT_GT(exactTiny, 0.0);
    EXPECT_NEAR(fTiny, exactTiny, 1e-2 * exactTiny);
    // The point-light limit: A cos^2 / d^2 with cos = 1 / sqrt(1.09), d^2 = 1.09.
    EXPECT_NEAR(exactTiny, 1e-12 / (1.09 * 1.09), 1e-3 * exactTiny);

    const Light huge = square(1e4f, 1.0f);
    const float fHuge = areaLightIrradianceFactor(huge, {0.0f, 0.0f, 0.0f}, {0, 1, 0});
    const double exactHuge = lambert(huge, {0, 0, 0}, {0, 1, 0});
    EXPECT_NEAR(fHuge, exactHuge, 1e-2 * exactHuge);
    EXPECT_NEAR(exactHuge, std::numbers::pi, 1e-3); // the whole hemisphere: E = pi L
}

TEST(AreaLightHardCases, ALightSeenExactlyEdgeOnDeliversNothing) {
    // The point lies in the light's plane, beside it, facing it: cos at the light is 0 everywhere.
    const Light l = square(1.0f, 0.0f);
    const float f = areaLightIrradianceFactor(l, {2.0f, 0.0f, 0.0f}, {-1, 0, 0});
    EXPECT_TRUE(std::isfinite(f));
    EXPECT_EQ(f, 0.0f);
    // A hair in front of the plane: small, finite, and within 1% of Lambert's formula.
    const float near = areaLightIrradianceFactor(l, {2.0f, -1e-3f, 0.0f}, {-1, 0, 0});
    const double exact = lambert(l, {2.0, -1e-3, 0.0}, {-1, 0, 0});
    ASSERT_GT(exact, 0.0);
    EXPECT_NEAR(near, exact, 1e-2 * exact);
}
