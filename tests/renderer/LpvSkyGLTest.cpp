// Sky light injection (docs/lpv.md) on llvmpipe: the injection kernel against
// LpvReference's injectSky on a hand-made height map, in the gather and the
// scatter variant (whose fixed-point scale must cover the sky's cells).
#include "GlFixture.h"
#include "ShGridCompare.h"
#include "SkyCourtyard.h"

#include "passes/lpv/LpvPass.h"
#include "lpv/renderer/GpuTimer.h"
#include "lpv/renderer/lpv/LpvReference.h"

#include <cmath>
#include <iostream>

using namespace lpv::renderer;
namespace ref = lpv::renderer::lpvref;

namespace {

class LpvSkyGLTest : public GlTest, public ::testing::WithParamInterface<LpvVariant> {};

TEST_P(LpvSkyGLTest, InjectionMatchesReference) {
    auto pass = LpvPass::create();
    ASSERT_TRUE(pass.has_value()) << pass.error().describe();
    const SkyCourtyard courtyard;
    const ref::GridFrame& grid = courtyard.grid;
    const LpvRsmInput rsm = courtyard.rsm();
    const LpvSkyInput sky = courtyard.sky();

    const ref::ShGrid injected = ref::injectSky(grid, courtyard.map, courtyard.radiance);
    for (int steps : {0, 4}) {
        LpvSettings settings;
        settings.gridSize = grid.n;
        settings.propagationSteps = steps;
        settings.occlusion = false;
        settings.gvFromCamera = false;
        settings.variant = GetParam();
        GpuTimer timer;
        timer.beginFrame();
        auto ok = pass->run(settings, rsm, nullptr, timer, &sky);
        ASSERT_TRUE(ok.has_value()) << ok.error().describe();
        EXPECT_NE(pass->note().find("sky light injected"), std::string::npos) << pass->note();
        const auto gpu = pass->readAccumulator(0);
        const ref::ShGrid expected = ref::propagateAndAccumulate(injected, nullptr, steps);
        float maxValue = 0.0f;
        const double relative = relativeDifference(expected, gpu, &maxValue);
        std::cout << "[ figures ] sky " << lpvVariantName(GetParam()) << ", " << steps
                  << " steps: max |GPU - CPU| = " << relative * maxValue << " of max " << maxValue << "\n";
        EXPECT_GT(maxValue, 0.0f);
        EXPECT_LT(relative, 2e-5);
    }
    // Where the sky went, read from the reference: the courtyard's first open
    // cell is y = 3 (ground 0.1 in cell 2), the walls' y = 9 (3.3 in cell 8),
    // under the roof nothing, and the empty strip's bottom cell 0.
    EXPECT_GT(injected.at(2, 8, 3, 8).x, 0.0f);
    EXPECT_GT(injected.at(2, 0, 9, 8).x, 0.0f);
    EXPECT_GT(injected.at(2, 5, 0, 15).x, 0.0f);
    for (int y = 0; y < grid.n; ++y)
        EXPECT_EQ(injected.at(2, 14, y, 14).x, 0.0f) << "under the roof, y = " << y;
}

INSTANTIATE_TEST_SUITE_P(Variants, LpvSkyGLTest,
                         ::testing::Values(LpvVariant::ComputeGather, LpvVariant::ComputeScatter),
                         [](const auto& p) { return std::string(lpvVariantName(p.param)); });

} // namespace
