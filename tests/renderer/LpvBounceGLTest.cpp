// Multi-bounce LPV on the GPU (shaders/lpv_bounce.comp) against the CPU
// reference (lpvref::propagateWithBounces), every propagation variant, in the
// closed room of LpvRoomScene.h; the running total's volume exists only while
// lpv.bounces > 1.
#include "LpvPassFixture.h"
#include "LpvRoomScene.h"
#include "ShGridCompare.h"

#include "passes/lpv/LpvPass.h"
#include "lpv/renderer/GpuTimer.h"
#include "lpv/renderer/lpv/LpvBounce.h"

#include <algorithm>
#include <cmath>
#include <iostream>

using namespace lpv::renderer;
namespace ref = lpv::renderer::lpvref;

namespace {

constexpr float kTexelArea = 0.125f * 0.125f;
const glm::vec3 kTowardSun{0.0f, 1.0f, 0.0f};

// The room as one RSM tile: the lit floor's VPLs, and every wall texel as a surfel of zero flux.
std::vector<Texel> roomTexels(const RoomScene& room) {
    std::vector<Texel> texels;
    for (const ref::Vpl& v : room.vpls)
        texels.push_back({v.position, v.normal, v.flux});
    for (const ref::Surfel& s : room.surfels)
        texels.push_back({s.position, s.normal, glm::vec3(0.0f)});
    return texels;
}

// What LpvPass computes from those texels, with `bounces` bounces: the GV
// surfels get the RSM's area (texel area over max(n . l, 0.2)), as lpv_gv_inject.comp does.
ref::ShGrid reference(const RoomScene& room, const std::vector<Texel>& texels, int steps, int bounces,
                      float albedo, std::vector<ref::ShGrid>* perBounce = nullptr) {
    std::vector<ref::Vpl> vpls;
    std::vector<ref::Surfel> surfels;
    for (const Texel& t : texels) {
        vpls.push_back({t.position, t.normal, t.flux});
        surfels.push_back(
            {t.position, t.normal, kTexelArea / std::max(glm::dot(t.normal, kTowardSun), 0.2f)});
    }
    const ref::ShGrid injected = ref::injectVpls(room.grid, vpls, 1.0f);
    const ref::GvGrid gv = ref::mergeByMax(ref::injectSurfels(room.grid, surfels), ref::GvGrid(room.grid.n));
    return ref::propagateWithBounces(injected, gv, true, steps, bounces, albedo, perBounce);
}

class LpvBounceTest : public LpvPassGLTest, public ::testing::WithParamInterface<LpvVariant> {
  protected:
    std::array<std::vector<glm::vec4>, 3> runGpu(const RoomScene& room, const FakeRsm& rsm, int steps,
                                                 int bounces, float albedo) {
        LpvSettings settings;
        settings.gridSize = room.grid.n;
        settings.propagationSteps = steps;
        settings.occlusion = true;
        settings.gvFromCamera = false;
        settings.variant = GetParam();
        settings.bounces = bounces;
        settings.bounceAlbedo = albedo;
        runPass(settings,
                rsmInputOf(rsm, {LpvCascade{room.grid.origin, room.grid.cellSize, room.grid.n}}, {kTexelArea}, kTowardSun));
        return pass_->readAccumulator(0);
    }

};

} // namespace

TEST_P(LpvBounceTest, MatchesReferenceAndFreesItsVolume) {
    const RoomScene room = closedRoom();
    const std::vector<Texel> texels = roomTexels(room);
    FakeRsm rsm(int(std::ceil(std::sqrt(double(texels.size())))), {texels});
    const int steps = 6;
    const auto one = runGpu(room, rsm, steps, 1, 0.5f);
    const std::size_t plainBytes = pass_->allocatedBytes();
    EXPECT_LT(relativeDifference(reference(room, texels, steps, 1, 0.5f), one), 2e-5);
    for (int bounces : {2, 3}) {
        std::vector<ref::ShGrid> perBounce;
        const ref::ShGrid expected = reference(room, texels, steps, bounces, 0.5f, &perBounce);
        const auto gpu = runGpu(room, rsm, steps, bounces, 0.5f);
        EXPECT_GT(pass_->allocatedBytes(), plainBytes) << "the running total of the bounces";
        float largest = 0.0f;
        const double d = relativeDifference(expected, gpu, &largest);
        std::cout << "[ figures ] " << lpvVariantName(GetParam()) << " 12^3, " << steps << " steps, "
                  << bounces << " bounces: relative |GPU - CPU| " << d << " of max " << largest
                  << "; flux of the last bounce / first "
                  << ref::totalFlux(perBounce.back(), 0) / ref::totalFlux(perBounce.front(), 0) << "\n";
        EXPECT_LT(d, 2e-5) << bounces << " bounces";
        // The bounces change the volume, by more than the tolerance.
        EXPECT_GT(relativeDifference(expected, one), 1e-3);
    }
    runGpu(room, rsm, steps, 1, 0.5f);
    EXPECT_EQ(pass_->allocatedBytes(), plainBytes) << "one bounce keeps no running total";
}

INSTANTIATE_TEST_SUITE_P(AllVariants, LpvBounceTest,
                         ::testing::Values(LpvVariant::ComputeGather, LpvVariant::ComputeScatter,
                                           LpvVariant::RasterGather, LpvVariant::RasterScatter),
                         [](const auto& p) { return std::string(lpvVariantName(p.param)); });
