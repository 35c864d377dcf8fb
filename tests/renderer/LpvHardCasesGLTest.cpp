// Numerical hard cases of the LPV pass on llvmpipe (issue #11 item 6,
// docs/hard-cases.md): a thin wall between a bright and a dark room, very dim
// light, and 64 propagation steps. Hand-written RSM tiles (FakeRsm.h) so each
// case is exact and small; every test asserts finiteness and a bound measured
// here, with the reason for its margin in a comment.
#include "LpvPassFixture.h"
#include "LookupKernel.h"
#include "ThinWallRooms.h"

#include "passes/lpv/LpvPass.h"
#include "lpv/renderer/GpuTimer.h"
#include "lpv/renderer/lpv/LpvReference.h"
#include "lpv/renderer/lpv/LpvVisibility.h"

#include <cmath>
#include <iostream>
#include <random>

using namespace lpv::renderer;
namespace ref = lpv::renderer::lpvref;

namespace {

using Volume = std::array<std::vector<glm::vec4>, 3>;

constexpr LpvVariant kVariants[] = {LpvVariant::ComputeGather, LpvVariant::ComputeScatter,
                                    LpvVariant::RasterGather, LpvVariant::RasterScatter};

bool allFinite(const Volume& volume) {
    for (const auto& channel : volume)
        for (const glm::vec4& v : channel)
            if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z) || !std::isfinite(v.w))
                return false;
    return true;
}

// Sum of the DC coefficient of channel 0 over the cells with x index in [x0, x1).
double dcSum(const Volume& volume, int n, int x0, int x1) {
    double sum = 0.0;
    for (int z = 0; z < n; ++z)
        for (int y = 0; y < n; ++y)
            for (int x = x0; x < x1; ++x)
                sum += double(volume[0][std::size_t(x + n * (y + n * z))].x);
    return sum;
}

class HardCaseLpvGLTest : public LpvPassGLTest {
  protected:
    // One cascade, the camera G-buffer off: only the hand-written tile feeds injection and the GV.
    Volume run(const ref::GridFrame& grid, float texelArea, const FakeRsm& rsm, LpvVariant variant, int steps,
               bool occlusion, float injectionOffset = 1.0f) {
        LpvSettings settings;
        settings.gridSize = grid.n;
        settings.propagationSteps = steps;
        settings.injectionOffset = injectionOffset;
        settings.occlusion = occlusion;
        settings.gvFromCamera = false;
        settings.variant = variant;
        runPass(settings, rsmInputOf(rsm, {LpvCascade{grid.origin, grid.cellSize, grid.n}}, {texelArea}));
        return pass_->readAccumulator(0);
    }

};

int tileFor(std::size_t texels) {
    return int(std::ceil(std::sqrt(double(texels))));
}

// The two rooms of ThinWallRooms.h as RSM texels.
std::vector<Texel> twoRooms(const ref::GridFrame& grid, float wallCells) {
    std::vector<Texel> texels;
    for (const auto& t : thinwall::twoRooms(grid, wallCells))
        texels.push_back({t.position, t.normal, t.flux});
    return texels;
}

} // namespace

// Light leaking through a wall thinner than a cell: the LPV stores light per
// cell and the GV blocks it at cell corners, so some light always reaches
// the dark room; this measures how much and bounds it, with and without the GV.
TEST_F(HardCaseLpvGLTest, ThinWallLeakIntoTheDarkRoomIsMeasuredAndBounded) {
    const ref::GridFrame grid{glm::vec3(0.0f), 0.25f, 16};
    // Surfel area: a wall facing +-x seen by a sun overhead gets texelArea /
    // 0.2 (LpvPass clamps the 1/cos); 2 surfels per cell and axis must cover
    // (cell / 2)^2 each for the wall to be closed.
    const float texelArea = thinwall::texelArea(grid);
    constexpr int steps = 16; // light crosses the 8 cells of the dark room twice over
    // Measured worst-variant leaks with the GV (all four variants agree to 1e-5):
    // 0.0122 with the wall on a cell face, 0.0184 mid-cell; the bounds add 20%
    // for GPUs that round the GV interpolation and fixed-point sums differently.
    const std::pair<float, double> walls[] = {{8.0f, 1.2 * 0.0122}, {8.5f, 1.2 * 0.0184}};
    for (const auto& [wallCells, bound] : walls) { // on a cell face (= GV cell centre plane) and mid-cell
        const auto texels = twoRooms(grid, wallCells);
        FakeRsm rsm(tileFor(texels.size()), {texels});
        const int firstDark = int(std::ceil(wallCells + 0.01f)); // cells wholly behind the wall
        double leak[2] = {0.0, 0.0};
        for (bool occlusion : {false, true})
            for (LpvVariant variant : kVariants) {
                const Volume volume = run(grid, texelArea, rsm, variant, steps, occlusion);
                ASSERT_TRUE(allFinite(volume)) << lpvVariantName(variant);
                const double total = dcSum(volume, grid.n, 0, grid.n);
                ASSERT_GT(total, 0.0);
                const double fraction = dcSum(volume, grid.n, firstDark, grid.n) / total;
                leak[occlusion ? 1 : 0] = std::max(leak[occlusion ? 1 : 0], fraction);
            }
        std::cout << "[ figures ] thin wall at " << wallCells << " cells, " << steps
                  << " steps: fraction of the light in the dark room, GV off / on = " << leak[0] << " / "
                  << leak[1] << " (worst of the 4 variants)\n";
        // Without the GV free propagation puts 4.0% (face) / 5.9% (mid-cell)
        // of the light into the dark room: the case would test nothing if
        // light did not get there at all.
        EXPECT_GT(leak[0], 0.02);
        // The GV cuts the leak by 3.3x in both positions; at least 2x.
        EXPECT_LT(leak[1], 0.5 * leak[0]);
        EXPECT_LT(leak[1], bound);
    }
}

// The same thin wall as shading reads it (ThinWallRooms.h): mean irradiance
// on the dark room's floor over the bright room's, and on the wall's dark face
// over its bright face, with the plain lookup and the visibility-aware one
// (docs/lpv.md). The lookup stops what trilinear filtering reads across the
// wall; what propagation carried into the dark room it cannot, so the case
// runs at lpv.occlusionStrength 1 (the GV's two-sided wall blocks half per
// crossing) and 4 (it blocks the crossing whole).
TEST_F(HardCaseLpvGLTest, ThinWallLookupWithVisibilityReadsOnlyItsOwnSide) {
    const ref::GridFrame grid{glm::vec3(0.0f), 0.25f, 16};
    const float bias = ref::VisibilitySettings{}.normalBias;
    struct Case {
        float wallCells, strength;
        double floorOn, wallOn; // measured with the visibility lookup
    };
    // Measured (computeGather; the CPU twin gives the same to 3 digits):
    // face x1: floor 3.87% -> 3.43%, wall 77.7% -> 16.3%; face x4: floor
    // 0.19% -> 0.0039%, wall 67.4% -> 0.025%; mid-cell x1: floor 3.65% ->
    // 3.65%, wall 84.4% -> 58.5%; mid-cell x4: floor 0.64% -> 0.64%, wall
    // 86.4% -> 44.1%. Mid-cell, the GV rounds the wall's faces to the planes
    // on either side of cell 8, whose light is both rooms': no lookup can
    // tell its sides apart there.
    const Case cases[] = {{8.0f, 1.0f, 0.0343, 0.163}, {8.0f, 4.0f, 3.9e-5, 2.5e-4},
                          {8.5f, 1.0f, 0.0365, 0.585}, {8.5f, 4.0f, 0.0064, 0.441}};
    for (const Case& c : cases) {
        const auto texels = twoRooms(grid, c.wallCells);
        const FakeRsm rsm(tileFor(texels.size()), {texels});
        LpvSettings settings;
        settings.gridSize = grid.n;
        settings.propagationSteps = 16;
        settings.gvFromCamera = false;
        settings.occlusionStrength = c.strength;
        settings.visibility = true;
        LpvRsmInput input;
        input.cascades = {LpvCascade{grid.origin, grid.cellSize, grid.n}};
        input.texelArea = {thinwall::texelArea(grid)};
        input.tileSize = rsm.tileSize;
        input.position = rsm.position.id();
        input.normal = rsm.normal.id();
        input.flux = rsm.flux.id();
        input.towardSun = glm::vec3(0.0f, 1.0f, 0.0f);
        timer_.beginFrame();
        ASSERT_TRUE(pass_->run(settings, input, nullptr, timer_).has_value());
        const auto points = thinwall::shadingPoints(grid, c.wallCells);
        std::vector<LookupPoint> lookups;
        for (const auto& p : points)
            lookups.push_back({p.position, p.normal});
        const auto off = thinwall::lookupLeak(points, runLookup(*pass_, 0, false, bias, lookups));
        const auto on = thinwall::lookupLeak(points, runLookup(*pass_, 0, true, bias, lookups));
        std::cout << "[ figures ] thin wall at " << c.wallCells << " cells, occlusionStrength " << c.strength
                  << ": dark / bright floor, lookup off / on = " << off.floor << " / " << on.floor
                  << "; dark / bright wall face = " << off.wall << " / " << on.wall << "\n";
        ASSERT_TRUE(std::isfinite(on.floor) && std::isfinite(on.wall));
        // Never more than the plain lookup reads; bounds 1.2x the measured
        // (other GPUs round the fixed-point injection differently).
        EXPECT_LE(on.floor, off.floor * 1.001);
        EXPECT_LE(on.wall, off.wall * 1.001);
        EXPECT_LT(on.floor, 1.2 * c.floorOn);
        EXPECT_LT(on.wall, 1.2 * c.wallOn);
        if (c.wallCells == 8.0f && c.strength == 4.0f) {
            // Issue #24's target: at most 0.1% in the dark room once
            // propagation blocks the wall; the plain lookup reads 0.19% of
            // the floor and 67% on the wall's dark face there.
            EXPECT_LT(on.floor, 0.001);
            EXPECT_LT(on.wall, 0.001);
            EXPECT_GT(off.wall, 0.5);
        }
    }
}

// A 1e-6 W and a 1e-25 W light: every cell the light reaches must hold that
// fraction of what a 1 W light gives it (no underflow to zero, no fixed-point
// step swallowing it: the injection's scale follows the brightest texel). A
// 1e-36 W light is below what the fixed-point injection can hold (its scale
// 2^29 / (0.85 * brightest flux * texels) overflows float for a tile whose
// brightest texels sum to under ~2e-30 W): it must come out as exactly no
// light, finite, never NaN.
TEST_F(HardCaseLpvGLTest, DimLightScalesLinearlyAndDenormalsStayFinite) {
    const ref::GridFrame grid{glm::vec3(0.0f), 1.0f, 16};
    auto point = [](float flux) {
        std::vector<Texel> t;
        for (const glm::vec3 n : {glm::vec3(1, 0, 0), glm::vec3(-1, 0, 0), glm::vec3(0, 1, 0),
                                  glm::vec3(0, -1, 0), glm::vec3(0, 0, 1), glm::vec3(0, 0, -1)})
            t.push_back({glm::vec3(8.5f), n, glm::vec3(flux)});
        return t;
    };
    const FakeRsm bright(3, {point(1.0f)}), tiny(3, {point(1e-36f)});
    for (const float flux : {1e-6f, 1e-25f})
        for (LpvVariant variant : kVariants) {
            const FakeRsm dim(3, {point(flux)});
            const Volume a = run(grid, 0.01f, bright, variant, 8, false, 0.0f);
            const Volume b = run(grid, 0.01f, dim, variant, 8, false, 0.0f);
            ASSERT_TRUE(allFinite(b)) << lpvVariantName(variant);
            float maxA = 0.0f;
            for (const glm::vec4& v : a[0])
                maxA = std::max(maxA, std::abs(v.x));
            double worst = 0.0;
            int reached = 0;
            for (std::size_t i = 0; i < a[0].size(); ++i) {
                if (std::abs(a[0][i].x) < 1e-4f * maxA)
                    continue; // cells the light hardly reaches: relative error means nothing there
                ++reached;
                worst = std::max(worst, std::abs(double(b[0][i].x) / double(flux) - double(a[0][i].x)) /
                                            std::abs(a[0][i].x));
            }
            std::cout << "[ figures ] " << flux << " W point, " << lpvVariantName(variant)
                      << ", 8 steps: " << reached
                      << " cells reached, worst |dim / flux - bright| / bright = " << worst << "\n";
            EXPECT_GT(reached, 100);
            // Measured at most 1.8e-6 (computeScatter at 1e-6 W): the fixed-point
            // sums scale with the brightest texel, so the relative rounding is
            // the same at any flux; 2e-5 leaves 10x, while losing the light to
            // underflow or a fixed step would be an error near 1.
            EXPECT_LT(worst, 2e-5) << lpvVariantName(variant);
        }
    for (LpvVariant variant : kVariants) {
        const Volume c = run(grid, 0.01f, tiny, variant, 8, false, 0.0f);
        EXPECT_TRUE(allFinite(c)) << lpvVariantName(variant);
        double largest = 0.0;
        for (const glm::vec4& v : c[0])
            largest = std::max(largest, double(std::abs(v.x)));
        EXPECT_LE(largest, 1e-30) << "1e-36 W: at most the light itself, never an overflowed sum";
    }
}

// 64 propagation steps (the registry's maximum) of a busy scene with the
// geometry volume on: every variant stays finite, agrees with the CPU
// reference, and the accumulated light does not run away.
TEST_F(HardCaseLpvGLTest, SixtyFourStepsAgreeWithTheReferenceAndStayBounded) {
    const ref::GridFrame grid{glm::vec3(-1.0f), 0.25f, 16};
    const float texelArea = 0.004f;
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<Texel> texels;
    const float extent = grid.cellSize * float(grid.n);
    for (int i = 0; i < 500; ++i) {
        const glm::vec3 n = glm::normalize(glm::vec3(u(rng) - 0.5f, u(rng) - 0.5f, u(rng) - 0.5f) + 1e-3f);
        texels.push_back(
            {grid.origin + glm::vec3(u(rng), u(rng), u(rng)) * extent, n, glm::vec3(u(rng), u(rng), u(rng))});
    }
    std::vector<ref::Vpl> vpls;
    std::vector<ref::Surfel> surfels;
    double injected = 0.0;
    for (const Texel& t : texels) {
        vpls.push_back({t.position, t.normal, t.flux});
        surfels.push_back({t.position, t.normal, texelArea / std::max(t.normal.y, 0.2f)});
    }
    const ref::ShGrid start = ref::injectVpls(grid, vpls, 1.0f);
    for (const glm::vec4& v : start.channel[0])
        injected += double(v.x);
    const ref::GvGrid gv = ref::mergeByMax(ref::injectSurfels(grid, surfels), ref::GvGrid(grid.n));
    const ref::ShGrid expected = ref::propagateAndAccumulate(start, &gv, 64);
    FakeRsm rsm(tileFor(texels.size()), {texels});
    for (LpvVariant variant : kVariants) {
        const Volume volume = run(grid, texelArea, rsm, variant, 64, true);
        ASSERT_TRUE(allFinite(volume)) << lpvVariantName(variant);
        float maxAbs = 0.0f, maxValue = 0.0f;
        for (std::size_t i = 0; i < volume[0].size(); ++i)
            for (int j = 0; j < 4; ++j) {
                maxAbs = std::max(maxAbs, std::abs(volume[0][i][j] - expected.channel[0][i][j]));
                maxValue = std::max(maxValue, std::abs(expected.channel[0][i][j]));
            }
        const double gain = dcSum(volume, grid.n, 0, grid.n) / injected;
        std::cout << "[ figures ] 64 steps, 16^3, GV on, " << lpvVariantName(variant)
                  << ": max |GPU - CPU| / max = " << maxAbs / maxValue
                  << ", accumulated / injected DC = " << gain << "\n";
        // Measured 4.0e-6..4.2e-6 (the four variants): 64 steps of float sums
        // in another order (and fixed point in the scatters); 4e-5 leaves 10x.
        EXPECT_LT(maxAbs / maxValue, 4e-5f) << lpvVariantName(variant);
        // Each step carries at most the previous step's flux (no gain, see
        // LpvStabilityTest), so 64 steps accumulate at most 65x the injected
        // light. Measured 25.72 (light leaves the 16-cell grid and the GV
        // absorbs some); the CPU reference agrees above, so the bound here
        // is the no-gain one.
        EXPECT_LT(gain, 65.0);
        EXPECT_GT(gain, 1.0);
    }
}
