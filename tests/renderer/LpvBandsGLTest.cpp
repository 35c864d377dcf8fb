// lpv.shBands (issue #47) through the renderer. Three bands run in the
// compute gather: each three-band stage (injection, the geometry volume's
// occlusion, propagation, the lookup) against its CPU twin lpvref::bands on a
// small grid, and the Cornell box rendered with three bands. The other three
// variants refuse lpv.shBands = 3 with an error that names the parameter and
// the variant, and render again at 2.
#include "LookupKernel.h"
#include "LpvPassFixture.h"
#include "SkyCourtyard.h"
#include "ThinWallRooms.h"

#include "lpv/renderer/ForwardRenderer.h"
#include "lpv/renderer/SceneAnalysis.h"
#include "lpv/renderer/lpv/LpvBands.h"
#include "lpv/scene/CornellBox.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <random>

using namespace lpv;
using namespace lpv::renderer;
namespace ref = lpv::renderer::lpvref;

TEST_F(GlTest, LpvVariantsOtherThanComputeGatherRefuseThreeShBandsNamingThemselves) {
    scene::Project project = scene::makeCornellBoxProject();
    auto r = renderer::ForwardRenderer::create();
    ASSERT_TRUE(r.has_value());
    r->setScene(project.scene);
    const scene::Camera& camera = project.scene.cameras.front();
    for (const char* variant : {"computeScatter", "rasterGather", "rasterScatter"}) {
        SCOPED_TRACE(variant);
        scene::ParameterSet params = project.parameters;
        ASSERT_TRUE(params.setFromText("lpv.variant", variant, "test").has_value());
        ASSERT_TRUE(params.setFromText("lpv.shBands", "3", "test").has_value());
        auto refused = r->render(project.scene, params, camera, 64, 64);
        ASSERT_FALSE(refused.has_value());
        const std::string message = refused.error().describe();
        EXPECT_NE(message.find("lpv.shBands"), std::string::npos) << message;
        EXPECT_NE(message.find(std::string("the ") + variant + " LPV runs two bands only"), std::string::npos)
            << message;
        ASSERT_TRUE(params.setFromText("lpv.shBands", "2", "test").has_value());
        auto ok = r->render(project.scene, params, camera, 64, 64);
        EXPECT_TRUE(ok.has_value()) << (ok ? "" : ok.error().describe());
    }
    // The reduced-resolution lookup pass reads two bands: refused with the parameter to change.
    scene::ParameterSet params = project.parameters;
    ASSERT_TRUE(params.setFromText("lpv.shBands", "3", "test").has_value());
    ASSERT_TRUE(params.setFromText("lpv.lookupResolution", "half", "test").has_value());
    auto refused = r->render(project.scene, params, camera, 64, 64);
    ASSERT_FALSE(refused.has_value());
    EXPECT_NE(refused.error().describe().find("lpv.lookupResolution = full"), std::string::npos)
        << refused.error().describe();
    // auto picks full for three bands (a view where it picks quarter for two), and renders.
    ASSERT_TRUE(params.setFromText("lpv.lookupResolution", "auto", "test").has_value());
    const auto three = renderer::decideLookupResolution(params, 1024, 600, 1.0f, 100);
    EXPECT_EQ(three.reduction, 1) << three.reason;
    ASSERT_TRUE(params.setFromText("lpv.shBands", "2", "test").has_value());
    EXPECT_GT(renderer::decideLookupResolution(params, 1024, 600, 1.0f, 100).reduction, 1);
    ASSERT_TRUE(params.setFromText("lpv.shBands", "3", "test").has_value());
    auto automatic = r->render(project.scene, params, camera, 64, 64);
    EXPECT_TRUE(automatic.has_value()) << (automatic ? "" : automatic.error().describe());
}

namespace {

struct Difference {
    double maxAbs = 0.0, maxValue = 0.0;
    double relative() const { return maxValue > 0.0 ? maxAbs / maxValue : maxAbs; }
    void add(float gpu, float cpu) {
        maxAbs = std::max(maxAbs, double(std::abs(gpu - cpu)));
        maxValue = std::max(maxValue, double(std::abs(cpu)));
    }
};

class LpvThreeBandsGLTest : public LpvPassGLTest {
  protected:
    const ref::GridFrame grid_{glm::vec3(-2.0f, 0.0f, 1.0f), 0.5f, 8};
    const float texelArea_ = 0.01f;
    const glm::vec3 towardSun_{0.0f, 1.0f, 0.0f};
    std::vector<Texel> texels_ = wallScene(grid_, 200, 3.0f, 7);
    FakeRsm rsm_{int(std::ceil(std::sqrt(double(texels_.size())))), {texels_}};

    LpvSettings settings(int steps, bool occlusion) const {
        LpvSettings s;
        s.shBands = 3;
        s.gridSize = grid_.n;
        s.propagationSteps = steps;
        s.injectionOffset = 1.0f;
        s.occlusion = occlusion;
        s.occlusionStrength = 1.333f;
        s.gvFromCamera = false;
        return s;
    }
    void run(const LpvSettings& s) {
        runPass(s, rsmInputOf(rsm_, {LpvCascade{grid_.origin, grid_.cellSize, grid_.n}}, {texelArea_}, towardSun_));
    }
    ref::bands::Gv<3> cpuGv(float strength) const {
        std::vector<ref::Surfel> surfels;
        for (const Texel& t : texels_)
            surfels.push_back({t.position, t.normal, texelArea_ / std::max(glm::dot(t.normal, towardSun_), 0.2f)});
        ref::bands::Gv<3> gv = ref::bands::injectSurfels<3>(grid_, surfels);
        gv.strength = strength;
        return gv;
    }
    ref::bands::Grid<3> cpuInjected() const {
        std::vector<ref::Vpl> vpls;
        for (const Texel& t : texels_)
            vpls.push_back({t.position, t.normal, t.flux});
        return ref::bands::injectVpls<3>(grid_, vpls, 1.0f);
    }
    Difference compareAccumulator(const ref::bands::Grid<3>& cpu) const {
        const auto gpu = pass_->readAccumulatorBands(0);
        Difference d;
        for (int c = 0; c < 3; ++c) {
            EXPECT_EQ(gpu[std::size_t(c)].size(), cpu.channel[c].size());
            for (std::size_t i = 0; i < cpu.channel[c].size() && i < gpu[std::size_t(c)].size(); ++i)
                for (int j = 0; j < 9; ++j)
                    d.add(gpu[std::size_t(c)][i][std::size_t(j)], cpu.channel[c][i][j]);
        }
        return d;
    }
    // The largest |band-2 coefficient|: zero would mean band 2 was never computed.
    static double band2Peak(const ref::bands::Grid<3>& g) {
        double peak = 0.0;
        for (int c = 0; c < 3; ++c)
            for (const auto& f : g.channel[c])
                for (int j = 4; j < 9; ++j)
                    peak = std::max(peak, double(std::abs(f[j])));
        return peak;
    }
};

} // namespace

TEST_F(LpvThreeBandsGLTest, InjectionMatchesTheCpuTwin) {
    run(settings(0, true));
    const auto cpu = cpuInjected();
    const Difference d = compareAccumulator(cpu);
    std::cout << "[ figures ] three-band injection 8^3: max |GPU - CPU| = " << d.maxAbs << " of " << d.maxValue
              << " (relative " << d.relative() << "), band-2 peak " << band2Peak(cpu) << "\n";
    EXPECT_GT(band2Peak(cpu), 0.01);
    EXPECT_LT(d.relative(), 1e-5);
}

TEST_F(LpvThreeBandsGLTest, GeometryVolumeMatchesTheCpuTwin) {
    run(settings(0, true));
    const auto cpu = cpuGv(1.0f);
    const auto gpu = pass_->readGeometryVolumeBands(0);
    ASSERT_EQ(gpu.size(), cpu.potential.size());
    Difference d, band2;
    for (std::size_t i = 0; i < gpu.size(); ++i)
        for (int j = 0; j < 9; ++j) {
            d.add(gpu[i][std::size_t(j)], cpu.potential[i][j]);
            if (j >= 4)
                band2.add(gpu[i][std::size_t(j)], cpu.potential[i][j]);
        }
    std::cout << "[ figures ] three-band GV 9^3: max |GPU - CPU| = " << d.maxAbs << " of " << d.maxValue
              << "; band 2 peak " << band2.maxValue << "\n";
    EXPECT_GT(band2.maxValue, 0.1);
    EXPECT_LT(d.relative(), 1e-4); // the GV's fixed point is 2^-16
}

TEST_F(LpvThreeBandsGLTest, PropagationWithOcclusionMatchesTheCpuTwin) {
    const auto gv = cpuGv(1.333f);
    for (const int steps : {1, 4}) {
        for (const bool occlusion : {false, true}) {
            SCOPED_TRACE(testing::Message() << steps << " steps, occlusion " << occlusion);
            run(settings(steps, occlusion));
            const auto cpu = ref::bands::propagateAndAccumulate<3>(cpuInjected(), occlusion ? &gv : nullptr, steps);
            const Difference d = compareAccumulator(cpu);
            std::cout << "[ figures ] three-band propagation 8^3, " << steps << " steps, occlusion " << occlusion
                      << ": relative " << d.relative() << " (max " << d.maxValue << ")\n";
            EXPECT_LT(d.relative(), 2e-5);
        }
    }
    // lpv.twoSidedOcclusion: a surfel blocks light from behind as well.
    {
        LpvSettings s = settings(4, true);
        s.twoSidedOcclusion = true;
        run(s);
        auto twoSided = gv;
        twoSided.twoSided = true;
        const Difference d = compareAccumulator(ref::bands::propagateAndAccumulate<3>(cpuInjected(), &twoSided, 4));
        std::cout << "[ figures ] three-band propagation 8^3, 4 steps, two-sided occlusion: relative " << d.relative()
                  << "\n";
        EXPECT_LT(d.relative(), 2e-5);
    }
    // Occlusion must matter (or the comparison above says nothing about it).
    const auto open = ref::bands::propagateAndAccumulate<3>(cpuInjected(), nullptr, 4);
    const auto walled = ref::bands::propagateAndAccumulate<3>(cpuInjected(), &gv, 4);
    double behindOpen = 0.0, behindWall = 0.0;
    for (int z = 0; z < grid_.n; ++z)
        for (int y = 0; y < grid_.n; ++y)
            for (int x = 6; x < grid_.n; ++x) {
                behindOpen += open.at(0, x, y, z)[0];
                behindWall += walled.at(0, x, y, z)[0];
            }
    EXPECT_GT(behindOpen, 1.5 * behindWall);
}

TEST_F(LpvThreeBandsGLTest, DirectedPropagationMatchesTheCpuTwin) {
    LpvSettings s = settings(3, true);
    s.directed = true;
    s.directedDilation = 1;
    run(s);
    std::vector<ref::Vpl> vpls; // every texel's normal counts, as the GPU's injection sums them
    for (const Texel& t : texels_)
        vpls.push_back({t.position, t.normal, t.flux});
    const auto normals = ref::dilateNormals(ref::injectNormals(grid_, vpls, 1.0f));
    const auto gv = cpuGv(1.333f);
    const auto cpu = ref::bands::propagateAndAccumulate<3>(cpuInjected(), &gv, 3, &normals);
    const Difference d = compareAccumulator(cpu);
    std::cout << "[ figures ] three-band directed propagation 8^3, 3 steps: relative " << d.relative() << "\n";
    EXPECT_LT(d.relative(), 2e-5);
}

TEST_F(LpvThreeBandsGLTest, LookupMatchesTheCpuTwin) {
    run(settings(4, true));
    const auto gv = cpuGv(1.333f);
    const auto cpu = ref::bands::propagateAndAccumulate<3>(cpuInjected(), &gv, 4);
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(0.05f, 0.95f);
    std::vector<LookupPoint> points;
    for (int i = 0; i < 300; ++i)
        points.push_back({grid_.origin + glm::vec3(u(rng), u(rng), u(rng)) * (grid_.cellSize * float(grid_.n)),
                          randomUnit(rng)});
    const std::vector<glm::vec3> gpu = runLookup(*pass_, 0, false, 0.0f, points);
    ASSERT_EQ(gpu.size(), points.size());
    double worst = 0.0, peak = 0.0, band2Effect = 0.0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const glm::vec3 e = ref::bands::irradianceAt<3>(cpu, grid_, points[i].position, points[i].normal);
        for (int c = 0; c < 3; ++c) {
            worst = std::max(worst, double(std::abs(gpu[i][c] - e[c])));
            peak = std::max(peak, double(e[c]));
        }
        // What band 2 adds to the lookup (the red channel's band-2 terms).
        const auto sample = ref::bands::sampleTrilinear<3>(cpu, 0, (points[i].position - grid_.origin) / grid_.cellSize);
        double two = 0.0, three = 0.0;
        const auto lobe = sh::cosineLobeOf<3>(-points[i].normal);
        for (int j = 0; j < 9; ++j)
            (j < 4 ? two : three) += double(sample[j]) * double(lobe[j]);
        band2Effect = std::max(band2Effect, std::abs(three));
    }
    std::cout << "[ figures ] three-band lookup, 300 points: max |GPU - CPU| / peak = " << worst / peak
              << "; band 2's largest share of a red lookup " << band2Effect / peak << " of the peak\n";
    EXPECT_GT(band2Effect / peak, 1e-2); // band 2 must change the lookup, or this tests bands 0-1 only
    EXPECT_LT(worst / peak, 1e-3);       // the GPU's trilinear filter weighs in fixed point
}

// The Cornell template with three bands: the LPV runs, its note says so, and
// it adds indirect light (lpv.intensity 1 against 0).
TEST_F(GlTest, CornellBoxRendersWithThreeShBands) {
    scene::Project project = scene::makeCornellBoxProject();
    auto r = renderer::ForwardRenderer::create();
    ASSERT_TRUE(r.has_value());
    r->setScene(project.scene);
    const scene::Camera& camera = project.scene.cameras.front();
    scene::ParameterSet params = project.parameters;
    ASSERT_TRUE(params.setFromText("lpv.shBands", "3", "test").has_value());
    ASSERT_TRUE(params.setFromText("output.view", "indirect", "test").has_value());
    double sum[2] = {0.0, 0.0};
    for (const int intensity : {0, 1}) {
        ASSERT_TRUE(params.setFromText("lpv.intensity", std::to_string(intensity), "test").has_value());
        auto ok = r->render(project.scene, params, camera, 96, 96);
        ASSERT_TRUE(ok.has_value()) << ok.error().describe();
        for (float v : r->readHdr())
            sum[intensity] += std::isfinite(v) ? double(v) : 1e30;
        if (intensity == 1) {
            const std::string note = r->lpvNote();
            std::cout << "[ figures ] " << note << "; indirect view sum " << sum[1] << "\n";
            EXPECT_NE(note.find("3 SH bands"), std::string::npos) << note;
        }
    }
    EXPECT_LT(sum[1], 1e29) << "non-finite pixels";
    EXPECT_GT(sum[1], sum[0] + 1.0);
}

// Sky light in three bands: the injection kernel (LPV_SH_BANDS 3) on a
// hand-made height map against bands::injectSky<3>, then 4 steps.
TEST_F(LpvPassGLTest, ThreeBandSkyInjectionMatchesTheCpuTwin) {
    const SkyCourtyard courtyard;
    const ref::GridFrame& grid = courtyard.grid;
    const LpvRsmInput rsm = courtyard.rsm();
    const LpvSkyInput sky = courtyard.sky();
    const auto injected = ref::bands::injectSky<3>(grid, courtyard.map, courtyard.radiance);
    for (const int steps : {0, 4}) {
        LpvSettings settings;
        settings.shBands = 3;
        settings.gridSize = grid.n;
        settings.propagationSteps = steps;
        settings.occlusion = false;
        settings.gvFromCamera = false;
        timer_.beginFrame();
        auto ok = pass_->run(settings, rsm, nullptr, timer_, &sky);
        ASSERT_TRUE(ok.has_value()) << ok.error().describe();
        EXPECT_NE(pass_->note().find("sky light injected"), std::string::npos) << pass_->note();
        const auto cpu = ref::bands::propagateAndAccumulate<3>(injected, nullptr, steps);
        const auto gpu = pass_->readAccumulatorBands(0);
        double worst = 0.0, peak = 0.0, band2 = 0.0;
        for (int c = 0; c < 3; ++c)
            for (std::size_t i = 0; i < cpu.channel[c].size(); ++i)
                for (int j = 0; j < 9; ++j) {
                    worst = std::max(worst, double(std::abs(gpu[std::size_t(c)][i][std::size_t(j)] - cpu.channel[c][i][j])));
                    peak = std::max(peak, double(std::abs(cpu.channel[c][i][j])));
                    if (j >= 4)
                        band2 = std::max(band2, double(std::abs(cpu.channel[c][i][j])));
                }
        std::cout << "[ figures ] three-band sky, " << steps << " steps: max |GPU - CPU| / peak = " << worst / peak
                  << " (band 2 peak " << band2 << " of " << peak << ")\n";
        EXPECT_GT(band2, 0.01 * peak);
        EXPECT_LT(worst / peak, 2e-5);
    }
}

// The hard-case suite's thin wall (ThinWallRooms.h) on the GPU with two and
// three bands: the dark room's share of the light equals the CPU twin's
// (LpvBands.TheThinWallLeaksLessWithThreeBands), and three bands leak less.
TEST_F(LpvPassGLTest, TheThinWallLeaksLessWithThreeBandsOnTheGpu) {
    const ref::GridFrame grid{glm::vec3(0.0f), 0.25f, 16};
    constexpr int steps = 16;
    for (const float wallCells : {8.0f, 8.5f}) {
        const auto rooms = thinwall::twoRooms(grid, wallCells);
        std::vector<Texel> texels;
        for (const auto& t : rooms)
            texels.push_back({t.position, t.normal, t.flux});
        FakeRsm rsm(int(std::ceil(std::sqrt(double(texels.size())))), {texels});
        const auto vpls = thinwall::vplsOf(rooms);
        const auto surfels = thinwall::surfelsOf(rooms, thinwall::texelArea(grid));
        const int firstDark = int(std::ceil(wallCells));
        auto share = [&](auto dcAt) {
            double dark = 0.0, all = 0.0;
            for (int z = 0; z < grid.n; ++z)
                for (int y = 0; y < grid.n; ++y)
                    for (int x = 0; x < grid.n; ++x) {
                        const double dc = dcAt(x, y, z);
                        all += dc;
                        if (x >= firstDark)
                            dark += dc;
                    }
            return dark / all;
        };
        double gpuShare[2] = {0.0, 0.0};
        for (const int bands : {2, 3}) {
            LpvSettings settings;
            settings.shBands = bands;
            settings.gridSize = grid.n;
            settings.propagationSteps = steps;
            settings.gvFromCamera = false;
            runPass(settings, rsmInputOf(rsm, {LpvCascade{grid.origin, grid.cellSize, grid.n}},
                                         {thinwall::texelArea(grid)}));
            const auto gpu = pass_->readAccumulator(0); // bands 0-1: the DC is .x either way
            gpuShare[bands - 2] = share([&](int x, int y, int z) {
                return double(gpu[0][std::size_t(x + grid.n * (y + grid.n * z))].x);
            });
        }
        auto cpuShare = [&]<int B>() {
            const auto gv = ref::bands::injectSurfels<B>(grid, surfels);
            const auto acc = ref::bands::propagateAndAccumulate<B>(ref::bands::injectVpls<B>(grid, vpls, 1.0f), &gv, steps);
            return share([&](int x, int y, int z) { return double(acc.at(0, x, y, z)[0]); });
        };
        const double cpu2 = cpuShare.template operator()<2>(), cpu3 = cpuShare.template operator()<3>();
        std::cout << "[ figures ] thin wall at " << wallCells << " cells, " << steps
                  << " steps, dark room's share: GPU two bands " << gpuShare[0] << ", three " << gpuShare[1]
                  << " (CPU twin " << cpu2 << ", " << cpu3 << ")\n";
        EXPECT_NEAR(gpuShare[0], cpu2, 1e-4);
        EXPECT_NEAR(gpuShare[1], cpu3, 1e-4);
        EXPECT_LT(gpuShare[1], 0.9 * gpuShare[0]);
    }
}
