// The report's convergence question (issue #47) without GL: on the imported
// Cornell box seen by its framing camera (as `lpv import` and `lpv bench
// report` see it), each of its settings refines the scene-fitted LPV (cell
// h, n steps, N cells per axis) to cells 2h, h, h/2 with steps n/2, n, 2n and
// N/2, N, 2N cells per axis, so every run's cascades cover the same space and
// carry light as far.
#include "TestPaths.h"

#include "lpv/bench/Questions.h"
#include "lpv/bench/Settings.h"
#include "lpv/importers/Importer.h"
#include "lpv/renderer/LpvFit.h"
#include "lpv/scene/FramingCamera.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

using namespace lpv;

namespace {

const bench::Question& convergence() {
    const auto& questions = bench::reportQuestions();
    const auto it = std::ranges::find(questions, std::string("convergence"), &bench::Question::name);
    if (it == questions.end())
        throw std::runtime_error("no convergence question");
    return *it;
}

std::vector<std::vector<bench::Setting>> combinationsOf(const std::string& sweep) {
    std::string error;
    const bench::SetPlan plan = bench::planSettings({sweep}, error);
    EXPECT_TRUE(error.empty()) << error;
    return plan.combinations;
}

} // namespace

TEST(ConvergenceQuestion, RefinesTheFittedCellsAndScalesStepsAndCellCountOnTheImportedCornellBox) {
    auto imported =
        importers::importScene(std::filesystem::path(test::kSharedScenesDir) / "cornell/CornellBox-Original.obj");
    ASSERT_TRUE(imported) << imported.error().describe();
    const scene::Bounds bounds = imported->scene.worldBounds();
    const glm::vec3 eye = scene::framingCamera(imported->scene).position;
    const scene::ParameterSet defaults;

    const auto combinations = combinationsOf(convergence().sweep);
    ASSERT_EQ(combinations.size(), 3u);
    ASSERT_TRUE(bench::checkCombinations({{}, combinations}, defaults, "--sweep") == std::nullopt);
    const int n = defaults.getInt("lpv.propagationSteps"), cells = defaults.getInt("lpv.gridSize");
    const double h = renderer::fitLpv(defaults, bounds, eye).cellSize; // the fitted finest cell
    const double refinements[] = {0.5, 1.0, 2.0};
    for (std::size_t i = 0; i < combinations.size(); ++i) {
        scene::ParameterSet p = defaults;
        for (const auto& [key, value] : combinations[i])
            ASSERT_TRUE(p.setFromText(key, value, "--sweep").has_value());
        const renderer::LpvFit fit = renderer::fitLpv(p, bounds, eye);
        const scene::ParameterSet frame = renderer::withFit(p, fit);
        const double r = refinements[i];
        SCOPED_TRACE(fit.reason);
        EXPECT_TRUE(fit.fitted);
        EXPECT_NEAR(frame.getFloat("lpv.cellSize"), h / r, 1e-6 * h);
        EXPECT_EQ(frame.getInt("lpv.propagationSteps"), int(n * r));
        EXPECT_EQ(frame.getInt("lpv.gridSize"), int(cells * r));
        // The coarsest cascade's extent and light's reach in it do not change.
        EXPECT_NEAR(frame.getFloat("lpv.cellSize") * frame.getInt("lpv.gridSize"), h * cells, 1e-5 * h * cells);
        EXPECT_NEAR(frame.getFloat("lpv.cellSize") * frame.getInt("lpv.propagationSteps"), h * n, 1e-5 * h * n);
        EXPECT_EQ(renderer::lpvDelivery(fit, cells, bounds, eye).problem, renderer::LpvDelivery::Problem::None);
    }
    // The 2 m box framed from outside: the fit's cells are larger than 1/160 of it.
    EXPECT_GT(h, 2.0 / 160.0);
    // --quick leaves it out (x2 alone costs 13x the fitted frame).
    EXPECT_TRUE(convergence().quickSweep.empty());
}
