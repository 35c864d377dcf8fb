// The CPU reference of the subsurface LPV (docs/lpv.md, "Subsurface LPV"):
// where translucent VPLs land and which way they point, that the attenuation
// takes (1 - a) of each step, and that light crosses a thin slab to its back.
#include "lpv/renderer/lpv/LpvSubsurfaceReference.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

using namespace lpv::renderer;
namespace ref = lpv::renderer::lpvref;

namespace {

const ref::GridFrame kGrid{glm::vec3(0.0f), 0.5f, 12};

double totalDc(const ref::ShGrid& g) {
    return ref::totalFlux(g, 0);
}

} // namespace

TEST(LpvSubsurfaceReference, TranslucentVplLandsInItsOwnCellPointingIntoTheSurface) {
    // A VPL on a surface facing +y (toward the sun) at cell (3, 5, 7).
    const glm::vec3 p = kGrid.origin + (glm::vec3(3.0f, 5.0f, 7.0f) + 0.3f) * kGrid.cellSize;
    const std::vector<ref::TranslucentVpl> vpls{{{p, {0.0f, 1.0f, 0.0f}, glm::vec3(2.0f)}, 0.25f},
                                                {{p, {0.0f, 1.0f, 0.0f}, glm::vec3(5.0f)}, 0.0f}};
    const ref::ShGrid g = ref::injectSubsurface(kGrid, vpls);
    // No offset: its own cell, not the one above; the opaque VPL adds nothing.
    const glm::vec4 expected = sh::vplIntensity({0.0f, -1.0f, 0.0f}, 2.0f * 0.25f);
    for (int j = 0; j < 4; ++j)
        EXPECT_NEAR(g.at(0, 3, 5, 7)[j], expected[j], 1e-7f);
    EXPECT_EQ(g.at(0, 3, 6, 7), glm::vec4(0.0f));
    // Pointing down, into the surface: Y1-1 = -0.4886 y is positive for a -y lobe.
    EXPECT_GT(g.at(0, 3, 5, 7).y, 0.0f);
    EXPECT_NEAR(totalDc(g), 2.0 * 0.25, 1e-6);
}

TEST(LpvSubsurfaceReference, EachStepKeepsOneMinusTheAttenuation) {
    ref::ShGrid injected(kGrid.n);
    // An isotropic point in the middle: propagation alone keeps its flux
    // (until it reaches the border, 6 cells away), so each step's flux is
    // (1 - a) of the previous one.
    injected.at(0, 6, 6, 6) = glm::vec4(1.0f, 0.0f, 0.0f, 0.0f);
    const float a = 0.4f;
    double previous = totalDc(ref::propagateSubsurface(injected, 0, a));
    for (int steps = 1; steps <= 4; ++steps) {
        const double accumulated = totalDc(ref::propagateSubsurface(injected, steps, a));
        const double before = totalDc(ref::propagateSubsurface(injected, steps - 1, a));
        const double step = accumulated - before;
        EXPECT_NEAR(step / (previous > 0 ? previous : 1.0), 1.0 - a, 1e-5) << "step " << steps;
        previous = step;
    }
    // a = 1 keeps only the injected light; a = 0 is the plain LPV propagation.
    const ref::ShGrid none = ref::propagateSubsurface(injected, 4, 1.0f);
    EXPECT_EQ(none.channel[0], injected.channel[0]);
    const ref::ShGrid plain = ref::propagateSubsurface(injected, 4, 0.0f);
    const ref::ShGrid lpv = ref::propagateAndAccumulate(injected, nullptr, 4);
    EXPECT_EQ(plain.channel[0], lpv.channel[0]);
}

TEST(LpvSubsurfaceReference, LightCrossesAThinSlabToItsBack) {
    // A slab 0.1 thick whose lit face (normal +z, toward the sun) is at z = 3.0
    // (cell 6), its back face at z = 2.9 with normal -z. VPLs cover the lit face.
    std::vector<ref::TranslucentVpl> vpls;
    for (int i = 0; i < 20; ++i)
        for (int j = 0; j < 20; ++j) {
            const glm::vec3 p(1.0f + 0.2f * float(i), 1.0f + 0.2f * float(j), 3.0f);
            vpls.push_back({{p, {0.0f, 0.0f, 1.0f}, glm::vec3(0.05f)}, 0.8f});
        }
    const ref::ShGrid acc = ref::propagateSubsurface(ref::injectSubsurface(kGrid, vpls), 4, 0.5f);
    const glm::vec3 centre(3.0f, 3.0f, 0.0f);
    const float back = ref::subsurfaceIrradianceAt(acc, kGrid, centre + glm::vec3(0, 0, 2.9f), {0, 0, -1}).r;
    const float front = ref::subsurfaceIrradianceAt(acc, kGrid, centre + glm::vec3(0, 0, 3.0f), {0, 0, 1}).r;
    std::cout << "[measured] subsurface irradiance behind the slab " << back << ", on its lit face " << front
              << "\n";
    RecordProperty("back", std::to_string(back));
    RecordProperty("front", std::to_string(front));
    EXPECT_GT(back, 0.0f);
    // The lit face sees almost none of it: the light travels away from the sun.
    EXPECT_LT(front, 0.2f * back);
}
