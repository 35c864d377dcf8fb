#pragma once
// What accuracy costs: of (cost, error) points, those no other beats on
// both, and the cheapest under an error bound. A cost is a time with its
// spread (two times inside each other's noise are the same cost, Timing.h)
// or an exact figure such as GPU bytes. The error is the symmetric one
// (ErrorMetrics::symmetricError, issue #43): MARE rewarded a dark LPV. A
// point whose mean light is outside 0.8-1.25x the reference's is biased: the
// front still shows it, marked, and "cheapest within" passes it over. Used
// by the sweep's plots and report and by the editor's sweep dock.
#include "lpv/bench/Timing.h"

#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

namespace lpv::bench {

// The band of mean ratios (LPV over reference) a result may have and still
// be called unbiased (issue #24).
inline constexpr double kUnbiasedLow = 0.8;
inline constexpr double kUnbiasedHigh = 1.25;
bool biasedMean(double meanRatio);

struct CostPoint {
    double cost = 0.0;                    // ms (a median) or bytes
    double costLow = 0.0, costHigh = 0.0; // its spread (the interquartile range); equal to cost when exact
    double error = 0.0;
    bool biased = false;
};
// A time with its spread.
CostPoint timedPoint(const TimingStats& time, double error, bool biased);
// An exact cost (bytes).
CostPoint exactPoint(double cost, double error, bool biased);

// Whether two costs are the same: their spreads overlap, or they differ by
// less than `sameFraction` of the larger (kSameCostFraction for times, 0 for
// exact costs).
bool sameCostPoints(const CostPoint& a, const CostPoint& b, double sameFraction);

// Which points no other dominates: no point costs less (beyond the noise) or
// the same with an error lower (errors within 0.1% of each other tie), and
// is at least as good in the other.
std::vector<bool> paretoFront(const std::vector<CostPoint>& points, double sameFraction);
// Exact costs, no bias: (cost, error) pairs.
std::vector<bool> paretoFront(const std::vector<std::pair<double, double>>& points);

// The cheapest unbiased point whose error is at most `maxError`; among
// points of the same cost (within the noise) the one of lowest error.
// nullopt when none is.
std::optional<std::size_t> cheapestWithin(const std::vector<CostPoint>& points, double maxError, double sameFraction);
std::optional<std::size_t> cheapestWithin(const std::vector<std::pair<double, double>>& points, double maxError);

} // namespace lpv::bench
