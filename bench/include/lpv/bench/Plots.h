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
};

// Lines of y over x, one colour per series, with a legend.
scene::Image8 linePlot(const std::string& title, const std::string& xLabel, const std::string& yLabel,
                       const std::vector<PlotSeries>& series);
// Points; the highlighted ones joined in x order (the Pareto front).
scene::Image8 scatterPlot(const std::string& title, const std::string& xLabel, const std::string& yLabel,
                          const std::vector<PlotPoint>& points);
// Images (RGBA8, same size) side by side in rows of `perRow`, each with its caption below.
scene::Image8 contactSheet(const std::vector<std::pair<std::string, scene::Image8>>& images, int perRow);

} // namespace lpv::bench
