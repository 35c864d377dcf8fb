// The visibility-aware lookup on the GPU against its CPU twin
// (LpvVisibility.h, docs/lpv.md "Visibility-aware lookup"): the moments
// lpv_visibility.comp builds from the pass's own geometry volume, and
// lpv_lookup.glsl's weighted taps (through lpv_lookup_test.comp) at random
// points of the pass's own accumulator.
#include "LpvPassFixture.h"
#include "LookupKernel.h"
#include "ThinWallRooms.h"

#include "passes/lpv/LpvPass.h"
#include "lpv/renderer/GpuTimer.h"
#include "lpv/renderer/lpv/LpvVisibility.h"

#include <cmath>
#include <iostream>
#include <random>

using namespace lpv::renderer;
namespace ref = lpv::renderer::lpvref;

namespace {

class LpvVisibilityGLTest : public LpvPassGLTest {
  protected:
    // One cascade from one hand-written tile, GV from the RSM only, the visibility moments on.
    void run(const ref::GridFrame& grid, float texelArea, const std::vector<Texel>& texels, int steps) {
        const FakeRsm rsm(int(std::ceil(std::sqrt(double(texels.size())))), {texels});
        LpvSettings settings;
        settings.gridSize = grid.n;
        settings.propagationSteps = steps;
        settings.gvFromCamera = false;
        settings.visibility = true;
        runPass(settings, rsmInputOf(rsm, {LpvCascade{grid.origin, grid.cellSize, grid.n}}, {texelArea}));
    }

    ref::GvGrid gpuGv(int n) const {
        ref::GvGrid gv(n);
        gv.potential = pass_->readGeometryVolume(0);
        return gv;
    }
    ref::MomentsGrid gpuMoments(int n) const {
        const auto texels = pass_->readVisibilityMoments(0);
        ref::MomentsGrid m(n);
        for (int z = 0; z < n; ++z)
            for (int y = 0; y < n; ++y)
                for (int x = 0; x < n; ++x)
                    for (int a = 0; a < 3; ++a)
                        m.moments[m.index(x, y, z)][std::size_t(a)] =
                            texels[std::size_t(3 * x + a) + std::size_t(3 * n) * std::size_t(y + n * z)];
        return m;
    }
    ref::ShGrid gpuAccumulator(int n) const {
        ref::ShGrid acc(n);
        auto volume = pass_->readAccumulator(0);
        for (int c = 0; c < 3; ++c)
            acc.channel[c] = volume[std::size_t(c)];
        return acc;
    }

};

// 600 random texels (VPLs and surfels of every orientation) and the thin wall between two rooms.
std::vector<std::pair<const char*, std::vector<Texel>>> scenes(const ref::GridFrame& grid) {
    std::mt19937 rng(24);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<Texel> random;
    const float extent = grid.cellSize * float(grid.n);
    for (int i = 0; i < 600; ++i) {
        const glm::vec3 n = glm::normalize(glm::vec3(u(rng) - 0.5f, u(rng) - 0.5f, u(rng) - 0.5f) + 1e-3f);
        random.push_back({grid.origin + glm::vec3(u(rng), u(rng), u(rng)) * extent, n, glm::vec3(u(rng))});
    }
    std::vector<Texel> rooms;
    for (const auto& t : thinwall::twoRooms(grid, 8.0f))
        rooms.push_back({grid.origin + t.position, t.normal, t.flux});
    return {{"random texels", random}, {"thin wall", rooms}};
}

} // namespace

TEST_F(LpvVisibilityGLTest, MomentsMatchTheCpuTwin) {
    const ref::GridFrame grid{glm::vec3(-1.0f), 0.25f, 16};
    for (const auto& [name, texels] : scenes(grid)) {
        run(grid, 0.2f * 0.125f * 0.125f * 4.0f, texels, 4);
        // From the GPU's own GV, so only lpv_visibility.comp is compared (the GV is LpvGLTest's).
        const ref::MomentsGrid cpu = ref::buildMoments(gpuGv(grid.n), ref::VisibilitySettings{});
        const ref::MomentsGrid gpu = gpuMoments(grid.n);
        float worst = 0.0f;
        int closer = 0; // cell directions that see a surface before the far distance
        for (std::size_t i = 0; i < cpu.moments.size(); ++i)
            for (int a = 0; a < 3; ++a) {
                const glm::vec4 d = glm::abs(cpu.moments[i][std::size_t(a)] - gpu.moments[i][std::size_t(a)]);
                worst = std::max({worst, d.x, d.y, d.z, d.w});
                closer += (cpu.moments[i][std::size_t(a)].x < 1.99f) + (cpu.moments[i][std::size_t(a)].z < 1.99f);
            }
        std::cout << "[ figures ] visibility moments, " << name << ", 16^3: max |GPU - CPU| = " << worst
                  << " cells (or cells^2); " << closer << " of " << 6 * cpu.moments.size()
                  << " cell directions see a surface\n";
        EXPECT_GT(closer, 100) << "a scene that blocks nothing would test nothing";
        // Measured 4.8e-7 (random texels) and 0 (thin wall): float rounding; the
        // moments reach 4 (cells^2), so 1e-5 is 40 float steps there.
        EXPECT_LT(worst, 1e-5f);
    }
}

TEST_F(LpvVisibilityGLTest, LookupMatchesTheCpuTwin) {
    const ref::GridFrame grid{glm::vec3(-1.0f), 0.25f, 16};
    std::mt19937 rng(2024);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::normal_distribution<float> gauss;
    const ref::VisibilitySettings settings;
    for (const auto& [name, texels] : scenes(grid)) {
        run(grid, 0.2f * 0.125f * 0.125f * 4.0f, texels, 8);
        const ref::ShGrid acc = gpuAccumulator(grid.n);
        const ref::MomentsGrid moments = gpuMoments(grid.n);
        std::vector<LookupPoint> points;
        for (int i = 0; i < 4000; ++i)
            points.push_back({grid.origin + glm::vec3(u(rng), u(rng), u(rng)) * grid.cellSize * float(grid.n),
                              glm::normalize(glm::vec3(gauss(rng), gauss(rng), gauss(rng)) + 1e-4f)});
        const auto gpu = runLookup(*pass_, 0, true, settings.normalBias, points);
        ASSERT_EQ(gpu.size(), points.size());
        float peak = 0.0f, worst = 0.0f;
        int changed = 0; // points whose red irradiance visibility changed by 5% or more
        std::vector<glm::vec3> cpu, plain;
        for (const LookupPoint& p : points) {
            cpu.push_back(ref::irradianceVisibleAt(acc, moments, grid, p.position, p.normal, settings));
            plain.push_back(ref::irradianceAt(acc, grid, p.position, p.normal));
            peak = std::max({peak, cpu.back().x, cpu.back().y, cpu.back().z});
        }
        for (std::size_t i = 0; i < points.size(); ++i)
            for (int c = 0; c < 3; ++c) {
                worst = std::max(worst, std::abs(gpu[i][c] - cpu[i][c]));
                changed += c == 0 && std::abs(cpu[i][c] - plain[i][c]) >= 0.05f * std::max(plain[i][c], 1e-20f);
            }
        const float relative = worst / std::max(peak, 1e-20f);
        std::cout << "[ figures ] visibility-aware lookup, " << name << ", " << points.size()
                  << " points: max |GPU - CPU| / peak = " << relative << "; " << changed
                  << " points where visibility changes the plain lookup by 5% or more\n";
        // Measured 13 points (random texels: smooth light, few walls) and 258
        // (thin wall): a comparison where no weight mattered would test nothing.
        EXPECT_GT(changed, std::string(name) == "thin wall" ? 100 : 5) << "the visibility weights must matter";
        // Measured 5.0e-8 / 9.7e-8: float sums of 8 taps in the same order;
        // a tap weighted differently would be 1e-2 or more.
        EXPECT_LT(relative, 1e-5f);
    }
}

// lpv.lookupOffset (issue #24): the plain lookup read half a cell in front of
// the surface, against lpvref::irradianceAt with the same offset.
TEST_F(LpvVisibilityGLTest, LookupOffsetMatchesTheCpuTwin) {
    const ref::GridFrame grid{glm::vec3(-1.0f), 0.25f, 16};
    std::mt19937 rng(77);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::normal_distribution<float> gauss;
    const auto [name, texels] = scenes(grid).front();
    run(grid, 0.2f * 0.125f * 0.125f * 4.0f, texels, 8);
    const ref::ShGrid acc = gpuAccumulator(grid.n);
    std::vector<LookupPoint> points;
    for (int i = 0; i < 2000; ++i)
        points.push_back({grid.origin + glm::vec3(u(rng), u(rng), u(rng)) * grid.cellSize * float(grid.n),
                          glm::normalize(glm::vec3(gauss(rng), gauss(rng), gauss(rng)) + 1e-4f)});
    const auto gpu = runLookup(*pass_, 0, false, 0.0f, points, 0.5f);
    ASSERT_EQ(gpu.size(), points.size());
    float peak = 0.0f, worst = 0.0f, moved = 0.0f;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const glm::vec3 cpu = ref::irradianceAt(acc, grid, points[i].position, points[i].normal, 0.5f);
        const glm::vec3 unmoved = ref::irradianceAt(acc, grid, points[i].position, points[i].normal);
        for (int c = 0; c < 3; ++c) {
            peak = std::max(peak, cpu[c]);
            worst = std::max(worst, std::abs(gpu[i][c] - cpu[c]));
            moved = std::max(moved, std::abs(cpu[c] - unmoved[c]));
        }
    }
    std::cout << "[ figures ] lookup 0.5 cells in front, " << name << ": max |GPU - CPU| / peak = " << worst / peak
              << "; the offset changes the lookup by up to " << moved / peak << " of the peak\n";
    EXPECT_GT(moved / peak, 1e-2f); // the offset must move the reads, or this tests nothing
    // Measured 9.4e-8 on llvmpipe, whose trilinear weights are exact; other
    // GPUs filter with 8-bit fractions (up to 1/256 of a value), hence 1e-2.
    EXPECT_LT(worst / peak, 1e-2f);
}
