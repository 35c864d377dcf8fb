#include "RadiosityTestScenes.h"

#include "lpv/radiosity/FormFactors.h"

#include <gtest/gtest.h>

#include <numbers>

using namespace lpv;

namespace {

auto cpuCompute(const radiosity::PatchMesh& mesh) {
    return [&mesh](const std::vector<std::uint32_t>& shooters) {
        radiosity::CpuFormFactors ff(mesh);
        std::vector<float> out;
        EXPECT_TRUE(ff.compute(shooters, out).has_value());
        return out;
    };
}

} // namespace

TEST(CpuFormFactors, PointAboveTheCentreOfADisc) {
    // Differential area facing a coaxial polygon approximating a disc of
    // radius r at height h: F = r^2 / (r^2 + h^2).
    std::vector<glm::dvec3> disc;
    for (int k = 0; k < 720; ++k) {
        const double a = 2.0 * std::numbers::pi * k / 720.0;
        disc.emplace_back(std::cos(a), std::sin(a), 2.0);
    }
    EXPECT_NEAR(radiosity::pointToPolygonFormFactor({0, 0, 0}, {0, 0, 1}, disc), 1.0 / 5.0, 1e-4);
}

TEST(CpuFormFactors, PolygonBehindTheShooterIsClipped) {
    const std::vector<glm::dvec3> below{{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}};
    EXPECT_EQ(radiosity::pointToPolygonFormFactor({0, 0, 0}, {0, 0, 1}, below), 0.0);
    // Half above the plane: the clipped half's contribution only.
    const std::vector<glm::dvec3> straddling{{1, -1, -1}, {1, 1, -1}, {1, 1, 1}, {1, -1, 1}};
    const double f = radiosity::pointToPolygonFormFactor({0, 0, 0}, {0, 0, 1}, straddling);
    EXPECT_GT(f, 0.0);
    EXPECT_LT(f, 0.25);
}

TEST(CpuFormFactors, ParallelUnitSquaresMatchTheAnalyticValue) {
    const auto mesh = radiosity::buildPatchMesh(test::parallelSquares(), {0.01f});
    const double f = test::objectFormFactor(mesh, 0, 1, cpuCompute(mesh));
    EXPECT_NEAR(f, 0.1998, 0.02 * 0.1998);
}

TEST(CpuFormFactors, PerpendicularUnitSquaresMatchTheAnalyticValue) {
    const auto mesh = radiosity::buildPatchMesh(test::perpendicularSquares(), {0.01f});
    const double f = test::objectFormFactor(mesh, 0, 1, cpuCompute(mesh));
    EXPECT_NEAR(f, 0.2000, 0.02 * 0.2000);
}

TEST(CpuFormFactors, AnOccluderBlocksTheView) {
    auto scene = test::parallelSquares();
    // A square between the two, facing the shooter.
    test::addQuad(scene, {{{-1, -1, 0.5f}, {2, -1, 0.5f}, {2, 2, 0.5f}, {-1, 2, 0.5f}}}, {0, 0, -1}, 0);
    const auto mesh = radiosity::buildPatchMesh(scene, {0.25f});
    EXPECT_EQ(test::objectFormFactor(mesh, 0, 1, cpuCompute(mesh)), 0.0);
    EXPECT_GT(test::objectFormFactor(mesh, 0, 2, cpuCompute(mesh)), 0.5);
}
