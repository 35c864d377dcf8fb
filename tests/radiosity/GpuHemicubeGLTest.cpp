// The GPU hemicube against analytic form factors and the CPU reference, on
// llvmpipe: small meshes so the suite stays fast.
#include "GlFixture.h"
#include "RadiosityTestScenes.h"

#include "lpv/radiosity/FormFactors.h"
#include "lpv/radiosity/ProgressiveSolver.h"
#include "lpv/renderer/GpuHemicube.h"

#include <algorithm>
#include <numeric>

using namespace lpv;

namespace {

std::unique_ptr<renderer::GpuHemicube> hemicube(const radiosity::PatchMesh& mesh, int resolution = 128,
                                                int batch = 16) {
    auto h = renderer::GpuHemicube::create(mesh, resolution, batch);
    EXPECT_TRUE(h.has_value()) << h.error().describe();
    return h ? std::move(*h) : nullptr;
}

} // namespace

class GpuHemicubeGLTest : public GlTest {};

TEST_F(GpuHemicubeGLTest, ParallelUnitSquaresMatchTheAnalyticValue) {
    const auto mesh = radiosity::buildPatchMesh(test::parallelSquares(), {0.01f});
    auto h = hemicube(mesh);
    ASSERT_TRUE(h);
    EXPECT_NEAR(test::objectFormFactor(mesh, 0, 1, test::computeWith(*h)), 0.1998, 0.02 * 0.1998);
}

TEST_F(GpuHemicubeGLTest, PerpendicularUnitSquaresMatchTheAnalyticValue) {
    const auto mesh = radiosity::buildPatchMesh(test::perpendicularSquares(), {0.01f});
    auto h = hemicube(mesh);
    ASSERT_TRUE(h);
    EXPECT_NEAR(test::objectFormFactor(mesh, 0, 1, test::computeWith(*h)), 0.2000, 0.02 * 0.2000);
}

TEST_F(GpuHemicubeGLTest, EveryShooterInAClosedBoxSeesExactlyOneHemisphere) {
    const auto mesh = radiosity::buildPatchMesh(test::boxWithBlock(), {0.1f});
    auto h = hemicube(mesh, 64);
    ASSERT_TRUE(h);
    std::vector<std::uint32_t> shooters;
    for (std::uint32_t i = 0; i < mesh.size(); i += 7)
        shooters.push_back(i);
    std::vector<float> factors;
    ASSERT_TRUE(h->compute(shooters, factors).has_value());
    for (std::size_t s = 0; s < shooters.size(); ++s) {
        const double sum = std::accumulate(factors.begin() + std::ptrdiff_t(s * mesh.size()),
                                           factors.begin() + std::ptrdiff_t((s + 1) * mesh.size()), 0.0);
        EXPECT_NEAR(sum, 1.0, 1e-3) << "shooter " << shooters[s];
        EXPECT_EQ(factors[s * mesh.size() + shooters[s]], 0.0f); // a patch never sees itself
    }
}

TEST_F(GpuHemicubeGLTest, AgreesWithTheCpuReferenceOnAnOccludedScene) {
    const auto mesh = radiosity::buildPatchMesh(test::boxWithBlock(), {0.1f});
    auto h = hemicube(mesh, 128);
    ASSERT_TRUE(h);
    radiosity::CpuFormFactors cpu(mesh);
    // Object-to-object factors (12 objects) average out the hemicube's
    // aliasing and the reference's single visibility ray per pair.
    double worst = 0.0;
    for (std::uint32_t from : {0u, 1u, 2u, 6u}) // floor, ceiling, a wall, the block's top
        for (std::uint32_t to = 0; to < 12; ++to) {
            const double gpu = test::objectFormFactor(mesh, from, to, test::computeWith(*h));
            const double ref =
                test::objectFormFactor(mesh, from, to, [&](const std::vector<std::uint32_t>& s) {
                    std::vector<float> out;
                    EXPECT_TRUE(cpu.compute(s, out).has_value());
                    return out;
                });
            worst = std::max(worst, std::abs(gpu - ref));
            EXPECT_NEAR(gpu, ref, 0.02) << "object " << from << " -> " << to;
        }
    RecordProperty("worstObjectFormFactorDifference", std::to_string(worst));
}

TEST_F(GpuHemicubeGLTest, BatchesGiveTheSameFactorsAsSingleShooters) {
    const auto mesh = radiosity::buildPatchMesh(test::boxWithBlock(), {0.25f});
    auto batched = hemicube(mesh, 32, 8);
    auto single = hemicube(mesh, 32, 1);
    ASSERT_TRUE(batched && single);
    EXPECT_EQ(batched->preferredBatch(), 8);
    const std::vector<std::uint32_t> shooters{0, 3, 5, 9, 12, 20, 21, 30, 31, 40};
    std::vector<float> a, b;
    ASSERT_TRUE(batched->compute(shooters, a).has_value()); // 10 shooters: a batch of 8, then 2
    ASSERT_TRUE(single->compute(shooters, b).has_value());
    ASSERT_EQ(a.size(), b.size());
    // The same pixels up to the rasteriser's rounding of window coordinates,
    // which differs with the viewport's offset in the batch's tall target.
    double worst = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i)
        worst = std::max(worst, double(std::abs(a[i] - b[i])));
    EXPECT_LT(worst, 2e-3);
    EXPECT_GT(*std::max_element(a.begin(), a.end()), 0.05f);
}

TEST_F(GpuHemicubeGLTest, HemicubeImageHoldsPatchIdsOfTheLastBatch) {
    const auto mesh = radiosity::buildPatchMesh(test::parallelSquares(), {0.25f});
    auto h = hemicube(mesh, 32, 4);
    ASSERT_TRUE(h);
    std::vector<float> factors;
    ASSERT_TRUE(h->compute(std::vector<std::uint32_t>{0}, factors).has_value());
    const auto ids = h->readHemicube(0);
    ASSERT_EQ(ids.size(), std::size_t(3 * 32 * 32));
    // The top face's centre looks straight at the opposite square (object 1: patches 4..7).
    const std::uint32_t centre = ids[std::size_t(16 * 96 + 16)];
    ASSERT_GT(centre, 0u);
    EXPECT_EQ(mesh.patches[centre - 1].object, 1u);
    EXPECT_TRUE(h->readHemicube(1).empty()); // only one shooter in the last batch
}

TEST_F(GpuHemicubeGLTest, EnergyIsConservedWithGpuFormFactors) {
    const auto scene = test::boxWithBlock();
    const auto mesh = radiosity::buildPatchMesh(scene, {0.1f});
    auto h = hemicube(mesh, 64, 16);
    ASSERT_TRUE(h);
    radiosity::ProgressiveSolver solver(mesh, radiosity::surfaceProperties(mesh, scene, {}));
    for (int i = 0; i < 10; ++i)
        ASSERT_TRUE(solver.step(*h, 16).has_value());
    const auto& b = solver.state().balance;
    const glm::dvec3 accounted = b.absorbed + b.escaped + solver.unshotPower();
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(accounted[c], b.emitted[c], 1e-3 * b.emitted[c]);
        EXPECT_LT(std::abs(b.escaped[c]), 1e-3 * b.emitted[c]); // closed: nothing leaves
    }
    EXPECT_LT(solver.residual(), 0.7);
}
