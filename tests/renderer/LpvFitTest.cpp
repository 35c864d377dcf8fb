// The LPV's fit to the scene (issue #41, LpvFit.h) on the CPU: cells as a
// fraction of the scene, doubled for a camera far away, a number forcing
// them, and the reasons an LPV cannot deliver light.
#include "lpv/renderer/LpvFit.h"

#include <gtest/gtest.h>

using namespace lpv;
using renderer::LpvDelivery;

namespace {

scene::Bounds box(float side, glm::vec3 corner = glm::vec3(0.0f)) {
    scene::Bounds b;
    b.extend(corner);
    b.extend(corner + glm::vec3(side, 0.5f * side, 0.8f * side));
    return b;
}

} // namespace

TEST(LpvFit, TheFinestCellIsAFractionOfTheSceneAtEveryScale) {
    const scene::ParameterSet defaults;
    for (float side : {0.02f, 2.0f, 40.0f, 20000.0f}) {
        SCOPED_TRACE(side);
        // A camera inside the scene: no doubling.
        const renderer::LpvFit fit = renderer::fitLpv(defaults, box(side), glm::vec3(0.5f * side, 0.2f * side, 0.4f * side));
        EXPECT_TRUE(fit.fitted);
        EXPECT_NEAR(fit.cellSize, side / 160.0, 1e-6 * side);
        EXPECT_EQ(fit.cascades, 4);
        EXPECT_EQ(fit.steps, 8);
        EXPECT_NE(fit.reason.find("1/160 of the"), std::string::npos) << fit.reason;
        EXPECT_EQ(renderer::withFit(defaults, fit).getFloat("lpv.cellSize"), float(fit.cellSize));
    }
}

TEST(LpvFit, ACameraFarFromTheSceneDoublesTheCellsUntilTheCoarsestReachesIt) {
    const scene::ParameterSet defaults;
    // The Cornell template's view: a 5.6 m box, the camera 8 m in front of it.
    const scene::Bounds b = box(5.6f);
    const glm::vec3 camera(2.8f, 1.4f, -8.0f);
    const renderer::LpvFit fit = renderer::fitLpv(defaults, b, camera);
    EXPECT_NEAR(fit.cellSize, 4.0 * 5.6 / 160.0, 1e-6);
    EXPECT_NE(fit.reason.find("x4 to reach it from the camera"), std::string::npos) << fit.reason;
    // The coarsest cascade (cells 8 x finest) serves 14 of its cells each way:
    // at least the distance to the box's middle and a quarter of it beyond.
    EXPECT_GE(8.0 * fit.cellSize * 14.0, 8.0 + 0.4 * 5.6 + 0.25 * 5.6);
    EXPECT_EQ(renderer::lpvDelivery(fit, 32, b, camera).problem, LpvDelivery::Problem::None);
    // Moved 100 km with the camera: the same fit (it depends on lengths only).
    const glm::vec3 far(1e5f, 0.0f, -1e5f);
    EXPECT_NEAR(renderer::fitLpv(defaults, box(5.6f, far), camera + far).cellSize, fit.cellSize, 1e-3 * fit.cellSize);
}

TEST(LpvFit, ANumberForcesTheCellSizeAndTheDeliveryIsJudged) {
    scene::ParameterSet forced;
    ASSERT_TRUE(forced.set("lpv.cellSize", 0.01).has_value());
    const scene::Bounds b = box(5.6f);
    const glm::vec3 outside(2.8f, 1.4f, -8.0f);
    const renderer::LpvFit fit = renderer::fitLpv(forced, b, outside);
    EXPECT_FALSE(fit.fitted);
    EXPECT_DOUBLE_EQ(fit.cellSize, 0.01f);
    EXPECT_EQ(renderer::withFit(forced, fit), forced);
    const LpvDelivery lost = renderer::lpvDelivery(fit, 32, b, outside);
    EXPECT_EQ(lost.problem, LpvDelivery::Problem::OutsideCascades);
    EXPECT_TRUE(lost.skipsLpv());
    EXPECT_NE(lost.reason.find("8 m away"), std::string::npos) << lost.reason;

    // Inside: the cascades reach the walls, but 8 steps of 8 cm carry light
    // 0.64 m, under 1/8 of the box.
    const glm::vec3 inside(2.8f, 1.4f, 2.2f);
    const LpvDelivery shortReach = renderer::lpvDelivery(fit, 32, b, inside);
    EXPECT_EQ(shortReach.problem, LpvDelivery::Problem::ShortReach) << shortReach.reason;
    EXPECT_FALSE(shortReach.skipsLpv());

    scene::ParameterSet noSteps;
    ASSERT_TRUE(noSteps.set("lpv.propagationSteps", 0).has_value());
    EXPECT_EQ(renderer::lpvDelivery(renderer::fitLpv(noSteps, b, inside), 32, b, inside).problem,
              LpvDelivery::Problem::NoSteps);
}

// lpv.refinement (issue #47's convergence question): on top of the fit, cells
// 1/r the size, r times as many along each axis and r times the steps, so the
// cascades cover the same space and light travels as far (r < 1 coarsens).
TEST(LpvFit, RefinementDividesTheCellsAndMultipliesTheirCountAndTheSteps) {
    const scene::Bounds b = box(5.6f);
    const glm::vec3 camera(2.8f, 1.4f, -8.0f); // outside: the fit doubles the cells
    const scene::ParameterSet defaults;
    const renderer::LpvFit base = renderer::fitLpv(defaults, b, camera);
    for (double r : {0.5, 1.0, 2.0, 4.0}) {
        SCOPED_TRACE(r);
        scene::ParameterSet p;
        ASSERT_TRUE(p.set("lpv.refinement", r).has_value());
        const renderer::LpvFit fit = renderer::fitLpv(p, b, camera);
        EXPECT_TRUE(fit.fitted);
        EXPECT_NEAR(fit.cellSize, base.cellSize / r, 1e-9);
        EXPECT_EQ(fit.gridSize, int(32 * r));
        EXPECT_EQ(fit.steps, int(8 * r));
        const scene::ParameterSet frame = renderer::withFit(p, fit);
        EXPECT_EQ(frame.getFloat("lpv.cellSize"), float(fit.cellSize));
        EXPECT_EQ(frame.getInt("lpv.gridSize"), int(32 * r));
        EXPECT_EQ(frame.getInt("lpv.propagationSteps"), int(8 * r));
        // The same extent and reach as unrefined; the delivery judged on the refined grid.
        EXPECT_NEAR(fit.cellSize * fit.gridSize, base.cellSize * 32, 1e-9);
        EXPECT_NEAR(fit.cellSize * fit.steps, base.cellSize * 8, 1e-9);
        EXPECT_EQ(renderer::lpvDelivery(fit, 32, b, camera).problem, LpvDelivery::Problem::None);
        EXPECT_EQ(fit.reason.find("refinement x") != std::string::npos, r != 1.0) << fit.reason;
    }
}

TEST(LpvFit, RefinementRefinesAForcedSizeAndIsCappedAtTheRegistrysMaximum) {
    scene::ParameterSet p;
    ASSERT_TRUE(p.set("lpv.cellSize", 0.2).has_value());
    ASSERT_TRUE(p.set("lpv.gridSize", 64).has_value());
    ASSERT_TRUE(p.set("lpv.propagationSteps", 32).has_value());
    ASSERT_TRUE(p.set("lpv.refinement", 4.0).has_value());
    const renderer::LpvFit fit = renderer::fitLpv(p, box(5.6f), glm::vec3(2.8f, 1.4f, 2.2f));
    EXPECT_FALSE(fit.fitted);
    EXPECT_NEAR(fit.cellSize, 0.05, 1e-7);
    EXPECT_EQ(fit.gridSize, 128);
    EXPECT_EQ(fit.steps, 64);
    EXPECT_NE(fit.reason.find("capped at lpv.gridSize 8-128"), std::string::npos) << fit.reason;
    const scene::ParameterSet frame = renderer::withFit(p, fit);
    EXPECT_EQ(frame.getInt("lpv.gridSize"), 128);
    EXPECT_EQ(frame.getInt("lpv.propagationSteps"), 64);
    EXPECT_NE(renderer::fitNote(fit, {}).find("refinement x4"), std::string::npos);
    // Unrefined, a forced size leaves the parameters as they are.
    ASSERT_TRUE(p.set("lpv.refinement", 1.0).has_value());
    EXPECT_EQ(renderer::withFit(p, renderer::fitLpv(p, box(5.6f), glm::vec3(2.8f, 1.4f, 2.2f))), p);
}
