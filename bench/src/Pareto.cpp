#include "lpv/bench/Pareto.h"

#include <algorithm>
#include <cmath>

namespace lpv::bench {

namespace {

// Errors within 0.1% of each other are a tie: the LPV variants give the
// same image up to float rounding, and the faster one should win.
bool lessOrTie(double a, double b) { return a <= b + 1e-3 * std::max(std::abs(a), std::abs(b)); }
bool tie(double a, double b) { return lessOrTie(a, b) && lessOrTie(b, a); }

std::vector<CostPoint> exactPoints(const std::vector<std::pair<double, double>>& points) {
    std::vector<CostPoint> out;
    for (const auto& [cost, error] : points)
        out.push_back(exactPoint(cost, error, false));
    return out;
}

} // namespace

bool biasedMean(double meanRatio) { return !(meanRatio >= kUnbiasedLow && meanRatio <= kUnbiasedHigh); }

CostPoint timedPoint(const TimingStats& time, double error, bool biased) {
    return {time.median, std::min(time.q1, time.median), std::max(time.q3, time.median), error, biased};
}

CostPoint exactPoint(double cost, double error, bool biased) { return {cost, cost, cost, error, biased}; }

bool sameCostPoints(const CostPoint& a, const CostPoint& b, double sameFraction) {
    const bool overlap = a.costLow <= b.costHigh && b.costLow <= a.costHigh;
    return overlap || std::abs(a.cost - b.cost) < sameFraction * std::max(a.cost, b.cost);
}

std::vector<bool> paretoFront(const std::vector<CostPoint>& points, double sameFraction) {
    std::vector<bool> front(points.size(), true);
    for (std::size_t i = 0; i < points.size(); ++i)
        for (std::size_t j = 0; j < points.size() && front[i]; ++j) {
            if (j == i)
                continue;
            const CostPoint& a = points[i];
            const CostPoint& b = points[j];
            const bool same = sameCostPoints(a, b, sameFraction);
            const bool cheaper = !same && b.cost < a.cost;
            const bool notDearer = same || cheaper;
            const bool moreAccurate = b.error < a.error && !tie(a.error, b.error);
            // Same cost and tied error: the lower median wins, as before the spread was known.
            const bool tieBreak = same && tie(a.error, b.error) && b.cost < a.cost;
            if (notDearer && lessOrTie(b.error, a.error) && (cheaper || moreAccurate || tieBreak))
                front[i] = false;
        }
    return front;
}

std::vector<bool> paretoFront(const std::vector<std::pair<double, double>>& points) {
    return paretoFront(exactPoints(points), 0.0);
}

std::optional<std::size_t> cheapestWithin(const std::vector<CostPoint>& points, double maxError,
                                          double sameFraction) {
    std::optional<std::size_t> best;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const CostPoint& p = points[i];
        if (p.biased || p.error > maxError)
            continue;
        if (!best) {
            best = i;
            continue;
        }
        const CostPoint& b = points[*best];
        if (sameCostPoints(p, b, sameFraction) ? p.error < b.error : p.cost < b.cost)
            best = i;
    }
    return best;
}

std::optional<std::size_t> cheapestWithin(const std::vector<std::pair<double, double>>& points, double maxError) {
    return cheapestWithin(exactPoints(points), maxError, 0.0);
}

} // namespace lpv::bench
