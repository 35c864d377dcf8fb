// The thesis preset (issue #25) called directly: its phases are medians
// over rounds of the per-round sums of their passes, its settings are the
// thesis's, and its camera looks along +x, pitched 5 degrees down.
#include "lpv/bench/ThesisSettings.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

using namespace lpv;
using namespace lpv::bench;

namespace {

TEST(ThesisSettings, ThesisPhasesAreMediansOverRoundsOfTheirPassSums) {
    auto pass = [](const char* name, double ms) { return renderer::PassTiming{name, ms, ms, ms, ms, 2}; };
    // Three rounds: shadow maps 10/12/14, RSM 5/5/5, propagation 20/30/25, shading 1/1/1.
    std::vector<std::vector<renderer::PassTiming>> rounds;
    const std::vector<std::pair<double, double>> shadowAndPropagation = {{10.0, 20.0}, {12.0, 30.0}, {14.0, 25.0}};
    for (const auto& [shadow, propagation] : shadowAndPropagation)
        rounds.push_back({pass("shadowMaps", shadow), pass("rsm", 5.0), pass("lpvPropagation", propagation),
                          pass("shading", 1.0)});
    const auto phases = thesisPhases(rounds, timingStatsOf({30.0, 31.0, 32.0}));
    auto find = [&](const std::string& name) {
        for (const ThesisPhase& p : phases)
            if (p.name == name)
                return p;
        ADD_FAILURE() << "no phase " << name;
        return ThesisPhase{};
    };
    EXPECT_DOUBLE_EQ(find("shadow maps").ours.median, 12.0);
    EXPECT_DOUBLE_EQ(find("shadow maps").ours.q1, 11.0);
    EXPECT_DOUBLE_EQ(find("shadow maps").ours.q3, 13.0);
    EXPECT_EQ(find("shadow maps").ours.rounds, 3);
    EXPECT_DOUBLE_EQ(find("propagation").ours.median, 25.0);
    // The whole frame is summed per round (36, 48, 45), not the sum of the phases' medians (43).
    EXPECT_DOUBLE_EQ(find("whole frame").ours.median, 45.0);
    EXPECT_DOUBLE_EQ(find("LPV off (whole frame)").ours.median, 31.0);
    const std::string text = formatThesisPhases(phases);
    EXPECT_NE(text.find("over 3 rounds"), std::string::npos) << text;
    EXPECT_NE(text.find("±IQR/2"), std::string::npos) << text;
}

TEST(ThesisSettings, PhasesLeaveOutPassesThatDidNotRunAndNameTheUngroupedOnes) {
    // "debugPass" belongs to no phase: counted in the whole frame and named there;
    // "rsm" with no samples did not run: in no phase's list.
    const std::vector<std::vector<renderer::PassTiming>> rounds = {
        {{"shadowMaps", 2.0, 2.0, 2.0, 2.0, 1}, {"rsm", 0.0, 0.0, 0.0, 0.0, 0}, {"debugPass", 3.0, 3.0, 3.0, 3.0, 1}}};
    const auto phases = thesisPhases(rounds, std::nullopt);
    ASSERT_EQ(phases.size(), 6u) << "five phases and the whole frame, no LPV-off row without its timing";
    EXPECT_EQ(phases[0].ourPasses, "shadowMaps");
    EXPECT_EQ(phases[1].name, "RSM");
    EXPECT_EQ(phases[1].ourPasses, "");
    EXPECT_DOUBLE_EQ(phases[1].ours.median, 0.0);
    EXPECT_EQ(phases.back().name, "whole frame");
    EXPECT_EQ(phases.back().ourPasses, "every pass (also debugPass)");
    EXPECT_DOUBLE_EQ(phases.back().ours.median, 5.0);
    EXPECT_TRUE(phases.back().thesisMs.has_value());
}

TEST(ThesisSettings, PresetIsTheThesisGridAndItsStartCamera) {
    const auto sets = thesisSettingsSets();
    for (const char* kv : {"lpv.cascades=4", "lpv.gridSize=32", "rsm.tileSize=128", "lpv.propagationSteps=8"})
        EXPECT_NE(std::ranges::find(sets, std::string(kv)), sets.end()) << kv;
    const scene::Camera c = thesisStartCamera();
    const glm::vec3 forward = c.target - c.position;
    EXPECT_NEAR(forward.z, 0.0f, 1e-6f) << "it looks along +x";
    EXPECT_GT(forward.x, 0.0f);
    EXPECT_NEAR(std::atan2(-forward.y, forward.x), 5.0f * 3.14159265f / 180.0f, 1e-5f) << "pitched 5 degrees down";
    EXPECT_NEAR(c.fovY, 60.0f * 3.14159265f / 180.0f, 1e-6f);
    EXPECT_EQ(kThesisWidth, 1024);
    EXPECT_EQ(kThesisHeight, 600);
}

} // namespace
