// Numerical hard cases of the radiosity solver (issue #11 item 6, docs/hard-cases.md):
// reflectance near 1 and tiny patches. Each asserts finiteness and a bound
// measured on this solver, with its reason.
#include "RadiosityTestScenes.h"

#include "lpv/radiosity/ProgressiveSolver.h"
#include "lpv/radiosity/SolveLoop.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

using namespace lpv;

namespace {

// The CPU reference computes each shooter's row on every shot; with
// reflectance 0.999 the solve needs about 10^5 shots, so the rows of the
// small box are computed once and replayed (the same numbers, cached).
class CachedFormFactors final : public radiosity::FormFactorSource {
  public:
    explicit CachedFormFactors(const radiosity::PatchMesh& mesh) : n_(mesh.size()) {
        radiosity::CpuFormFactors cpu(mesh, false); // a convex box: nothing occludes
        std::vector<std::uint32_t> all(n_);
        for (std::uint32_t i = 0; i < n_; ++i)
            all[i] = i;
        EXPECT_TRUE(cpu.compute(all, rows_).has_value());
    }
    scene::Expected<void> compute(std::span<const std::uint32_t> shooters,
                                  std::vector<float>& factors) override {
        factors.resize(shooters.size() * n_);
        for (std::size_t s = 0; s < shooters.size(); ++s)
            std::copy_n(rows_.begin() + std::ptrdiff_t(shooters[s] * n_), n_,
                        factors.begin() + std::ptrdiff_t(s * n_));
        return {};
    }
    const char* name() const override { return "cached-cpu-reference"; }

  private:
    std::size_t n_;
    std::vector<float> rows_;
};

// The closed box of RadiosityTestScenes.h scaled by `side` (the emitting
// ceiling keeps radiance 1, so its power scales with the area).
scene::Scene scaledBox(float reflectance, float side) {
    scene::Scene s = test::closedBox(glm::vec3(reflectance), glm::vec3(1.0f));
    for (scene::Mesh& m : s.meshes)
        for (glm::vec3& p : m.positions)
            p *= side;
    return s;
}

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// |emitted - (absorbed + escaped + unshot)| / emitted, worst channel.
double balanceError(const radiosity::ProgressiveSolver& solver) {
    const auto& b = solver.state().balance;
    const glm::dvec3 accounted = b.absorbed + b.escaped + solver.unshotPower();
    double worst = 0.0;
    for (int c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(accounted[c] - b.emitted[c]) / b.emitted[c]);
    return worst;
}

// Area-weighted mean reflected radiosity (the ceiling's emission of 1 taken
// off) over every patch, and the largest wall patch.
struct WallStats {
    double mean = 0.0;
    double max = 0.0;
};

WallStats wallStats(const radiosity::ProgressiveSolver& solver) {
    double sum = 0.0, area = 0.0, max = 0.0;
    const auto& mesh = solver.mesh();
    for (std::size_t i = 0; i < mesh.size(); ++i) {
        const glm::vec3 b = solver.state().radiosity[i];
        EXPECT_TRUE(finite(b)) << "patch " << i;
        const bool emitter = mesh.patches[i].material == 1;
        sum += (double(b.x) - (emitter ? 1.0 : 0.0)) * mesh.patches[i].area;
        area += mesh.patches[i].area;
        if (!emitter)
            max = std::max(max, double(b.x));
    }
    return {sum / area, max};
}

} // namespace

// Reflectance 0.999: the light bounces about 1 / (1 - rho) = 1000 times, the
// equilibrium radiosity is 999x the emitted flux per area, and the unshot
// energy shrinks by only 0.1% per bounce. The solve must stay finite, keep
// the energy balance to float accuracy and approach the analytic mean from
// below without overshooting it.
TEST(HardCaseRadiosity, ReflectanceNearOneStaysFiniteBalancedAndBelowEquilibrium) {
    constexpr float rho = 0.999f;
    const scene::Scene scene = scaledBox(rho, 1.0f);
    const radiosity::PatchMesh mesh = radiosity::buildPatchMesh(scene, {0.25f});
    CachedFormFactors formFactors(mesh);
    radiosity::ProgressiveSolver solver(mesh, radiosity::surfaceProperties(mesh, scene, {}));
    radiosity::SolveOptions options;
    options.residualTarget = 0.01; // ~4600 bounces of the whole box
    options.shootersPerBatch = 8;
    options.progressInterval = 0.0;
    double previous = 1.0, worstRise = 0.0;
    options.progress = [&](const radiosity::SolveProgress& p) {
        worstRise = std::max(worstRise, p.residual - previous);
        previous = p.residual;
    };
    const auto reason = radiosity::solve(solver, formFactors, options);
    ASSERT_TRUE(reason.has_value()) << reason.error().describe();
    EXPECT_EQ(*reason, radiosity::StopReason::Converged);

    // Analytic equilibrium (ProgressiveSolverTest): mean wall radiosity
    // rho / (1 - rho) * E / A with E = 1 per channel and A = 6; 1% is unshot.
    const double equilibrium = double(rho) / (1.0 - double(rho)) / 6.0;
    const WallStats walls = wallStats(solver);
    const double balance = balanceError(solver);
    std::cout << "[ figures ] reflectance 0.999: " << solver.state().shots << " shots, mean wall radiosity "
              << walls.mean / equilibrium << " of the analytic equilibrium, balance error " << balance
              << ", worst residual rise " << worstRise << "\n";
    // Measured 0.98999 of the equilibrium (the 1% left unshot is missing):
    // never above it (that would be energy created), and within 0.5% of 0.99.
    EXPECT_LT(walls.mean, equilibrium);
    EXPECT_NEAR(walls.mean / equilibrium, 1.0 - options.residualTarget, 0.005);
    // Measured 5.0e-7 after 72,772 shots (float radiosity, double
    // bookkeeping): 1e-5 leaves 20x for other compilers' rounding, while a
    // lost or doubled shot (1/24 of the power at the start) would be 4e-2.
    EXPECT_LT(balance, 1e-5);
    EXPECT_LE(worstRise, 1e-9); // unshot energy never grows when rho < 1
}

// Patches of area 1e-4 (the registry's smallest radiosity.maxPatchArea) in a
// box of side 0.05: form factors do not depend on scale, so every patch must
// get the radiosity of the same patch in the unit box, without the 1/r^2 of
// the point-to-polygon factor over- or underflowing at millimetre distances.
TEST(HardCaseRadiosity, TinyPatchesMatchTheUnitBoxAndKeepTheBalance) {
    constexpr float side = 0.05f;
    constexpr float rho = 0.7f;
    auto solveBox = [&](float scale, float maxPatchArea) {
        const scene::Scene scene = scaledBox(rho, scale);
        auto mesh = std::make_unique<radiosity::PatchMesh>(radiosity::buildPatchMesh(scene, {maxPatchArea}));
        auto solver = std::make_unique<radiosity::ProgressiveSolver>(
            *mesh, radiosity::surfaceProperties(*mesh, scene, {}));
        CachedFormFactors formFactors(*mesh);
        radiosity::SolveOptions options;
        options.residualTarget = 1e-3;
        options.shootersPerBatch = 8;
        EXPECT_TRUE(radiosity::solve(*solver, formFactors, options).has_value());
        return std::make_pair(std::move(mesh), std::move(solver));
    };
    const auto [tinyMesh, tiny] = solveBox(side, 1e-4f);
    const auto [unitMesh, unit] = solveBox(1.0f, 1e-4f / (side * side));
    ASSERT_EQ(tinyMesh->size(), unitMesh->size());
    EXPECT_GE(tinyMesh->size(), 150u); // 25 patches per face
    double worstArea = 0.0, worstPatch = 0.0;
    for (std::size_t i = 0; i < tinyMesh->size(); ++i) {
        worstArea = std::max(worstArea, double(tinyMesh->patches[i].area));
        const glm::vec3 a = tiny->state().radiosity[i];
        const glm::vec3 b = unit->state().radiosity[i];
        ASSERT_TRUE(finite(a)) << "patch " << i;
        ASSERT_GT(b.x, 0.0f);
        worstPatch = std::max(worstPatch, double(std::abs(a.x - b.x) / b.x));
    }
    const double balance = balanceError(*tiny);
    std::cout << "[ figures ] tiny patches (" << tinyMesh->size() << " of area <= " << worstArea
              << "): worst relative difference to the unit box " << worstPatch << ", balance error "
              << balance << "\n";
    EXPECT_LE(worstArea, 1.0001e-4);
    // Measured 1.4e-4: the form factors agree to float rounding, but both
    // solves stop at 1e-3 unshot and rounding can change which of two equal
    // shooters goes first, so the bound is that residual: 1e-3. A
    // scale-dependent term (an epsilon in metres) would change patches by
    // percents.
    EXPECT_LT(worstPatch, 1e-3);
    EXPECT_LT(balance, 1e-6); // measured 3.4e-10
    // And the solution is the analytic one: mean reflected radiosity
    // rho / (1 - rho) / 6 less the 0.1% unshot; measured as printed.
    const double mean = wallStats(*tiny).mean / (rho / (1.0 - rho) / 6.0);
    std::cout << "[ figures ] tiny patches: mean reflected radiosity " << mean
              << " of the analytic equilibrium\n";
    EXPECT_NEAR(mean, 1.0 - 1e-3, 2e-3);
}
