// Directed propagation in the CPU reference (docs/lpv.md): a lit floor under
// a box. The floor's VPLs should light the box's underside but not, through
// light that flows back down, the floor itself.
#include "LpvDirectedScene.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <iostream>

using namespace lpv::renderer;
using namespace lpv::renderer::lpvref;

namespace {

void report(const std::string& key, double value) {
    char text[64];
    std::snprintf(text, sizeof text, "%.9g", value);
    ::testing::Test::RecordProperty(key, text);
    std::cout << "[measured] " << key << " = " << text << "\n";
}

} // namespace

TEST(LpvReferenceDirected, NormalsAverageThenDilateOneCellPerPass) {
    const GridFrame frame{glm::vec3(0.0f), 1.0f, 8};
    // Two VPLs in cell (2, 2, 2) (offset 0), normals +x and +y: the average is (0.5, 0.5, 0).
    const std::vector<Vpl> vpls{{{2.5f, 2.5f, 2.5f}, {1, 0, 0}, {1, 1, 1}}, {{2.2f, 2.7f, 2.1f}, {0, 1, 0}, {1, 1, 1}}};
    const NormalGrid injected = injectNormals(frame, vpls, 0.0f);
    EXPECT_EQ(injected.at(2, 2, 2), glm::vec4(0.5f, 0.5f, 0.0f, 1.0f));
    EXPECT_EQ(injected.at(3, 2, 2).w, 0.0f);
    const NormalGrid once = dilateNormals(injected);
    EXPECT_EQ(once.at(3, 2, 2), injected.at(2, 2, 2)); // axis neighbours take it
    EXPECT_EQ(once.at(3, 3, 2).w, 0.0f);               // diagonal ones only after a second pass
    EXPECT_EQ(dilateNormals(once).at(3, 3, 2), injected.at(2, 2, 2));
    // The face weight: back into the surface 0, sideways and away 1.
    EXPECT_FLOAT_EQ(directedWeight({0, -1, 0}, {0, 1, 0, 1}), 0.0f);
    EXPECT_FLOAT_EQ(directedWeight({1, 0, 0}, {0, 1, 0, 1}), 1.0f);
    EXPECT_FLOAT_EQ(directedWeight({0, 1, 0}, {0, 1, 0, 1}), 1.0f);
    EXPECT_FLOAT_EQ(directedWeight({0, -1, 0}, {0, 0, 0, 0}), 1.0f);
}

TEST(LpvReferenceDirected, FloorLightsItselfLessAndTheBoxUndersideStillReceives) {
    const DirectedScene scene = floorUnderBox();
    const GvGrid gv = mergeByMax(injectSurfels(scene.grid, scene.surfels), GvGrid(scene.grid.n));
    const ShGrid injected = injectVpls(scene.grid, scene.vpls, 1.0f);
    // Light the floor sends to itself: its own VPLs are the only light there is.
    const ShGrid plain = propagateAndAccumulate(injected, &gv, 8);
    for (int dilation : {1, 2}) {
        NormalGrid normals = injectNormals(scene.grid, scene.vpls, 1.0f);
        for (int i = 0; i < dilation; ++i)
            normals = dilateNormals(normals);
        const ShGrid directed = propagateAndAccumulate(injected, &gv, 8, &normals);
        const DirectedFigures off = measure(scene, plain), on = measure(scene, directed);
        const std::string tag = "directed.dilation" + std::to_string(dilation);
        report(tag + ".floor_irradiance_on_over_off", on.floor / off.floor);
        report(tag + ".box_underside_irradiance_on_over_off", on.underside / off.underside);
        report(tag + ".floor_irradiance_off", off.floor);
        report(tag + ".box_underside_irradiance_off", off.underside);
        EXPECT_GT(off.floor, 0.0);
        EXPECT_GT(off.underside, 0.0);
        // The floor gets measurably less of its own light back ...
        EXPECT_LT(on.floor, 0.9 * off.floor);
        // ... while the underside, which faces the floor, keeps most of it.
        EXPECT_GT(on.underside, 0.7 * off.underside);
    }
}
