// Area lights (issue #22): the irradiance the shader's float twin computes
// against Lambert's formula in double precision and against an independent
// closed form (the corner-point form factor of a rectangle, the on-axis disc);
// the radiance of a light given by its power; the outline.
#include "lpv/scene/AreaLight.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace lpv::scene;

namespace {

constexpr double kPi = std::numbers::pi;

// A rectangle w x h in the plane y = height, centred on (cx, height, cz), emitting downward.
Light rectangle(float w, float h, float height, float cx = 0.0f, float cz = 0.0f) {
    Light l;
    l.type = LightType::Area;
    l.shape = AreaShape::Rectangle;
    l.size = {w, h};
    l.position = {cx, height, cz};
    l.direction = {0.0f, -1.0f, 0.0f};
    l.tangent = {1.0f, 0.0f, 0.0f};
    l.intensity = 1.0f;
    return l;
}

// pi times the form factor from a point to an a x b rectangle parallel to it
// at distance c, the point facing it and opposite one corner (Howell's catalogue, C-11).
double cornerFactor(double a, double b, double c) {
    const double x = a / c, y = b / c;
    return 0.5 * (x / std::sqrt(1 + x * x) * std::atan(y / std::sqrt(1 + x * x)) +
                  y / std::sqrt(1 + y * y) * std::atan(x / std::sqrt(1 + y * y)));
}

double lambert(const Light& light, const glm::dvec3& p, const glm::dvec3& n) {
    std::vector<glm::dvec3> polygon;
    for (const glm::vec3& v : areaLightPolygon(light))
        polygon.emplace_back(v);
    return polygonCosineSolidAngle(p, n, polygon);
}

// The cosine-weighted solid angle by midpoint quadrature over the light (the
// definition, independent of Lambert's formula): sum of cos_s cos_l / r^2 dA.
double quadrature(const Light& light, const glm::dvec3& p, const glm::dvec3& n, int steps = 1500) {
    const AreaLightFrame f = areaLightFrame(light);
    const glm::dvec3 c(f.center), u(f.halfU), v(f.halfV), ln(f.normal);
    const double dA = 4.0 * glm::length(u) * glm::length(v) / double(steps) / double(steps);
    double sum = 0.0;
    for (int i = 0; i < steps; ++i)
        for (int j = 0; j < steps; ++j) {
            const glm::dvec3 q = c + u * (2.0 * (i + 0.5) / steps - 1.0) + v * (2.0 * (j + 0.5) / steps - 1.0);
            const glm::dvec3 d = q - p;
            const double r2 = glm::dot(d, d), r = std::sqrt(r2);
            const double cs = glm::dot(n, d) / r, cl = -glm::dot(ln, d) / r;
            if (cs > 0.0 && cl > 0.0)
                sum += cs * cl / r2 * dA;
        }
    return sum;
}

} // namespace

TEST(AreaLight, LambertsFormulaMatchesTheCornerFormFactor) {
    // A 2 x 3 rectangle 1.5 above a point under its centre: four corner rectangles of 1 x 1.5.
    const Light l = rectangle(2.0f, 3.0f, 1.5f);
    const double expected = 4.0 * cornerFactor(1.0, 1.5, 1.5);
    EXPECT_NEAR(lambert(l, {0, 0, 0}, {0, 1, 0}), expected, 1e-9 * expected);
    EXPECT_NEAR(areaLightIrradianceFactor(l, {0, 0, 0}, {0, 1, 0}), expected, 1e-5 * expected);
}

TEST(AreaLight, TheShaderTwinIsWithinOnePercentInFrontBesideAndAtGrazingAngles) {
    const Light l = rectangle(1.3f, 1.05f, 2.0f);
    struct Case {
        const char* what;
        glm::dvec3 p, n;
    };
    const Case cases[] = {
        {"in front, facing it", {0.2, 0.0, -0.1}, {0, 1, 0}},
        {"in front, tilted 60 degrees", {0.0, 0.5, 0.0}, glm::normalize(glm::dvec3(0.0, 0.5, 0.866))},
        {"beside it, facing up", {2.5, 0.0, 0.3}, {0, 1, 0}},
        {"beside it, a wall facing it (the light crosses the horizon)", {1.0, 1.0, 0.0}, {-1, 0, 0}},
        {"grazing: the horizon cuts the light in half", {0.0, 0.0, 0.0}, {1, 0, 0}},
        {"grazing: 85 degrees from the light", {0.0, 1.5, 0.0}, glm::normalize(glm::dvec3(0.996, 0.087, 0.0))},
    };
    for (const Case& c : cases) {
        const double exact = quadrature(l, c.p, c.n);
        ASSERT_GT(exact, 0.0) << c.what;
        EXPECT_NEAR(lambert(l, c.p, c.n), exact, 2e-3 * exact) << c.what; // the quadrature: h^2, or h where the horizon cuts
        EXPECT_NEAR(areaLightIrradianceFactor(l, glm::vec3(c.p), glm::vec3(c.n)), exact, 1e-2 * exact) << c.what;
    }
}

TEST(AreaLight, NothingBehindAOneSidedLightAndBothSidesWhenTwoSided) {
    Light l = rectangle(1.0f, 1.0f, 1.0f);
    EXPECT_EQ(areaLightIrradianceFactor(l, {0.0f, 2.0f, 0.0f}, {0.0f, -1.0f, 0.0f}), 0.0f);
    l.twoSided = true;
    const float below = areaLightIrradianceFactor(l, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f});
    const float above = areaLightIrradianceFactor(l, {0.0f, 2.0f, 0.0f}, {0.0f, -1.0f, 0.0f});
    EXPECT_GT(below, 0.0f);
    EXPECT_NEAR(above, below, 1e-5f * below);
}

TEST(AreaLight, ADiscOnItsAxisMatchesTheClosedForm) {
    Light d = rectangle(1.0f, 1.0f, 1.2f);
    d.shape = AreaShape::Disc;
    d.radius = 0.7f;
    const double expected = kPi * 0.49 / (0.49 + 1.44); // pi r^2 / (r^2 + h^2)
    EXPECT_NEAR(areaLightIrradianceFactor(d, {0, 0, 0}, {0, 1, 0}), expected, 3e-3 * expected);
    EXPECT_NEAR(areaLightArea(d), kPi * 0.49, 1e-6);
    // The polygon has the disc's area.
    const auto polygon = areaLightPolygon(d);
    ASSERT_EQ(polygon.size(), std::size_t(kAreaLightDiscSides));
    double area = 0.0;
    for (std::size_t i = 0; i < polygon.size(); ++i)
        area += 0.5 * glm::length(glm::cross(glm::dvec3(polygon[i] - d.position),
                                             glm::dvec3(polygon[(i + 1) % polygon.size()] - d.position)));
    EXPECT_NEAR(area, kPi * 0.49, 1e-5);
}

TEST(AreaLight, PowerIsSpreadOverPiTimesTheAreaPerSide) {
    Light l = rectangle(2.0f, 0.5f, 1.0f);
    l.unit = AreaUnit::Power;
    l.intensity = 10.0f;
    l.color = {1.0f, 0.5f, 0.25f};
    EXPECT_NEAR(areaLightRadiance(l).r, 10.0 / (kPi * 1.0), 1e-5);
    EXPECT_NEAR(areaLightRadiance(l).g, 5.0 / (kPi * 1.0), 1e-5);
    l.twoSided = true;
    EXPECT_NEAR(areaLightRadiance(l).r, 10.0 / (2.0 * kPi), 1e-5);
    l.unit = AreaUnit::Radiance;
    EXPECT_FLOAT_EQ(areaLightRadiance(l).r, 10.0f);
}

TEST(AreaLight, TheOutlineFollowsTheTangentAndFacesTheFront) {
    Light l = rectangle(2.0f, 1.0f, 0.0f);
    l.tangent = {0.0f, 0.3f, 1.0f}; // not orthogonal to the direction: made so
    const AreaLightFrame f = areaLightFrame(l);
    EXPECT_NEAR(glm::dot(f.halfU, f.normal), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::length(f.halfU), 1.0f, 1e-6f);
    EXPECT_NEAR(glm::length(f.halfV), 0.5f, 1e-6f);
    EXPECT_NEAR(f.halfU.z, 1.0f, 1e-6f); // along the tangent's part in the plane
    const auto q = areaLightPolygon(l);
    // Counter-clockwise seen from the front: (q1 - q0) x (q2 - q1) points along the normal.
    EXPECT_GT(glm::dot(glm::cross(q[1] - q[0], q[2] - q[1]), f.normal), 0.0f);
}
