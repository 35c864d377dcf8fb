// Issue #43: the statistics of interleaved timing rounds, on synthetic
// timings: a known noise gives a known spread, a real 2x difference is
// called a different cost and a 1.02x one the same, the rounds alternate
// their order, and they stop at the spread target, the round limit or the
// time budget.
#include "lpv/bench/Timing.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace lpv;
using bench::RoundPlan;
using bench::TimingStats;

namespace {

std::vector<renderer::PassTiming> table(double ms) { return {{"lpvPropagation", ms, ms, ms, ms, 3}}; }

// Times `means` in rounds, each sample the mean times (1 + noise) with noise
// drawn uniformly from [-amplitude, amplitude].
bench::RoundsResult timeSynthetic(const std::vector<double>& means, double amplitude, const RoundPlan& plan,
                                  unsigned seed = 7, std::vector<int>* order = nullptr) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> noise(-amplitude, amplitude);
    double clock = 0.0;
    bench::RoundCallbacks callbacks;
    callbacks.clock = [&] { return clock; };
    callbacks.timeOnce = [&](int index) -> scene::Expected<std::vector<renderer::PassTiming>> {
        if (order)
            order->push_back(index);
        const double ms = means[std::size_t(index)] * (1.0 + noise(random));
        clock += ms / 1000.0;
        return table(ms);
    };
    auto result = bench::timeInRounds(int(means.size()), plan, callbacks);
    EXPECT_TRUE(result.has_value());
    return result ? *result : bench::RoundsResult{};
}

} // namespace

TEST(TimingStats, QuartilesInterpolateBetweenOrderStatistics) {
    const TimingStats t = bench::timingStatsOf({4, 1, 3, 2, 5});
    EXPECT_DOUBLE_EQ(t.median, 3.0);
    EXPECT_DOUBLE_EQ(t.q1, 2.0);
    EXPECT_DOUBLE_EQ(t.q3, 4.0);
    EXPECT_DOUBLE_EQ(t.min, 1.0);
    EXPECT_DOUBLE_EQ(t.max, 5.0);
    EXPECT_EQ(t.rounds, 5);
    EXPECT_DOUBLE_EQ(t.relativeSpread(), 2.0 / 3.0);
    const TimingStats three = bench::timingStatsOf({10, 30, 20});
    EXPECT_DOUBLE_EQ(three.q1, 15.0) << "halfway between the lowest and the median";
    EXPECT_DOUBLE_EQ(three.q3, 25.0);
    EXPECT_EQ(bench::timingStatsOf({}).rounds, 0);
}

TEST(TimingStats, AKnownNoiseGivesAKnownSpread) {
    // Uniform noise of +-10% has an interquartile range of 10% of the mean
    // (the middle half of [-10%, +10%]); over 41 rounds within a fifth of that.
    RoundPlan plan{41, 41, 0.0, 0.0};
    const auto result = timeSynthetic({100.0}, 0.10, plan);
    ASSERT_EQ(result.rounds, 41);
    const TimingStats& t = result.settings[0].total;
    EXPECT_NEAR(t.median, 100.0, 3.0);
    EXPECT_NEAR(t.relativeSpread(), 0.10, 0.02);
    EXPECT_GE(t.min, 90.0);
    EXPECT_LE(t.max, 110.0);
    // Without noise, no spread.
    const auto quiet = timeSynthetic({100.0}, 0.0, {5, 5, 0.0, 0.0});
    EXPECT_DOUBLE_EQ(quiet.settings[0].total.spread(), 0.0);
    EXPECT_DOUBLE_EQ(quiet.settings[0].total.median, 100.0);
}

TEST(TimingStats, ARealTwofoldDifferenceIsDifferentAndTwoPercentIsTheSame) {
    const RoundPlan plan{9, 9, 0.0, 0.0};
    for (unsigned seed = 1; seed <= 50; ++seed) {
        // A quiet machine (+-2% per round): 1.02x apart is the same cost.
        const auto close = timeSynthetic({100.0, 102.0}, 0.02, plan, seed);
        EXPECT_TRUE(bench::sameCost(close.settings[0].total, close.settings[1].total)) << "seed " << seed;
        // A noisy one (+-20%): 2x apart is still a different cost.
        const auto twice = timeSynthetic({100.0, 200.0}, 0.20, plan, seed);
        EXPECT_FALSE(bench::sameCost(twice.settings[0].total, twice.settings[1].total)) << "seed " << seed;
    }
    // Even noiseless, 2% is under what a timer resolves from run to run.
    const auto exact = timeSynthetic({100.0, 102.0}, 0.0, plan);
    EXPECT_TRUE(bench::sameCost(exact.settings[0].total, exact.settings[1].total));
    // Noiseless and 10% apart: different.
    const auto tenPercent = timeSynthetic({100.0, 110.0}, 0.0, plan);
    EXPECT_FALSE(bench::sameCost(tenPercent.settings[0].total, tenPercent.settings[1].total));
    // A noise of 30% makes 1.25x apart the same: the difference is inside it.
    const TimingStats a{100, 85, 115, 70, 130, 9}, b{125, 118, 150, 100, 160, 9};
    EXPECT_TRUE(bench::sameCost(a, b));
}

TEST(TimingRounds, RoundsAlternateTheirOrder) {
    std::vector<int> order;
    timeSynthetic({1.0, 2.0, 3.0}, 0.0, {3, 3, 0.0, 0.0}, 1, &order);
    EXPECT_EQ(order, (std::vector<int>{0, 1, 2, 2, 1, 0, 0, 1, 2}));
    EXPECT_EQ(bench::roundOrder(2, 1), (std::vector<int>{1, 0}));
}

TEST(TimingRounds, TheyStopAtTheSpreadTargetTheRoundLimitOrTheBudget) {
    // Quiet: the minimum of 3 rounds already has every spread within 10%.
    const auto quiet = timeSynthetic({10.0, 20.0}, 0.01, {3, 9, 0.10, 0.0});
    EXPECT_EQ(quiet.rounds, 3);
    EXPECT_NE(quiet.stopReason.find("within 10%"), std::string::npos) << quiet.stopReason;
    // Noisy (+-50%): the spread stays over 10%, so the rounds go on to the limit.
    const auto noisy = timeSynthetic({10.0, 20.0}, 0.5, {3, 9, 0.10, 0.0});
    EXPECT_EQ(noisy.rounds, 9);
    EXPECT_NE(noisy.stopReason.find("round limit"), std::string::npos) << noisy.stopReason;
    // A budget of 0.5 s with rounds of 0.3 s (100 + 200 ms): one round, a second would end past it.
    const auto budget = timeSynthetic({100.0, 200.0}, 0.0, {3, 9, 0.10, 0.5});
    EXPECT_EQ(budget.rounds, 1);
    EXPECT_NE(budget.stopReason.find("time budget"), std::string::npos) << budget.stopReason;
    // No rounds at all: nothing timed.
    const auto none = timeSynthetic({10.0}, 0.0, {0, 0, 0.10, 0.0});
    EXPECT_EQ(none.rounds, 0);
    EXPECT_EQ(none.settings[0].total.rounds, 0);
}

TEST(TimingRounds, PassesAndTotalsAreTheRoundsMediansAndAStopIsAnError) {
    bench::RoundCallbacks callbacks;
    int calls = 0;
    callbacks.timeOnce = [&](int) -> scene::Expected<std::vector<renderer::PassTiming>> {
        ++calls;
        // Two passes; the total of a round is the sum of their medians.
        return std::vector<renderer::PassTiming>{{"a", double(calls), 0, 0, 0, 2}, {"b", 10.0, 0, 0, 0, 2}};
    };
    auto result = bench::timeInRounds(1, {3, 3, 0.0, 0.0}, callbacks);
    ASSERT_TRUE(result.has_value());
    const bench::SettingTiming& t = result->settings[0];
    ASSERT_EQ(t.passes.size(), 2u);
    EXPECT_DOUBLE_EQ(t.passes[0].medianMs, 2.0);
    EXPECT_DOUBLE_EQ(t.passes[0].minMs, 1.0);
    EXPECT_DOUBLE_EQ(t.passes[0].maxMs, 3.0);
    EXPECT_EQ(t.passes[0].samples, 6u) << "frames timed in all";
    EXPECT_DOUBLE_EQ(t.total.median, 12.0);
    callbacks.progress = [](int round, int, int) { return round < 1; };
    auto stopped = bench::timeInRounds(2, {3, 3, 0.0, 0.0}, callbacks);
    ASSERT_FALSE(stopped.has_value());
    EXPECT_EQ(stopped.error().code, scene::ErrorCode::Cancelled);
}

// Issue #43's target for two runs of one report: the same order of settings.
#include "lpv/bench/SharedTiming.h"

namespace {
bench::SharedTiming timingOf(const std::vector<double>& medians, double spread) {
    bench::SharedTiming t;
    for (std::size_t i = 0; i < medians.size(); ++i) {
        bench::SharedTiming::Entry e;
        e.parameters = {{"lpv.propagationSteps", std::to_string(i + 1)}};
        e.run.settings = e.parameters;
        const double m = medians[i];
        e.run.total = {m, m * (1.0 - spread / 2), m * (1.0 + spread / 2), m * (1.0 - spread), m * (1.0 + spread), 5};
        e.run.totalMs = m;
        t.entries.push_back(e);
    }
    return t;
}
} // namespace

TEST(TimingAgreement, TwoRunsInTheSameOrderAgreeAndASwapIsCounted) {
    EXPECT_DOUBLE_EQ(bench::spearman({1, 2, 3, 4}, {10, 20, 30, 40}), 1.0);
    EXPECT_DOUBLE_EQ(bench::spearman({1, 2, 3, 4}, {40, 30, 20, 10}), -1.0);
    EXPECT_DOUBLE_EQ(bench::spearman({1, 2, 2, 3}, {1, 2, 2, 3}), 1.0) << "ties take average ranks";
    // The second run 3% slower throughout: the same order, every setting the same cost as before.
    const auto a = timingOf({10, 20, 40, 80, 160}, 0.04);
    const auto same = bench::compareTimings(a, timingOf({10.3, 20.6, 41.2, 82.4, 164.8}, 0.04));
    EXPECT_EQ(same.settings, 5);
    EXPECT_DOUBLE_EQ(same.spearman, 1.0);
    EXPECT_EQ(same.distinctPairs, 10);
    EXPECT_EQ(same.discordantPairs, 0);
    EXPECT_EQ(same.sameCostInBoth, 5);
    EXPECT_NEAR(same.largestRatio, 1.03, 1e-9);
    // The two dearest swap places, and one setting took twice as long.
    const auto swapped = bench::compareTimings(a, timingOf({10, 40, 20, 160, 80}, 0.04));
    EXPECT_LT(swapped.spearman, 0.95);
    EXPECT_EQ(swapped.discordantPairs, 2);
    EXPECT_NEAR(swapped.largestRatio, 2.0, 1e-9);
    EXPECT_EQ(swapped.sameCostInBoth, 1);
    EXPECT_FALSE(bench::rankingAgrees(swapped));
    EXPECT_TRUE(bench::rankingAgrees(same));
}

TEST(TimingAgreement, SettingsOfTheSameCostMayTradePlacesWithoutBreakingTheRanking) {
    // Three settings within 2% of each other (the same cost) swap order between
    // the runs; the two dear ones keep theirs. All five: a low Spearman; the
    // three settings apart by more than the noise (one of the cheap ones, 50, 100): 1.
    const auto a = timingOf({10.0, 10.1, 10.2, 50, 100}, 0.04);
    const auto b = timingOf({10.2, 10.0, 10.1, 50, 100}, 0.04);
    const auto g = bench::compareTimings(a, b);
    EXPECT_LT(g.spearman, 0.95);
    EXPECT_EQ(g.distinctSettings, 3);
    EXPECT_DOUBLE_EQ(g.distinctSpearman, 1.0);
    EXPECT_EQ(g.discordantPairs, 0);
    EXPECT_TRUE(bench::rankingAgrees(g));
}
