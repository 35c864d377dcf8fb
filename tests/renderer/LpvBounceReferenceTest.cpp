// Multi-bounce LPV, CPU reference (LpvBounce.h, docs/lpv.md "Local lights,
// emissive surfaces and bounces"): the secondary VPL of one surfel against its
// formula, and in a closed room the second bounce adds light and the third
// adds less than the second.
#include "LpvRoomScene.h"

#include "lpv/renderer/lpv/LpvBounce.h"

#include <gtest/gtest.h>

#include <iostream>

using namespace lpv::renderer;
namespace ref = lpv::renderer::lpvref;

TEST(LpvReferenceBounce, SurfelReflectsAlbedoTimesTheFluxItReceives) {
    // One cell whose 8 GV corners hold a full wall facing +x, lit by light travelling -x.
    const int n = 4;
    ref::GvGrid gv(n);
    for (int corner = 0; corner < 8; ++corner)
        gv.at(1 + (corner & 1), 1 + ((corner >> 1) & 1), 1 + ((corner >> 2) & 1)) =
            sh::cosineLobe({1.0f, 0.0f, 0.0f});
    ref::ShGrid light(n);
    const glm::vec4 incoming = sh::vplIntensity({-1.0f, 0.0f, 0.0f}, 2.0f); // a VPL shining at the wall
    for (int c = 0; c < 3; ++c)
        light.at(c, 1, 1, 1) = incoming * float(c + 1);
    const float albedo = 0.5f;
    const ref::ShGrid bounced = ref::bounceVpls(light, gv, albedo);
    const float received = glm::dot(incoming, sh::cosineLobe({-1.0f, 0.0f, 0.0f}));
    for (int c = 0; c < 3; ++c) {
        const glm::vec4 expected = sh::vplIntensity({1.0f, 0.0f, 0.0f}, albedo * received * float(c + 1));
        for (int j = 0; j < 4; ++j)
            EXPECT_NEAR(bounced.at(c, 1, 1, 1)[j], expected[j], 1e-6f);
    }
    // A cell without surfels reflects nothing; light from behind the wall is not reflected either.
    EXPECT_EQ(bounced.at(0, 3, 3, 3), glm::vec4(0.0f));
    ref::ShGrid behind(n);
    behind.at(0, 1, 1, 1) = sh::vplIntensity({1.0f, 0.0f, 0.0f}, 2.0f);
    EXPECT_EQ(ref::bounceVpls(behind, gv, albedo).at(0, 1, 1, 1), glm::vec4(0.0f));
}

TEST(LpvReferenceBounce, SecondBounceAddsLightAndTheThirdAddsLess) {
    const RoomScene room = closedRoom();
    const ref::ShGrid injected = ref::injectVpls(room.grid, room.vpls, 1.0f);
    const ref::GvGrid gv = ref::injectSurfels(room.grid, room.surfels);
    std::vector<ref::ShGrid> bounces;
    const ref::ShGrid total = ref::propagateWithBounces(injected, gv, true, 8, 3, 0.5f, &bounces);
    ASSERT_EQ(bounces.size(), 3u);
    // Light at the walls: irradiance on the ceiling and on the unlit side's wall, per bounce.
    auto wallLight = [&](const ref::ShGrid& g) {
        double sum = 0.0;
        for (float a = 0.625f; a < 2.5f; a += 0.25f)
            for (float b = 0.625f; b < 2.5f; b += 0.25f) {
                sum += double(ref::irradianceAt(g, room.grid, {a, room.hi, b}, {0, -1, 0}).r); // ceiling
                sum += double(ref::irradianceAt(g, room.grid, {room.hi, a, b}, {-1, 0, 0}).r); // far wall
            }
        return sum;
    };
    const double e1 = wallLight(bounces[0]), e2 = wallLight(bounces[1]), e3 = wallLight(bounces[2]);
    const double f1 = ref::totalFlux(bounces[0], 0), f2 = ref::totalFlux(bounces[1], 0),
                 f3 = ref::totalFlux(bounces[2], 0);
    std::cout << "[measured] room 12^3, 8 steps, albedo 0.5: wall irradiance bounce 2 / 1 = " << e2 / e1
              << ", 3 / 2 = " << e3 / e2 << "; accumulated flux 2 / 1 = " << f2 / f1
              << ", 3 / 2 = " << f3 / f2 << "\n";
    RecordProperty("wall_ratio_2_1", std::to_string(e2 / e1));
    RecordProperty("wall_ratio_3_2", std::to_string(e3 / e2));
    EXPECT_GT(e2, 0.05 * e1) << "the second bounce adds light at the walls";
    EXPECT_LT(e3, e2) << "the third bounce adds less than the second";
    EXPECT_LT(f3, f2);
    EXPECT_LT(f2, f1);
    // The total is the sum of the bounces, and more bounces never take light away.
    EXPECT_NEAR(ref::totalFlux(total, 0), f1 + f2 + f3, 1e-6 * (f1 + f2 + f3));
    // Albedo 0 is one bounce; a brighter albedo bounces more.
    std::vector<ref::ShGrid> dark, bright;
    ref::propagateWithBounces(injected, gv, true, 8, 2, 0.0f, &dark);
    ref::propagateWithBounces(injected, gv, true, 8, 2, 0.9f, &bright);
    EXPECT_EQ(ref::totalFlux(dark[1], 0), 0.0);
    EXPECT_GT(ref::totalFlux(bright[1], 0), f2);
}
