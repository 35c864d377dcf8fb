#pragma once
// What accuracy costs in time: of (cost, error) points, those no other beats
// on both, and the cheapest under an error bound. Used by the sweep's plot
// and report and by the editor's sweep dock.
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

namespace lpv::bench {

// Which points no other dominates (x and y lower or equal, one lower; y within 0.1% counts as equal).
std::vector<bool> paretoFront(const std::vector<std::pair<double, double>>& points);

// The point of lowest x whose y is at most `maxError`, or nullopt when none is.
std::optional<std::size_t> cheapestWithin(const std::vector<std::pair<double, double>>& points, double maxError);

} // namespace lpv::bench
