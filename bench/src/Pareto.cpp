#include "lpv/bench/Pareto.h"

#include <algorithm>
#include <cmath>

namespace lpv::bench {

std::vector<bool> paretoFront(const std::vector<std::pair<double, double>>& points) {
    // Errors within 0.1% of each other are a tie: the LPV variants give the
    // same image up to float rounding, and the faster one should win.
    auto lessOrTie = [](double a, double b) { return a <= b + 1e-3 * std::max(std::abs(a), std::abs(b)); };
    std::vector<bool> front(points.size(), true);
    for (std::size_t i = 0; i < points.size(); ++i)
        for (std::size_t j = 0; j < points.size() && front[i]; ++j) {
            const auto& [xi, yi] = points[i];
            const auto& [xj, yj] = points[j];
            const bool tieY = lessOrTie(yj, yi) && lessOrTie(yi, yj);
            if (j != i && xj <= xi && lessOrTie(yj, yi) && (xj < xi || (yj < yi && !tieY)))
                front[i] = false;
        }
    return front;
}

std::optional<std::size_t> cheapestWithin(const std::vector<std::pair<double, double>>& points, double maxError) {
    std::optional<std::size_t> best;
    for (std::size_t i = 0; i < points.size(); ++i)
        if (points[i].second <= maxError && (!best || points[i].first < points[*best].first))
            best = i;
    return best;
}

} // namespace lpv::bench
