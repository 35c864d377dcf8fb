#pragma once
// The LPV's GL tests share this: an LpvPass made for each test, and one run
// of it over hand-written RSM tiles (FakeRsm.h).
#include "FakeRsm.h"
#include "GlFixture.h"
#include "passes/lpv/LpvPass.h"
#include "lpv/renderer/GpuTimer.h"
#include "lpv/renderer/lpv/LpvReference.h"

#include <optional>
#include <random>
#include <vector>

namespace lpv::renderer {

// The LPV's RSM input: `rsm`'s tiles feeding `cascades` (tile k feeds cascade
// k). Any RSM of tileSize and position, normal and flux arrays will do.
template <class Rsm>
LpvRsmInput rsmInputOf(const Rsm& rsm, std::vector<LpvCascade> cascades, std::vector<float> texelArea,
                              glm::vec3 towardSun = glm::vec3(0.0f, 1.0f, 0.0f)) {
    LpvRsmInput input;
    input.cascades = std::move(cascades);
    input.texelArea = std::move(texelArea);
    input.tileSize = rsm.tileSize;
    input.position = rsm.position.id();
    input.normal = rsm.normal.id();
    input.flux = rsm.flux.id();
    input.towardSun = towardSun;
    return input;
}

// A random direction, uniform on the sphere.
inline glm::vec3 randomUnit(std::mt19937& rng) {
    std::normal_distribution<float> g;
    glm::vec3 v;
    do {
        v = {g(rng), g(rng), g(rng)};
    } while (glm::length(v) < 1e-3f);
    return glm::normalize(v);
}

// The LPV tests' wall scene, in one cascade: VPLs scattered through the
// lower 45% of x, lit with random colours, and a wall of dark surfels
// across the middle (x = 0.6 of the cascade) facing -x.
inline std::vector<Texel> wallScene(const lpvref::GridFrame& grid, int vplCount, float fluxScale,
                                    unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<Texel> texels;
    const float extent = grid.cellSize * float(grid.n);
    for (int i = 0; i < vplCount; ++i) {
        const glm::vec3 p = grid.origin + glm::vec3(u(rng) * 0.45f, u(rng), u(rng)) * extent;
        texels.push_back({p, randomUnit(rng), fluxScale * glm::vec3(u(rng), u(rng), u(rng))});
    }
    // The wall: a grid of surfels on the plane x = 0.6 extent.
    const int side = grid.n * 2;
    for (int y = 0; y < side; ++y)
        for (int z = 0; z < side; ++z) {
            const glm::vec3 p =
                grid.origin + glm::vec3(0.6f * extent, (float(y) + 0.5f) / float(side) * extent,
                                        (float(z) + 0.5f) / float(side) * extent);
            texels.push_back({p, glm::vec3(-1.0f, 0.0f, 0.0f), glm::vec3(0.0f)});
        }
    return texels;
}

class LpvPassGLTest : public GlTest {
  protected:
    void SetUp() override {
        GlTest::SetUp();
        auto pass = LpvPass::create();
        ASSERT_TRUE(pass.has_value()) << pass.error().describe();
        pass_.emplace(std::move(*pass));
    }

    // One frame of the pass; a failure or a GL error fails the test.
    void runPass(const LpvSettings& settings, const LpvRsmInput& input, const LpvCameraInput* camera = nullptr) {
        timer_.beginFrame();
        auto ok = pass_->run(settings, input, camera, timer_);
        EXPECT_TRUE(ok.has_value()) << (ok ? "" : ok.error().describe());
        EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    }

    std::optional<LpvPass> pass_;
    GpuTimer timer_;
};

} // namespace lpv::renderer
