// A light whose energy overflows (issue #42): its residual was NaN, and NaN
// is never <= the target, so `lpv radiosity` solved for ever, or with
// --max-seconds saved an all-black NaN solution. The solve now stops at
// once with an error. (The project reader refuses such a light first,
// ValueChecksTest; this is the solver's own guard.)
#include "RadiosityTestScenes.h"

#include "lpv/radiosity/DirectLight.h"
#include "lpv/radiosity/FormFactors.h"
#include "lpv/radiosity/ProgressiveSolver.h"
#include "lpv/radiosity/SolveLoop.h"
#include "lpv/radiosity/SurfaceProperties.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <limits>

using namespace lpv;

namespace {

void expectStopsWithError(radiosity::ProgressiveSolver& solver, const radiosity::PatchMesh& mesh) {
    radiosity::CpuFormFactors formFactors(mesh, false);
    radiosity::SolveOptions options;
    options.residualTarget = 1e-3;
    const auto start = std::chrono::steady_clock::now();
    const auto reason = radiosity::solve(solver, formFactors, options);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ASSERT_FALSE(reason.has_value()) << "stopped: " << radiosity::toString(*reason);
    EXPECT_EQ(reason.error().code, scene::ErrorCode::NonFinite);
    EXPECT_EQ(reason.error().location, "radiosity residual");
    EXPECT_EQ(reason.error().message,
              "the residual (unshot / emitted energy) is NaN after 0 shots: the emitted energy overflowed (a "
              "light, emissive surface or reflectance too large); the solution was not kept");
    EXPECT_LT(seconds, 1.0);
    std::printf("[ figures ] %.3f s: %s\n", seconds, reason.error().describe().c_str());
}

} // namespace

TEST(HardCaseRadiosity, OverflowingLightStopsTheSolveWithAnError) {
    scene::Scene s = test::closedBox(glm::vec3(0.5f), glm::vec3(0.0f));
    scene::Light light; // what the reader refuses, handed to the solver directly
    light.type = scene::LightType::Point;
    light.position = {0.5f, 0.5f, 0.5f};
    light.intensity = 3.4e38f;
    light.color = glm::vec3(3.4e38f);
    s.lights.push_back(light);
    const radiosity::PatchMesh mesh = radiosity::buildPatchMesh(s, {0.25f});
    radiosity::ProgressiveSolver solver(mesh, radiosity::surfaceProperties(mesh, s, {}));
    const auto direct = radiosity::directLight(mesh, s, {}, 1);
    ASSERT_TRUE(direct.has_value());
    ASSERT_TRUE(solver.addDirectLight(*direct).has_value());
    expectStopsWithError(solver, mesh);
}

TEST(HardCaseRadiosity, NanResidualStopsTheSolveWithAnError) {
    const scene::Scene s = test::closedBox(glm::vec3(0.5f), glm::vec3(1.0f));
    const radiosity::PatchMesh mesh = radiosity::buildPatchMesh(s, {0.25f});
    radiosity::ProgressiveSolver solver(mesh, radiosity::surfaceProperties(mesh, s, {}));
    // One patch receives an infinite irradiance, the rest none.
    std::vector<glm::vec3> direct(mesh.size(), glm::vec3(0.0f));
    std::fill_n(direct.begin(), std::min<std::size_t>(1, direct.size()),
                glm::vec3(std::numeric_limits<float>::infinity()));
    ASSERT_TRUE(solver.addDirectLight(direct).has_value());
    expectStopsWithError(solver, mesh);
}
