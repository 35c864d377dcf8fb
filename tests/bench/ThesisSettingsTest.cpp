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

// tools/thesis-app/run.sh's output as it prints it (issue #48 item 4's round 1).
constexpr const char* kRunShOutput = "# thesis application, 5 frames after 2 warm-up, lpv geometry\n"
                                     "# Renderer: llvmpipe (LLVM 15.0.6, 256 bits)\n"
                                     "phase shadow_maps 87.7\n"
                                     "#   shadow_maps min 86.3 max 105.2\n"
                                     "phase rsm 58.6\n"
                                     "phase lpv_clear 8.7\n"
                                     "phase injection 12.9\n"
                                     "phase propagation 168.1\n"
                                     "phase final_shading 183.9\n"
                                     "phase whole_frame 532.4\n"
                                     "phase lpv_off_whole_frame 393.2\n";

TEST(ThesisSettings, ARunOfTheThesisApplicationGivesTheTableItsFigures) {
    const auto figures = parseThesisRun(kRunShOutput, "run-1.txt");
    ASSERT_TRUE(figures) << figures.error().describe();
    EXPECT_DOUBLE_EQ(*figures->shadowMaps, 87.7);
    EXPECT_DOUBLE_EQ(*figures->injection, 8.7 + 12.9) << "its clear is part of our injection";
    EXPECT_DOUBLE_EQ(*figures->finalShading, 183.9);
    EXPECT_DOUBLE_EQ(*figures->wholeFrame, 532.4);
    EXPECT_DOUBLE_EQ(*figures->lpvOff, 393.2);
    const std::vector<std::vector<renderer::PassTiming>> rounds = {
        {{"shadowMaps", 50.0, 50.0, 50.0, 50.0, 1}, {"shading", 200.0, 200.0, 200.0, 200.0, 1}}};
    const auto phases = thesisPhases(rounds, timingStatsOf({300.0}), *figures);
    ASSERT_EQ(phases.size(), 7u);
    EXPECT_DOUBLE_EQ(*phases[0].thesisMs, 87.7);
    EXPECT_DOUBLE_EQ(*phases[5].thesisMs, 532.4);
    EXPECT_DOUBLE_EQ(*phases[6].thesisMs, 393.2);
    const std::string text = formatThesisPhases(phases, figures->source);
    EXPECT_NE(text.find("its figures: run-1.txt"), std::string::npos) << text;
    EXPECT_NE(text.find("0.57x"), std::string::npos) << "ours 50 against its 87.7 ms\n" << text;
    // Without a run the table says its figures are another day's.
    EXPECT_NE(formatThesisPhases(thesisPhases(rounds, std::nullopt)).find("issue #25's day"), std::string::npos);
}

TEST(ThesisSettings, AMalformedRunIsAnErrorNamingItsLine) {
    const auto bad = parseThesisRun("# header\nphase shadow_maps 87.7\nphase whole_frame fast\n", "run.txt");
    ASSERT_FALSE(bad);
    EXPECT_EQ(bad.error().code, scene::ErrorCode::InvalidValue);
    EXPECT_NE(bad.error().describe().find("line 3"), std::string::npos) << bad.error().describe();
    for (const char* value : {"nan", "inf", "-1", "12ms", ""}) {
        const auto refused = parseThesisRun(std::string("phase whole_frame ") + value + "\n", "run.txt");
        EXPECT_FALSE(refused) << "accepted \"" << value << "\"";
    }
    const auto none = parseThesisRun("lpv bench render output, not run.sh's\ntotal 612.0\n", "ours.txt");
    ASSERT_FALSE(none);
    EXPECT_EQ(none.error().code, scene::ErrorCode::MissingField);
    EXPECT_NE(none.error().describe().find("whole_frame"), std::string::npos) << none.error().describe();
}

TEST(ThesisSettings, FinalShadingCountsTheReducedLookupsPasses) {
    // At lpv.lookupResolution = half|quarter the diffuse lookup runs in its own
    // passes; the thesis application does it inside its forward pass.
    const std::vector<std::vector<renderer::PassTiming>> rounds = {{{"lpvLookup", 20.0, 20.0, 20.0, 20.0, 1},
                                                                    {"lpvLookupResolve", 30.0, 30.0, 30.0, 30.0, 1},
                                                                    {"shading", 100.0, 100.0, 100.0, 100.0, 1}}};
    const auto phases = thesisPhases(rounds, std::nullopt);
    ASSERT_EQ(phases[4].name, "final shading");
    EXPECT_DOUBLE_EQ(phases[4].ours.median, 150.0);
    EXPECT_EQ(phases[4].ourPasses, "lpvLookup + lpvLookupResolve + shading");
    EXPECT_EQ(phases.back().ourPasses, "every pass") << "nothing left outside the phases";
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
