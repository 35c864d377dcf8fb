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
