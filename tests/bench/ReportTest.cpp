#include "lpv/bench/Report.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

using namespace lpv;

namespace {

bench::SweepRun run(const std::string& steps, double ms, double mare, double meanRatio) {
    bench::SweepRun r;
    r.settings = {{"lpv.propagationSteps", steps}};
    r.totalMs = ms;
    r.indirect.mare = mare;
    r.indirect.meanReference = 2.0;
    r.indirect.meanTest = 2.0 * meanRatio;
    r.indirect.noiseMare = 0.03;
    r.image.mare = mare / 2.0;
    return r;
}

} // namespace

TEST(Report, RowsKnowWhichRunIsTheProjectsOwnAndTheMeanRatio) {
    scene::ParameterSet current;
    (void)current.setFromText("lpv.propagationSteps", "8");
    const auto rows = bench::reportRunsOf("steps", {run("0", 40, 0.9, 0.1), run("8", 100, 0.5, 0.7)}, current);
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_FALSE(rows[0].projectSettings);
    EXPECT_TRUE(rows[1].projectSettings);
    EXPECT_EQ(rows[1].setting, "lpv.propagationSteps=8");
    EXPECT_DOUBLE_EQ(rows[1].indirectMeanRatio, 0.7);
    EXPECT_DOUBLE_EQ(rows[0].imageMare, 0.45);
}

TEST(Report, TheHeadlineNamesTheCheapestUnderEachBoundAndTheBestInTheMeanBand) {
    scene::ParameterSet current;
    (void)current.setFromText("lpv.propagationSteps", "8");
    bench::SceneReport scene;
    scene.name = "room";
    scene.referenceNote = "64x48, 64 spp in 1.0 s, 1 bounce";
    // 16 steps: lowest error but far too dark; 32: under 10% and in the band; 64: under 5%.
    scene.runs = bench::reportRunsOf(
        "steps",
        {run("8", 100, 0.5, 0.7), run("16", 150, 0.04, 0.2), run("32", 200, 0.08, 0.9), run("64", 400, 0.045, 1.0)},
        current);
    EXPECT_EQ(bench::cheapestBelow(scene.runs, 0.10)->setting, "lpv.propagationSteps=16");
    EXPECT_EQ(bench::cheapestBelow(scene.runs, 0.01), nullptr);
    EXPECT_EQ(bench::lowestInBand(scene.runs)->setting, "lpv.propagationSteps=64");
    const std::string md = bench::reportMarkdown({scene}, "lpv bench report", "machine");
    EXPECT_NE(md.find("| room | 100.0 ms, 50.0%, mean 0.70x |"), std::string::npos) << md;
    EXPECT_NE(md.find("`lpv.propagationSteps=64`: 400.0 ms, 4.5%, mean 1.00x |\n"), std::string::npos) << md;
    EXPECT_NE(md.find("its own noise on the indirect light: MARE 3.0%"), std::string::npos) << md;
    const auto json = nlohmann::json::parse(bench::reportJson({scene}, "cmd", "machine"));
    ASSERT_EQ(json["scenes"][0]["runs"].size(), 4u);
    EXPECT_EQ(json["scenes"][0]["runs"][0]["projectSettings"], true);
    EXPECT_DOUBLE_EQ(json["scenes"][0]["runs"][2]["indirectMeanRatio"].get<double>(), 0.9);
}
