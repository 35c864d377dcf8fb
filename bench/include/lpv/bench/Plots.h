#pragma once
// The PNG plots of a sweep (`lpv bench PROJECT --sweep`, the report), drawn with OpenImageIO's
// ImageBufAlgo (lines, boxes, text in DejaVu Sans where installed; without the
// font the plots have no labels and the Markdown report still names them).
#include "lpv/scene/Image.h"

#include <string>
#include <utility>
#include <vector>

namespace lpv::bench {

struct PlotSeries {
    std::string name;
    std::vector<std::pair<double, double>> points; // x, y; drawn in x order, joined by lines
};

struct PlotPoint {
    double x = 0.0;
    double y = 0.0;
    std::string label;
    bool highlighted = false; // on the Pareto front: filled, and joined by a line
    double xLow = 0.0, xHigh = 0.0; // an error bar along x (a time's interquartile range) when xHigh > xLow
    bool biased = false;             // its mean is outside 0.8-1.25x the reference's: drawn in orange
};

// Round ticks for a log axis over [lo, hi] (lo > 0): 1, 2 and 5 times powers
// of ten, fewer (1 and 3, then powers of ten only) when the range spans many
// decades; always at least the two decades around the range.
std::vector<double> logTicks(double lo, double hi);
// A tick's text: "0.5", "20", "1500".
std::string tickLabel(double v);

// Lines of y over x, one colour per series, with a legend.
scene::Image8 linePlot(const std::string& title, const std::string& xLabel, const std::string& yLabel,
                       const std::vector<PlotSeries>& series);
// Points; the highlighted ones joined in x order (the Pareto front). `logX`:
// x on a log scale with round ticks (times spanning 10 to 2000 ms).
scene::Image8 scatterPlot(const std::string& title, const std::string& xLabel, const std::string& yLabel,
                          const std::vector<PlotPoint>& points, bool logX = false);
// Images (RGBA8, same size) side by side in rows of `perRow`, each with its caption below.
scene::Image8 contactSheet(const std::vector<std::pair<std::string, scene::Image8>>& images, int perRow);

} // namespace lpv::bench
