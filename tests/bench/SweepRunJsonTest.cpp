#include "lpv/bench/SweepRunJson.h"

#include <gtest/gtest.h>

#include <cstring>

using namespace lpv;

namespace {

bool sameBits(double a, double b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

} // namespace

TEST(SweepRunJson, ARunReadsBackWithTheSameBitsThroughText) {
    bench::SweepRun run;
    run.settings = {{"lpv.propagationSteps", "8"}, {"lpv.variant", "computeGather"}};
    run.bounces = 2;
    run.totalMs = 1.0 / 3.0;
    run.passes.push_back({"lpvPropagation", 12.345678901234567, 11.1, 14.2, 12.9, 7});
    run.indirect.mare = 0.1 + 0.2; // not exactly 0.3: a short decimal would lose it
    run.indirect.noiseMare = 1e-17;
    run.indirect.pixels = 14400;
    run.indirectOne.ssim = 0.987654321987654321;
    run.image.meanReference = 6.02214076e23;
    run.solveSeconds = 4.0 / 7.0;
    run.solveResidual = 0.0099;
    const std::string text = bench::sweepRunToJson(run).dump();
    const bench::SweepRun back = bench::sweepRunFromJson(nlohmann::json::parse(text));
    EXPECT_EQ(back.settings, run.settings);
    EXPECT_EQ(back.bounces, 2);
    EXPECT_TRUE(sameBits(back.totalMs, run.totalMs));
    ASSERT_EQ(back.passes.size(), 1u);
    EXPECT_EQ(back.passes[0].pass, "lpvPropagation");
    EXPECT_TRUE(sameBits(back.passes[0].medianMs, run.passes[0].medianMs));
    EXPECT_EQ(back.passes[0].samples, 7u);
    EXPECT_TRUE(sameBits(back.indirect.mare, run.indirect.mare));
    EXPECT_TRUE(sameBits(back.indirect.noiseMare, run.indirect.noiseMare));
    EXPECT_EQ(back.indirect.pixels, 14400u);
    EXPECT_TRUE(sameBits(back.indirectOne.ssim, run.indirectOne.ssim));
    EXPECT_TRUE(sameBits(back.image.meanReference, run.image.meanReference));
    EXPECT_TRUE(sameBits(back.solveSeconds, run.solveSeconds));
    EXPECT_TRUE(sameBits(back.solveResidual, run.solveResidual));
}

TEST(SweepRunJson, AMissingFieldThrowsInsteadOfReadingZero) {
    nlohmann::json j = bench::sweepRunToJson(bench::SweepRun{});
    j.erase("totalMs");
    EXPECT_THROW((void)bench::sweepRunFromJson(j), nlohmann::json::exception);
    // Except the radiosity solve's figures, which sweeps written before them lack.
    nlohmann::json older = bench::sweepRunToJson(bench::SweepRun{});
    older.erase("solveSeconds");
    older.erase("solveResidual");
    EXPECT_EQ(bench::sweepRunFromJson(older).solveSeconds, 0.0);
}
