#include "RadiosityTestScenes.h"

#include "lpv/radiosity/ProgressiveSolver.h"
#include "lpv/radiosity/SolveLoop.h"

#include <gtest/gtest.h>

using namespace lpv;

namespace {

double sum(const glm::dvec3& v) {
    return v.x + v.y + v.z;
}

struct BoxSolve {
    explicit BoxSolve(float reflectance, float maxPatchArea = 0.25f)
        : scene(test::closedBox(glm::vec3(reflectance), glm::vec3(1.0f))),
          mesh(radiosity::buildPatchMesh(scene, {maxPatchArea})), formFactors(mesh, false),
          solver(mesh, radiosity::surfaceProperties(mesh, scene, {})) {}
    scene::Scene scene;
    radiosity::PatchMesh mesh;
    radiosity::CpuFormFactors formFactors; // a convex box: nothing occludes
    radiosity::ProgressiveSolver solver;
};

} // namespace

TEST(ProgressiveSolver, StartsWithTheEmittersAsUnshotEnergy) {
    BoxSolve box(0.5f);
    EXPECT_NEAR(sum(box.solver.state().balance.emitted), 3.0,
                1e-5); // ceiling: area 1, radiance 1 per channel
    EXPECT_NEAR(box.solver.residual(), 1.0, 1e-9);
}

TEST(ProgressiveSolver, EnergyIsConserved) {
    BoxSolve box(0.7f);
    for (int i = 0; i < 40; ++i)
        ASSERT_TRUE(box.solver.step(box.formFactors, 4).has_value());
    const auto& b = box.solver.state().balance;
    const glm::dvec3 accounted = b.absorbed + b.escaped + box.solver.unshotPower();
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(accounted[c], b.emitted[c], 1e-3 * b.emitted[c]);
    // In a closed box the point-to-polygon factors of every shooter sum to 1: nothing escapes.
    EXPECT_LT(sum(b.escaped), 1e-3 * sum(b.emitted));
    EXPECT_GT(sum(b.absorbed), 0.5 * sum(b.emitted));
}

TEST(ProgressiveSolver, WhiteBoxWithReflectance099ConvergesWithoutBlowingUp) {
    BoxSolve box(0.99f, 0.5f);
    radiosity::SolveOptions options;
    options.residualTarget = 0.01;
    options.shootersPerBatch = 8;
    std::vector<double> residuals;
    options.progressInterval = 0.0;
    options.progress = [&](const radiosity::SolveProgress& p) { residuals.push_back(p.residual); };
    const auto reason = radiosity::solve(box.solver, box.formFactors, options);
    ASSERT_TRUE(reason.has_value());
    EXPECT_EQ(*reason, radiosity::StopReason::Converged);
    EXPECT_LE(box.solver.residual(), 0.01);
    ASSERT_GT(residuals.size(), 10u);
    // Unshot energy only shrinks (the reflectance is below 1).
    for (std::size_t i = 1; i < residuals.size(); ++i)
        EXPECT_LE(residuals[i], residuals[i - 1] + 1e-9);
    // Analytic equilibrium of a closed box: absorbed = emitted, so the mean
    // irradiance is E / ((1 - rho) A) and the mean radiosity of the walls
    // rho / (1 - rho) * E / A (E = 1 per channel, A = 6). The 1% left unshot is missing.
    double wallRadiosity = 0.0, wallArea = 0.0;
    for (std::size_t i = 0; i < box.mesh.size(); ++i)
        if (box.mesh.patches[i].material == 0) {
            const glm::vec3 b = box.solver.state().radiosity[i];
            ASSERT_TRUE(std::isfinite(b.x) && std::isfinite(b.y) && std::isfinite(b.z));
            wallRadiosity += b.x * box.mesh.patches[i].area;
            wallArea += box.mesh.patches[i].area;
        }
    const double expectedMean = 0.99 / 0.01 / 6.0;
    EXPECT_NEAR(wallRadiosity / wallArea, expectedMean, 0.03 * expectedMean);
}

TEST(ProgressiveSolver, SolveStopsAtTheTimeBudgetAndResumes) {
    BoxSolve box(0.99f, 0.5f);
    radiosity::SolveOptions options;
    // A target no 0.05 s budget can reach, on any machine: the solve must stop for the
    // budget (1e-6 was reached within the third budget on a loaded CI machine).
    options.residualTarget = 1e-30;
    options.maxSeconds = 0.05;
    const auto first = radiosity::solve(box.solver, box.formFactors, options);
    ASSERT_TRUE(first.has_value());
    EXPECT_EQ(*first, radiosity::StopReason::TimeBudget);
    const auto shots = box.solver.state().shots;
    const double residual = box.solver.residual();
    EXPECT_GT(shots, 0u);
    std::atomic<bool> cancel{true};
    options.cancel = &cancel;
    EXPECT_EQ(*radiosity::solve(box.solver, box.formFactors, options), radiosity::StopReason::Cancelled);
    EXPECT_EQ(box.solver.state().shots, shots);
    cancel = false;
    EXPECT_EQ(*radiosity::solve(box.solver, box.formFactors, options), radiosity::StopReason::TimeBudget);
    EXPECT_GT(box.solver.state().shots, shots);
    EXPECT_LT(box.solver.residual(), residual);
}

TEST(ProgressiveSolver, AmbientTermAccountsForTheUnshotEnergy) {
    BoxSolve box(0.5f);
    const auto before = box.solver.ambient();
    ASSERT_TRUE(box.solver.step(box.formFactors, 4).has_value());
    const auto after = box.solver.ambient();
    ASSERT_EQ(after.size(), box.mesh.size());
    EXPECT_GT(before[0].x, 0.0f);
    EXPECT_LT(after[0].x, before[0].x); // less left to shoot, smaller ambient
}

TEST(ProgressiveSolver, RefinementCarriesTheSolutionOver) {
    BoxSolve box(0.7f, 0.25f);
    for (int i = 0; i < 10; ++i)
        ASSERT_TRUE(box.solver.step(box.formFactors, 4).has_value());
    const auto which = box.solver.patchesToRefine(0.05f);
    ASSERT_FALSE(which.empty()); // the light falls off across the walls
    std::vector<std::uint32_t> parentOf;
    const auto refined = radiosity::refinePatches(box.mesh, which, parentOf);
    radiosity::ProgressiveSolver next(refined, radiosity::surfaceProperties(refined, box.scene, {}));
    ASSERT_TRUE(next.restore(radiosity::refineState(box.solver.state(), parentOf)).has_value());
    EXPECT_NEAR(next.residual(), box.solver.residual(), 1e-5);
    EXPECT_GT(refined.size(), box.mesh.size());
}
