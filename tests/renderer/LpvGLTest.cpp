// Every GPU propagation variant against the CPU reference (docs/lpv.md), on
// llvmpipe: injection, geometry volume and propagation on an 8^3 and a 32^3
// grid, and a bright 1024^2-VPL scene for the fixed-point atomics.
#include "LpvPassFixture.h"
#include "LpvDirectedScene.h"

#include "passes/lpv/LpvPass.h"
#include "lpv/renderer/GpuTimer.h"
#include "lpv/renderer/lpv/LpvReference.h"

#include <glm/gtc/type_ptr.hpp>

#include <cmath>
#include <iostream>
#include <limits>
#include <random>

using namespace lpv::renderer;
namespace ref = lpv::renderer::lpvref;

namespace {

struct LpvCase {
    ref::GridFrame grid;
    float texelArea = 0.0f;
    glm::vec3 towardSun{0.0f, 1.0f, 0.0f};
    float injectionOffset = 1.0f;
    bool occludeFirstStep = true;   // lpv.occlusionFirstStep
    float occlusionStrength = 1.0f; // lpv.occlusionStrength
    bool twoSided = false;          // lpv.twoSidedOcclusion
};

// The reference accumulator for the texels of one tile.
// `dilation` >= 0: directed propagation with that many dilation passes.
ref::ShGrid referenceAccumulator(const LpvCase& s, const std::vector<Texel>& texels, int steps, bool occlusion,
                                 int dilation = -1) {
    std::vector<ref::Vpl> vpls;
    std::vector<ref::Surfel> surfels;
    for (const Texel& t : texels) {
        vpls.push_back({t.position, t.normal, t.flux});
        const float area = s.texelArea / std::max(glm::dot(t.normal, s.towardSun), 0.2f);
        surfels.push_back({t.position, t.normal, area});
    }
    const ref::ShGrid injected = ref::injectVpls(s.grid, vpls, s.injectionOffset);
    ref::GvGrid gv = ref::mergeByMax(ref::injectSurfels(s.grid, surfels), ref::GvGrid(s.grid.n));
    gv.strength = s.occlusionStrength;
    gv.twoSided = s.twoSided;
    if (dilation < 0)
        return ref::propagateAndAccumulate(injected, occlusion ? &gv : nullptr, steps, nullptr, s.occludeFirstStep);
    ref::NormalGrid normals = ref::injectNormals(s.grid, vpls, s.injectionOffset);
    for (int i = 0; i < dilation; ++i)
        normals = ref::dilateNormals(normals);
    return ref::propagateAndAccumulate(injected, occlusion ? &gv : nullptr, steps, &normals);
}

struct Difference {
    float maxAbs = 0.0f;
    float maxValue = 0.0f;
    float relative() const { return maxValue > 0.0f ? maxAbs / maxValue : maxAbs; }
};

Difference compare(const ref::ShGrid& expected, const std::array<std::vector<glm::vec4>, 3>& gpu) {
    Difference d;
    for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(gpu[std::size_t(c)].size(), expected.channel[c].size());
        for (std::size_t i = 0; i < expected.channel[c].size() && i < gpu[std::size_t(c)].size(); ++i)
            for (int j = 0; j < 4; ++j) {
                d.maxAbs = std::max(d.maxAbs, std::abs(gpu[std::size_t(c)][i][j] - expected.channel[c][i][j]));
                d.maxValue = std::max(d.maxValue, std::abs(expected.channel[c][i][j]));
            }
    }
    return d;
}

class LpvGLTest : public LpvPassGLTest {
  protected:
    // Runs one variant on a single cascade and returns its accumulator.
    std::array<std::vector<glm::vec4>, 3> runGpu(const LpvCase& s, const FakeRsm& rsm, LpvVariant variant, int steps,
                                                 bool occlusion, int dilation = -1) {
        LpvSettings settings;
        settings.gridSize = s.grid.n;
        settings.propagationSteps = steps;
        settings.injectionOffset = s.injectionOffset;
        settings.occlusion = occlusion;
        settings.occludeFirstStep = s.occludeFirstStep;
        settings.occlusionStrength = s.occlusionStrength;
        settings.twoSidedOcclusion = s.twoSided;
        settings.gvFromCamera = false;
        settings.variant = variant;
        settings.directed = dilation >= 0;
        settings.directedDilation = std::max(dilation, 0);
        runPass(settings, rsmInputOf(rsm, {LpvCascade{s.grid.origin, s.grid.cellSize, s.grid.n}}, {s.texelArea},
                                     s.towardSun));
        return pass_->readAccumulator(0);
    }

};

constexpr LpvVariant kVariants[] = {LpvVariant::ComputeGather, LpvVariant::ComputeScatter, LpvVariant::RasterGather,
                                    LpvVariant::RasterScatter};

// Injection alone (0 steps): the fixed-point sums against the float reference.
TEST_F(LpvGLTest, InjectionMatchesReference) {
    LpvCase s{{glm::vec3(-2.0f, 0.0f, 1.0f), 0.5f, 8}, 0.01f};
    const auto texels = wallScene(s.grid, 200, 3.0f, 1);
    FakeRsm rsm(int(std::ceil(std::sqrt(double(texels.size())))), {texels});
    const ref::ShGrid expected = referenceAccumulator(s, texels, 0, true);
    const Difference d = compare(expected, runGpu(s, rsm, LpvVariant::ComputeGather, 0, true));
    std::cout << "[ figures ] injection 8^3: max |GPU - CPU| = " << d.maxAbs << " of max " << d.maxValue
              << " (relative " << d.relative() << ")\n";
    EXPECT_GT(d.maxValue, 0.1f);
    EXPECT_LT(d.relative(), 1e-5f);
}

// Each variant, 8^3 and 32^3, with and without occlusion, several step counts.
struct GridCase {
    int n;
    int vpls;
    int steps;
};

class LpvVariantTest : public LpvGLTest, public ::testing::WithParamInterface<std::tuple<LpvVariant, GridCase>> {};

TEST_P(LpvVariantTest, MatchesReference) {
    const auto [variant, grid] = GetParam();
    LpvCase s{{glm::vec3(1.0f, -3.0f, 0.5f), 0.25f, grid.n}, 0.002f};
    const auto texels = wallScene(s.grid, grid.vpls, 2.0f, unsigned(grid.n));
    const int size = int(std::ceil(std::sqrt(double(texels.size()))));
    FakeRsm rsm(size, {texels});
    // Light behind the wall (x > 0.6 of the extent, the VPLs are below 0.45).
    auto behindWall = [&](const std::array<std::vector<glm::vec4>, 3>& volume) {
        double sum = 0.0;
        for (int z = 0; z < grid.n; ++z)
            for (int y = 0; y < grid.n; ++y)
                for (int x = int(0.62f * float(grid.n)) + 1; x < grid.n; ++x)
                    sum += volume[1][std::size_t(x + grid.n * (y + grid.n * z))].x;
        return sum;
    };
    double behind[2] = {0.0, 0.0};
    for (bool occlusion : {false, true}) {
        const ref::ShGrid expected = referenceAccumulator(s, texels, grid.steps, occlusion);
        const auto gpu = runGpu(s, rsm, variant, grid.steps, occlusion);
        behind[occlusion ? 1 : 0] = behindWall(gpu);
        const Difference d = compare(expected, gpu);
        std::cout << "[ figures ] " << lpvVariantName(variant) << " " << grid.n << "^3, " << grid.steps
                  << " steps, occlusion " << (occlusion ? "on" : "off") << ": max |GPU - CPU| = " << d.maxAbs
                  << " of max " << d.maxValue << " (relative " << d.relative() << ")\n";
        EXPECT_GT(d.maxValue, 0.01f);
        // Float sums in a different order, fixed point in the scatter variant.
        EXPECT_LT(d.relative(), 2e-5f) << lpvVariantName(variant) << " occlusion " << occlusion;
    }
    if (grid.steps >= 6) { // enough steps for light to reach the far side
        std::cout << "[ figures ] " << lpvVariantName(variant) << " " << grid.n
                  << "^3: light behind the wall, occlusion off / on = " << behind[0] / behind[1] << "\n";
        EXPECT_GT(behind[0], 1.5 * behind[1]);
    }
}

INSTANTIATE_TEST_SUITE_P(AllVariants, LpvVariantTest,
                         ::testing::Combine(::testing::ValuesIn(kVariants),
                                            // 9 and 10: grids the compute gather's
                                            // columns of 4 cells do not divide
                                            ::testing::Values(GridCase{8, 60, 1}, GridCase{8, 60, 6},
                                                              GridCase{9, 60, 6}, GridCase{10, 80, 6},
                                                              GridCase{32, 2000, 8})),
                         [](const auto& p) {
                             const GridCase g = std::get<1>(p.param);
                             return std::string(lpvVariantName(std::get<0>(p.param))) + "_" +
                                    std::to_string(g.n) + "cubed_" + std::to_string(g.steps) + "steps";
                         });

// The leak and over-blocking candidates of issue #24 (docs/lpv.md): the first
// step without occlusion, a stronger blocking potential, and two-sided
// blocking (lpv.twoSidedOcclusion), in every variant
// against the reference; each must change the result, or it tests nothing.
class LpvOcclusionOptionsTest : public LpvGLTest, public ::testing::WithParamInterface<LpvVariant> {};

TEST_P(LpvOcclusionOptionsTest, FirstStepAndStrengthMatchReference) {
    const LpvVariant variant = GetParam();
    LpvCase base{{glm::vec3(1.0f, -3.0f, 0.5f), 0.25f, 10}, 0.002f};
    const auto texels = wallScene(base.grid, 80, 2.0f, 10u);
    FakeRsm rsm(int(std::ceil(std::sqrt(double(texels.size())))), {texels});
    const ref::ShGrid plain = referenceAccumulator(base, texels, 6, true);
    LpvCase firstOpen = base, stronger = base, twoSided = base;
    firstOpen.occludeFirstStep = false;
    stronger.occlusionStrength = 4.0f / 3.0f;
    twoSided.twoSided = true; // the wall's surfels face -x: two-sided they block light going -x too
    for (const auto& [name, s] : {std::pair{"first step unoccluded", firstOpen}, std::pair{"strength 4/3", stronger},
                                  std::pair{"two-sided", twoSided}}) {
        const ref::ShGrid expected = referenceAccumulator(s, texels, 6, true);
        const Difference d = compare(expected, runGpu(s, rsm, variant, 6, true));
        const Difference change = compare(plain, [&] {
            std::array<std::vector<glm::vec4>, 3> v;
            for (int c = 0; c < 3; ++c)
                v[std::size_t(c)] = expected.channel[c];
            return v;
        }());
        std::cout << "[ figures ] " << lpvVariantName(variant) << ", " << name << ": relative |GPU - CPU| "
                  << d.relative() << "; the option changes the reference by " << change.relative() << "\n";
        EXPECT_LT(d.relative(), 2e-5f) << name;
        EXPECT_GT(change.relative(), 1e-3f) << name;
    }
}

INSTANTIATE_TEST_SUITE_P(AllVariants, LpvOcclusionOptionsTest, ::testing::ValuesIn(kVariants),
                         [](const auto& p) { return std::string(lpvVariantName(p.param)); });

// 1024^2 VPLs of high flux into one 8^3 grid: integer atomics must neither
// overflow nor lose precision (the scale follows the brightest texel).
TEST_F(LpvGLTest, BrightMillionVplsDoNotOverflow) {
    LpvCase s{{glm::vec3(0.0f), 1.0f, 8}, 1e-6f};
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const int size = 1024;
    std::vector<Texel> texels(std::size_t(size) * std::size_t(size));
    for (Texel& t : texels)
        t = {glm::vec3(u(rng), u(rng), u(rng)) * 8.0f, randomUnit(rng), 1e6f * glm::vec3(u(rng), u(rng), u(rng))};
    FakeRsm rsm(size, {texels});
    for (LpvVariant variant : {LpvVariant::ComputeGather, LpvVariant::ComputeScatter}) {
        const ref::ShGrid expected = referenceAccumulator(s, texels, 4, false);
        const Difference d = compare(expected, runGpu(s, rsm, variant, 4, false));
        std::cout << "[ figures ] 1024^2 VPLs of up to 1e6 W, " << lpvVariantName(variant)
                  << ", 4 steps: max |GPU - CPU| = " << d.maxAbs << " of max " << d.maxValue << " (relative "
                  << d.relative() << ")\n";
        EXPECT_GT(d.maxValue, 1e9f); // the sums really are far beyond 32-bit integers at a scale of 1000
        // About 2000 VPLs per cell, each rounded to the injection's fixed-point
        // step (0.85 * brightest flux * 2^20 texels / 2^29): the rounding errors
        // add up to under 1e-4 of the brightest cell.
        EXPECT_LT(d.relative(), 1e-4f);
    }
}

} // namespace

namespace {

double totalDc(const std::array<std::vector<glm::vec4>, 3>& volume, int channel) {
    double sum = 0.0;
    for (const glm::vec4& v : volume[std::size_t(channel)])
        sum += double(v.x);
    return sum;
}

bool allFinite(const std::array<std::vector<glm::vec4>, 3>& volume) {
    for (const auto& channel : volume)
        for (const glm::vec4& v : channel)
            if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z) || !std::isfinite(v.w))
                return false;
    return true;
}

// An isotropic point: six VPLs in one cell whose cosine lobes add up to a
// constant (the band-1 parts cancel).
std::vector<Texel> isotropicPoint(const glm::vec3& centre, float flux) {
    std::vector<Texel> texels;
    for (const glm::vec3 n : {glm::vec3(1, 0, 0), glm::vec3(-1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, -1, 0),
                              glm::vec3(0, 0, 1), glm::vec3(0, 0, -1)})
        texels.push_back({centre, n, glm::vec3(flux)});
    return texels;
}

class LpvStabilityTest : public LpvGLTest, public ::testing::WithParamInterface<LpvVariant> {};

// The 6 axis neighbours of an isotropic point receive equal light, and the
// total flux does not grow from one step to the next while the light stays
// inside the grid.
TEST_P(LpvStabilityTest, PointSpreadsSymmetricallyAndDoesNotGainFlux) {
    const LpvVariant variant = GetParam();
    LpvCase s{{glm::vec3(0.0f), 1.0f, 32}, 0.01f};
    s.injectionOffset = 0.0f;
    FakeRsm rsm(4, {isotropicPoint(glm::vec3(16.5f), 10.0f)});
    const auto one = runGpu(s, rsm, variant, 1, false);
    auto at = [](const glm::ivec3& v) { return std::size_t(v.x + 32 * (v.y + 32 * v.z)); };
    const glm::ivec3 c(16);
    double lo = 1e30, hi = 0.0;
    for (const glm::ivec3 d : {glm::ivec3(1, 0, 0), glm::ivec3(-1, 0, 0), glm::ivec3(0, 1, 0), glm::ivec3(0, -1, 0),
                               glm::ivec3(0, 0, 1), glm::ivec3(0, 0, -1)}) {
        const double dc = one[0][at(c + d)].x;
        lo = std::min(lo, dc);
        hi = std::max(hi, dc);
    }
    std::cout << "[ figures ] " << lpvVariantName(variant) << ": axis neighbours after one step, spread (max - min) / max = "
              << (hi - lo) / hi << "\n";
    EXPECT_GT(lo, 0.0);
    EXPECT_LT((hi - lo) / hi, 1e-5);

    // Per-step flux: the DC summed over all cells of V_i = accumulator(i) - accumulator(i - 1).
    double previousAccumulated = totalDc(runGpu(s, rsm, variant, 0, false), 0);
    double previousStep = previousAccumulated;
    double worstGrowth = 0.0;
    for (int steps = 1; steps <= 12; ++steps) { // 12 < 16 cells to the border: nothing leaves the grid
        const double accumulated = totalDc(runGpu(s, rsm, variant, steps, false), 0);
        const double step = accumulated - previousAccumulated;
        worstGrowth = std::max(worstGrowth, step / previousStep - 1.0);
        previousAccumulated = accumulated;
        previousStep = step;
    }
    std::cout << "[ figures ] " << lpvVariantName(variant) << ": largest flux growth from one step to the next = "
              << worstGrowth << "\n";
    EXPECT_LT(worstGrowth, 1e-5); // measured at most 6.1e-7 on llvmpipe (float sums)
}

// 64 steps of a busy scene stay finite, with and without occlusion.
TEST_P(LpvStabilityTest, SixtyFourStepsStayFinite) {
    const LpvVariant variant = GetParam();
    LpvCase s{{glm::vec3(-1.0f), 0.25f, 16}, 0.002f};
    const auto texels = wallScene(s.grid, 400, 5.0f, 3);
    FakeRsm rsm(int(std::ceil(std::sqrt(double(texels.size())))), {texels});
    for (bool occlusion : {false, true}) {
        const auto volume = runGpu(s, rsm, variant, 64, occlusion);
        EXPECT_TRUE(allFinite(volume)) << "occlusion " << occlusion;
        EXPECT_GT(totalDc(volume, 0), 0.0);
    }
}

INSTANTIATE_TEST_SUITE_P(AllVariants, LpvStabilityTest, ::testing::ValuesIn(kVariants),
                         [](const auto& p) { return std::string(lpvVariantName(p.param)); });

// Degenerate texels (zero normal, NaN, zero flux, 1e6 W, far outside every
// cascade) are skipped or handled: the volume stays finite and the good VPLs
// still arrive.
TEST_F(LpvGLTest, DegenerateTexelsStayFinite) {
    LpvCase s{{glm::vec3(0.0f), 0.5f, 8}, 0.01f};
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    std::vector<Texel> texels = {
        {glm::vec3(2.0f), glm::vec3(0.0f), glm::vec3(1.0f)},              // zero normal
        {glm::vec3(2.1f), glm::vec3(0, 1, 0), glm::vec3(0.0f)},           // zero flux
        {glm::vec3(2.2f), glm::vec3(0, 1, 0), glm::vec3(1e6f)},           // very bright
        {glm::vec3(1e9f), glm::vec3(0, 1, 0), glm::vec3(1.0f)},           // far outside
        {glm::vec3(-1e30f), glm::vec3(0, 1, 0), glm::vec3(1.0f)},         // beyond int range
        {glm::vec3(nan), glm::vec3(0, 1, 0), glm::vec3(1.0f)},            // NaN position
        {glm::vec3(1.5f), glm::vec3(nan, 0, 0), glm::vec3(1.0f)},         // NaN normal
        {glm::vec3(1.6f), glm::vec3(0, 1, 0), glm::vec3(inf, 1.0f, 1.0f)}, // infinite flux
        {glm::vec3(3.0f), glm::vec3(0, 0, 1), glm::vec3(2.0f)},           // a good one
    };
    FakeRsm rsm(3, {texels});
    for (LpvVariant variant : kVariants) {
        const auto volume = runGpu(s, rsm, variant, 8, true);
        EXPECT_TRUE(allFinite(volume)) << lpvVariantName(variant);
        // The good and the bright VPL arrived: the usable ones match the reference.
        std::vector<Texel> usable = {texels[1], texels[2], texels[8]};
        const Difference d = compare(referenceAccumulator(s, usable, 8, true), volume);
        EXPECT_LT(d.relative(), 1e-4f) << lpvVariantName(variant);
    }
}

// A camera 1e5 units from the origin: every cascade still sits on its own
// cell grid and the LPV around it stays finite.
TEST_F(LpvGLTest, FarCameraStaysSnappedAndFinite) {
    const glm::vec3 camera(1e5f, -3.7e4f, 1e5f + 0.37f);
    const LpvCascadeSettings settings{4, 16, 0.5f, true};
    for (int k = 0; k < 4; ++k) {
        const LpvCascade cascade = lpvCascade(camera, k, settings);
        for (int a = 0; a < 3; ++a) {
            const double cells = double(cascade.origin[a]) / double(cascade.cellSize);
            EXPECT_NEAR(cells, std::round(cells), 1e-6) << "cascade " << k << " axis " << a;
        }
        EXPECT_LT(glm::length(cascade.origin + glm::vec3(0.5f * cascade.extent()) - camera), cascade.extent());
    }
    LpvCase s{{lpvCascade(camera, 0, settings).origin, 0.5f, 16}, 0.01f};
    FakeRsm rsm(4, {isotropicPoint(camera, 3.0f)});
    const auto volume = runGpu(s, rsm, LpvVariant::ComputeGather, 8, false);
    EXPECT_TRUE(allFinite(volume));
    EXPECT_GT(totalDc(volume, 0), 0.0);
}

} // namespace

// Directed propagation (docs/lpv.md): every variant against the reference on
// the floor-under-a-box scene, with 1 and 2 dilation passes, occlusion on; the
// normals volume is allocated only while the extension runs.
class LpvDirectedTest : public LpvGLTest, public ::testing::WithParamInterface<LpvVariant> {};

TEST_P(LpvDirectedTest, MatchesReferenceAndFreesItsVolume) {
    const LpvVariant variant = GetParam();
    const DirectedScene scene = floorUnderBox();
    LpvCase s{scene.grid, 0.125f * 0.125f};
    std::vector<Texel> texels;
    for (const ref::Vpl& v : scene.vpls)
        texels.push_back({v.position, v.normal, v.flux});
    for (const ref::Surfel& f : scene.surfels)
        texels.push_back({f.position, f.normal, glm::vec3(0.0f)});
    FakeRsm rsm(int(std::ceil(std::sqrt(double(texels.size())))), {texels});

    const auto undirected = runGpu(s, rsm, variant, 8, true);
    const std::size_t plainBytes = pass_->allocatedBytes();
    for (int dilation : {1, 2}) {
        const ref::ShGrid expected = referenceAccumulator(s, texels, 8, true, dilation);
        const auto gpu = runGpu(s, rsm, variant, 8, true, dilation);
        EXPECT_GT(pass_->allocatedBytes(), plainBytes);
        const Difference d = compare(expected, gpu);
        std::cout << "[ figures ] directed " << lpvVariantName(variant) << " 16^3, 8 steps, dilation " << dilation
                  << ": max |GPU - CPU| = " << d.maxAbs << " of max " << d.maxValue << " (relative " << d.relative()
                  << ")\n";
        EXPECT_GT(d.maxValue, 0.001f);
        EXPECT_LT(d.relative(), 2e-5f) << lpvVariantName(variant) << " dilation " << dilation;
        // And it changes something: the undirected volume differs.
        EXPECT_GT(compare(expected, undirected).relative(), 1e-3f);
    }
    runGpu(s, rsm, variant, 8, true);
    EXPECT_EQ(pass_->allocatedBytes(), plainBytes) << "the normals volume is freed when the extension is off";
}

INSTANTIATE_TEST_SUITE_P(AllVariants, LpvDirectedTest, ::testing::ValuesIn(kVariants),
                         [](const auto& p) { return std::string(lpvVariantName(p.param)); });

// The compute gather's interleaved ping-pong volumes (docs/lpv.md, "Memory
// layout"): allocated only while it runs, and a step the LPV viewer captures
// is unpacked into the per-channel volumes exactly as the raster gather,
// which has no interleaved copy, leaves that step.
TEST_F(LpvGLTest, InterleavedVolumesOnlyWhileTheComputeGatherRunsAndCapturesUnpack) {
    const int n = 8;
    LpvCase s{{glm::vec3(1.0f, -3.0f, 0.5f), 0.25f, n}, 0.002f};
    const auto texels = wallScene(s.grid, 60, 2.0f, 8u);
    FakeRsm rsm(int(std::ceil(std::sqrt(double(texels.size())))), {texels});

    pass_->setCapture(LpvCaptureRequest{0, 3});
    runGpu(s, rsm, LpvVariant::RasterGather, 6, true);
    ASSERT_TRUE(pass_->snapshot().has_value());
    const LpvSnapshot raster = *pass_->snapshot();
    const std::size_t withoutInterleaved = pass_->allocatedBytes();

    runGpu(s, rsm, LpvVariant::ComputeGather, 6, true);
    ASSERT_TRUE(pass_->snapshot().has_value());
    const LpvSnapshot gather = *pass_->snapshot();
    EXPECT_EQ(pass_->allocatedBytes() - withoutInterleaved, std::size_t(2 * 3 * n * n * n * 16))
        << "two 3N x N x N RGBA32F volumes for one cascade";
    EXPECT_EQ(gather.step, 3);
    float maxValue = 0.0f, maxDifference = 0.0f;
    for (std::size_t c = 0; c < 3; ++c) {
        ASSERT_EQ(gather.stepVolume[c].size(), raster.stepVolume[c].size());
        for (std::size_t i = 0; i < gather.stepVolume[c].size(); ++i)
            for (int j = 0; j < 4; ++j) {
                maxValue = std::max(maxValue, std::abs(raster.stepVolume[c][i][j]));
                maxDifference = std::max(maxDifference, std::abs(gather.stepVolume[c][i][j] - raster.stepVolume[c][i][j]));
                maxDifference = std::max(maxDifference, std::abs(gather.accumulatedToStep[c][i][j] -
                                                                 raster.accumulatedToStep[c][i][j]));
            }
    }
    std::cout << "[ figures ] step 3 of 6 captured, compute gather against raster gather: max difference "
              << maxDifference << " of max " << maxValue << "\n";
    EXPECT_GT(maxValue, 1e-3f) << "light has reached step 3";
    EXPECT_LT(maxDifference, 2e-5f * maxValue);

    pass_->setCapture(std::nullopt);
    runGpu(s, rsm, LpvVariant::ComputeScatter, 6, true);
    EXPECT_EQ(pass_->allocatedBytes(), withoutInterleaved) << "freed when another variant runs";
}

// lpv.cascadeSteps = byCellSize (issue #25): cascade k propagates steps >> k
// steps; every variant agrees with the CPU reference run for that many steps
// on each cascade, and cascades that stopped keep their accumulator.
TEST_F(LpvGLTest, CoarserCascadesRunFewerStepsAndMatchTheReference) {
    const int n = 8;
    const int steps = 6; // cascades run 6, 3, 1
    std::vector<LpvCase> cases;
    std::vector<std::vector<Texel>> tiles;
    for (int k = 0; k < 3; ++k) {
        const float cell = 0.25f * float(1 << k);
        LpvCase s{{glm::vec3(-0.5f * cell * float(n)), cell, n}, 0.002f * float(1 << (2 * k))};
        tiles.push_back(wallScene(s.grid, 120, 2.0f, unsigned(7 + k)));
        cases.push_back(s);
    }
    std::size_t most = 0;
    for (const auto& t : tiles)
        most = std::max(most, t.size());
    FakeRsm rsm(int(std::ceil(std::sqrt(double(most)))), tiles);
    for (LpvVariant variant : kVariants) {
        LpvSettings settings;
        settings.gridSize = n;
        settings.propagationSteps = steps;
        settings.stepsByCellSize = true;
        settings.occlusion = true;
        settings.gvFromCamera = false;
        settings.variant = variant;
        settings.requestedCascades = 3;
        settings.rsmCascades = 3;
        ASSERT_EQ(settings.stepsFor(0), 6);
        ASSERT_EQ(settings.stepsFor(1), 3);
        ASSERT_EQ(settings.stepsFor(2), 1);
        LpvRsmInput input;
        for (const LpvCase& s : cases) {
            input.cascades.push_back(LpvCascade{s.grid.origin, s.grid.cellSize, s.grid.n});
            input.texelArea.push_back(s.texelArea);
        }
        input.tileSize = rsm.tileSize;
        input.position = rsm.position.id();
        input.normal = rsm.normal.id();
        input.flux = rsm.flux.id();
        input.towardSun = cases[0].towardSun;
        timer_.beginFrame();
        auto ok = pass_->run(settings, input, nullptr, timer_);
        ASSERT_TRUE(ok.has_value()) << ok.error().describe();
        for (int k = 0; k < 3; ++k) {
            const ref::ShGrid expected = referenceAccumulator(cases[std::size_t(k)], tiles[std::size_t(k)],
                                                              settings.stepsFor(k), true);
            const Difference d = compare(expected, pass_->readAccumulator(k));
            std::cout << "[ figures ] " << lpvVariantName(variant) << " cascade " << k << ", "
                      << settings.stepsFor(k) << " steps: max |GPU - CPU| = " << d.maxAbs << " of max "
                      << d.maxValue << " (relative " << d.relative() << ")\n";
            EXPECT_GT(d.maxValue, 0.01f);
            EXPECT_LT(d.relative(), 2e-5f) << lpvVariantName(variant) << " cascade " << k;
            // Not the full step count: the coarse cascades' light differs from 6 steps' by far more.
            if (k > 0) {
                const Difference full = compare(referenceAccumulator(cases[std::size_t(k)], tiles[std::size_t(k)],
                                                                     steps, true),
                                                pass_->readAccumulator(k));
                EXPECT_GT(full.relative(), 1e-3f) << "cascade " << k << " ran all the steps";
            }
        }
    }
}
