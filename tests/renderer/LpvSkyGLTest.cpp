// Sky light injection (docs/lpv.md) on llvmpipe: the injection kernel against
// LpvReference's injectSky on a hand-made height map, in the gather and the
// scatter variant (whose fixed-point scale must cover the sky's cells).
#include "GlFixture.h"
#include "ShGridCompare.h"

#include "passes/lpv/LpvPass.h"
#include "lpv/renderer/GpuTimer.h"
#include "lpv/renderer/lpv/LpvReference.h"

#include <cmath>
#include <iostream>

using namespace lpv::renderer;
namespace ref = lpv::renderer::lpvref;

namespace {

Texture layerTexture(GLenum format, int size, GLenum dataFormat, const void* data) {
    Texture t = createTexture(GL_TEXTURE_2D_ARRAY);
    glTextureStorage3D(t.id(), 1, format, size, size, 1);
    glTextureSubImage3D(t.id(), 0, 0, 0, 0, size, size, 1, dataFormat, GL_FLOAT, data);
    return t;
}

class LpvSkyGLTest : public GlTest, public ::testing::WithParamInterface<LpvVariant> {};

TEST_P(LpvSkyGLTest, InjectionMatchesReference) {
    auto pass = LpvPass::create();
    ASSERT_TRUE(pass.has_value()) << pass.error().describe();
    const ref::GridFrame grid{glm::vec3(-2.0f, -1.0f, 3.0f), 0.5f, 16};

    // A height map of 2 texels per cell: a courtyard (ground at y = 0.1)
    // inside walls 3.3 high, a roof at 9 (above the cascade) over one corner,
    // and a strip with no surface at all.
    ref::HeightMap map;
    map.size = 32;
    map.min = {grid.origin.x, grid.origin.z};
    map.texelSize = grid.cellSize / 2.0f;
    const float top = 12.0f, bottom = -4.0f;
    std::vector<float> depth(std::size_t(map.size * map.size));
    map.height.resize(depth.size());
    for (int j = 0; j < map.size; ++j)
        for (int i = 0; i < map.size; ++i) {
            float h = 0.1f;
            if (i < 4 || j < 4 || i >= 28)
                h = 3.3f;
            if (i >= 24 && j >= 24)
                h = 9.0f;
            const bool empty = j >= 30;
            const std::size_t t = std::size_t(i + map.size * j);
            depth[t] = empty ? 1.0f : (top - h) / (top - bottom);
            map.height[t] = empty ? -std::numeric_limits<float>::infinity() : h;
        }
    const glm::vec3 radiance(0.5f, 0.7f, 1.0f);
    const Texture depthTexture = layerTexture(GL_DEPTH_COMPONENT32F, map.size, GL_DEPTH_COMPONENT, depth.data());

    // An RSM with one dark texel: the sky is the only light.
    const float zero[4] = {0, 0, 0, 0};
    const Texture position = layerTexture(GL_RGBA32F, 1, GL_RGBA, zero), normal = layerTexture(GL_RGBA32F, 1, GL_RGBA, zero),
                  flux = layerTexture(GL_RGBA32F, 1, GL_RGBA, zero);
    LpvRsmInput rsm;
    rsm.cascades = {LpvCascade{grid.origin, grid.cellSize, grid.n}};
    rsm.texelArea = {0.01f};
    rsm.tileSize = 1;
    rsm.position = position.id();
    rsm.normal = normal.id();
    rsm.flux = flux.id();
    LpvSkyInput sky{depthTexture.id(), map.size, map.min, map.texelSize, top, bottom, radiance};

    const ref::ShGrid injected = ref::injectSky(grid, map, radiance);
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
