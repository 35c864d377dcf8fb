#include "lpv/bench/Pareto.h"

#include <gtest/gtest.h>

using lpv::bench::cheapestWithin;
using lpv::bench::paretoFront;

TEST(Pareto, APointBeatenOnTimeAndErrorIsOffTheFront) {
    // (ms, error): b is slower and worse than a; c is slower but better; d is fastest and worst.
    const std::vector<std::pair<double, double>> points{{10, 0.5}, {12, 0.6}, {20, 0.3}, {5, 0.9}};
    const std::vector<bool> front = paretoFront(points);
    EXPECT_EQ(front, (std::vector<bool>{true, false, true, true}));
}

TEST(Pareto, ErrorsWithinATenthOfAPercentTieAndTheFasterWins) {
    // The LPV variants give one image up to rounding: the slower one is off the front.
    const std::vector<std::pair<double, double>> points{{10, 0.5000}, {30, 0.49999}};
    EXPECT_EQ(paretoFront(points), (std::vector<bool>{true, false}));
    // A real error gain keeps the slower point.
    const std::vector<std::pair<double, double>> better{{10, 0.5}, {30, 0.45}};
    EXPECT_EQ(paretoFront(better), (std::vector<bool>{true, true}));
}

TEST(Pareto, CheapestWithinAnErrorBoundIsTheFastestThatMeetsIt) {
    const std::vector<std::pair<double, double>> points{{10, 0.5}, {40, 0.08}, {25, 0.09}, {60, 0.04}};
    EXPECT_EQ(cheapestWithin(points, 0.10), std::optional<std::size_t>(2));
    EXPECT_EQ(cheapestWithin(points, 0.05), std::optional<std::size_t>(3));
    EXPECT_FALSE(cheapestWithin(points, 0.01).has_value());
    EXPECT_FALSE(cheapestWithin({}, 1.0).has_value());
}

// Issue #43: times with their spread, and biased points.
using lpv::bench::CostPoint;
using lpv::bench::TimingStats;

namespace {
CostPoint timed(double median, double q1, double q3, double error, bool biased = false) {
    return lpv::bench::timedPoint(TimingStats{median, q1, q3, q1, q3, 5}, error, biased);
}
} // namespace

TEST(Pareto, TimesWithinEachOthersNoiseAreTheSameCostAndTheMoreAccurateWins) {
    // b is "faster" by 3 ms, but the two times' spreads overlap: one cost, and a's lower error wins.
    const std::vector<CostPoint> points{timed(100, 95, 105, 0.40), timed(97, 92, 102, 0.60)};
    EXPECT_EQ(paretoFront(points, lpv::bench::kSameCostFraction), (std::vector<bool>{true, false}));
    // Well apart (no overlap, 2x): both stay, the faster for its time.
    const std::vector<CostPoint> apart{timed(100, 98, 102, 0.40), timed(50, 49, 51, 0.60)};
    EXPECT_EQ(paretoFront(apart, lpv::bench::kSameCostFraction), (std::vector<bool>{true, true}));
}

TEST(Pareto, CheapestWithinPassesOverBiasedPoints) {
    // The cheapest point within 50% is biased (it lost its light): the next one is named.
    const std::vector<CostPoint> points{timed(10, 9.9, 10.1, 0.30, true), timed(20, 19.9, 20.1, 0.45),
                                        timed(40, 39.9, 40.1, 0.35)};
    EXPECT_EQ(cheapestWithin(points, 0.50, lpv::bench::kSameCostFraction), std::optional<std::size_t>(1));
    // Same cost within the noise: the lower error of the two.
    const std::vector<CostPoint> tied{timed(20, 18, 22, 0.45), timed(21, 19, 23, 0.35)};
    EXPECT_EQ(cheapestWithin(tied, 0.50, lpv::bench::kSameCostFraction), std::optional<std::size_t>(1));
    EXPECT_FALSE(cheapestWithin(std::vector<CostPoint>{timed(10, 9, 11, 0.1, true)}, 1.0,
                                lpv::bench::kSameCostFraction)
                     .has_value());
    EXPECT_TRUE(lpv::bench::biasedMean(0.28));
    EXPECT_TRUE(lpv::bench::biasedMean(1.3));
    EXPECT_FALSE(lpv::bench::biasedMean(0.8));
    EXPECT_FALSE(lpv::bench::biasedMean(1.25));
}
