// The CPU twin of the glossy LPV ray march (LpvGlossy.h) against answers
// worked out by hand: a uniform radiance field, light from one side only,
// the cone's choice of cascade, and Schlick's Fresnel term at its limits.
#include "lpv/renderer/lpv/LpvGlossy.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace lpv::renderer;
using namespace lpv::renderer::lpvref;

namespace {

constexpr int kCells = 16;

// Two nested cascades around the origin, cells 0.25 and 0.5.
std::vector<GridFrame> twoCascades() {
    return {{glm::vec3(-2.0f), 0.25f, kCells}, {glm::vec3(-4.0f), 0.5f, kCells}};
}

// Every cell of cascade k holds the same SH per channel, scaled by s_k^2 so
// that the radiance (intensity / s^2) is the same in every cascade.
std::vector<ShGrid> uniformField(const std::vector<GridFrame>& frames, const glm::vec4& perUnitArea) {
    std::vector<ShGrid> grids;
    for (const GridFrame& f : frames) {
        ShGrid g(f.n);
        for (auto& channel : g.channel)
            for (glm::vec4& v : channel)
                v = perUnitArea * (f.cellSize * f.cellSize);
        grids.push_back(std::move(g));
    }
    return grids;
}

} // namespace

TEST(LpvGlossyReference, UniformRadianceIsReturnedWhicheverCascadeIsRead) {
    const auto frames = twoCascades();
    // An isotropic field of radiance 2: DC = 2 / Y00.
    const auto grids = uniformField(frames, glm::vec4(2.0f / sh::kY0, 0.0f, 0.0f, 0.0f));
    GlossyMarch march;
    march.intensity = 0.5f;
    for (float glossiness : {0.0f, 0.5f, 1.0f})
        for (const glm::vec3& r : {glm::vec3(1, 0, 0), glm::normalize(glm::vec3(1, 2, -3))}) {
            const glm::vec3 l = glossyIncoming(grids, frames, glm::vec3(0.1f), r, glossiness, march);
            EXPECT_NEAR(l.r, 1.0f, 1e-5f);
            EXPECT_NEAR(l.b, 1.0f, 1e-5f);
        }
}

TEST(LpvGlossyReference, LightTravellingTowardTheSurfaceIsSeenOnlyLookingAtItsSource) {
    const auto frames = twoCascades();
    // Light travelling toward -x (a bright wall at +x): the intensity lobe cosineLobe(-x).
    const auto grids = uniformField(frames, sh::cosineLobe(glm::vec3(-1.0f, 0.0f, 0.0f)));
    const GlossyMarch march;
    const glm::vec3 towardWall =
        glossyIncoming(grids, frames, glm::vec3(0.0f), glm::vec3(1, 0, 0), 1.0f, march);
    const glm::vec3 away = glossyIncoming(grids, frames, glm::vec3(0.0f), glm::vec3(-1, 0, 0), 1.0f, march);
    // Band-limited cosine lobe in its own direction: 0.75; opposite: 0.25 - 0.5 < 0, clamped.
    EXPECT_NEAR(towardWall.g, 0.75f, 1e-5f);
    EXPECT_EQ(away.g, 0.0f);
}

TEST(LpvGlossyReference, TheConeWidensIntoCoarserCascades) {
    const auto frames = twoCascades();
    const glm::vec3 p(0.5f, 0.0f, 0.0f);
    EXPECT_EQ(glossyCascade(frames, p, 0.0f), 0); // a mirror's footprint fits the finest cells
    EXPECT_EQ(glossyCascade(frames, p, 0.3f), 1); // wider than 0.25: the next cascade
    EXPECT_EQ(glossyCascade(frames, p, 5.0f), 1); // wider than every cascade: the coarsest that holds p
    EXPECT_EQ(glossyCascade(frames, glm::vec3(3.0f, 0, 0), 0.0f), 1);  // outside the finest (margin < 1)
    EXPECT_EQ(glossyCascade(frames, glm::vec3(3.8f, 0, 0), 0.0f), -1); // within a cell of the coarsest's face
}

TEST(LpvGlossyReference, TheMarchStopsWhereTheCascadesEnd) {
    // Radiance 1 in the finest cascade, 3 in the coarse one: the mean over the
    // samples says how many read each, and samples beyond the volume count not at all.
    const auto frames = twoCascades();
    auto grids = uniformField(frames, glm::vec4(1.0f / sh::kY0, 0.0f, 0.0f, 0.0f));
    for (auto& channel : grids[1].channel)
        for (glm::vec4& v : channel)
            v *= 3.0f;
    GlossyMarch march;
    march.steps = 5;
    march.maxDistanceCells = 16.0f; // t = 0.25, 0.5, 1, 2, 4 m
    // A mirror ray along +x from the centre: 0.25, 0.5, 1 in the finest (margin >= 1 up to 1.75),
    // 2 in the coarse one, 4 outside both (the coarse cube ends at 4, margin 0).
    const glm::vec3 l = glossyIncoming(grids, frames, glm::vec3(0.0f), glm::vec3(1, 0, 0), 1.0f, march);
    EXPECT_NEAR(l.r, (1.0f + 1.0f + 1.0f + 3.0f) / 4.0f, 1e-5f);
}

TEST(LpvGlossyReference, FresnelGoesFromF0HeadOnToOneAtGrazing) {
    const glm::vec3 f0(0.04f, 0.5f, 1.0f);
    const glm::vec3 headOn = glossyReflectance(f0, 0.5f, 1.0f);
    const glm::vec3 grazing = glossyReflectance(f0, 0.5f, 0.0f);
    EXPECT_NEAR(headOn.r, 0.02f, 1e-6f);
    EXPECT_NEAR(headOn.g, 0.25f, 1e-6f);
    EXPECT_NEAR(grazing.r, 0.5f, 1e-6f);
    EXPECT_NEAR(grazing.b, 0.5f, 1e-6f);
    EXPECT_EQ(glossyReflectance(f0, 0.0f, 0.3f), glm::vec3(0.0f));
}
