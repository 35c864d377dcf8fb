#include "lpv/bench/Plots.h"
#include "lpv/bench/Pareto.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>

namespace lpv::bench {

namespace {

namespace IBA = OIIO::ImageBufAlgo;

constexpr int kWidth = 800, kHeight = 500;
constexpr int kLeft = 90, kRight = 190, kTop = 50, kBottom = 70; // margins: axis labels left, legend right

// DejaVu Sans from fonts-dejavu-core; OpenImageIO also searches its own font path for the name.
std::string fontPath() {
    for (const char* p :
         {"/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf", "/usr/share/fonts/TTF/DejaVuSans.ttf"})
        if (std::filesystem::exists(p))
            return p;
    return "DejaVuSans";
}

void text(OIIO::ImageBuf& img, int x, int y, const std::string& s, int size = 14,
          IBA::TextAlignX ax = IBA::TextAlignX::Left) {
    static const std::string font = fontPath();
    const float black[] = {0.1f, 0.1f, 0.1f, 1.0f};
    // Without the font the call fails and the plot stays unlabelled, not broken.
    (void)IBA::render_text(img, x, y, s, size, font, black, ax);
}

OIIO::cspan<float> colour(std::size_t i) {
    static const float palette[][4] = {{0.12f, 0.47f, 0.71f, 1}, {1.0f, 0.5f, 0.05f, 1},
                                       {0.17f, 0.63f, 0.17f, 1}, {0.84f, 0.15f, 0.16f, 1},
                                       {0.58f, 0.4f, 0.74f, 1},  {0.55f, 0.34f, 0.29f, 1},
                                       {0.89f, 0.47f, 0.76f, 1}, {0.5f, 0.5f, 0.5f, 1},
                                       {0.74f, 0.74f, 0.13f, 1}, {0.09f, 0.75f, 0.81f, 1}};
    return OIIO::cspan<float>(palette[i % 10], 4);
}

std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", v);
    return buf;
}

struct Axes {
    double x0, x1, y0, y1;
    bool logX = false;
    int px(double x) const {
        const double t = logX ? (std::log(std::max(x, 1e-300)) - std::log(x0)) / (std::log(x1) - std::log(x0))
                              : (x - x0) / (x1 - x0);
        return kLeft + int(t * double(kWidth - kLeft - kRight));
    }
    int py(double y) const {
        return kHeight - kBottom - int((y - y0) / (y1 - y0) * double(kHeight - kTop - kBottom));
    }
};

Axes fit(const std::vector<std::pair<double, double>>& all) {
    Axes a{std::numeric_limits<double>::max(), std::numeric_limits<double>::lowest(),
           std::numeric_limits<double>::max(), std::numeric_limits<double>::lowest()};
    for (const auto& [x, y] : all) {
        if (!std::isfinite(x) || !std::isfinite(y))
            continue;
        a.x0 = std::min(a.x0, x);
        a.x1 = std::max(a.x1, x);
        a.y0 = std::min(a.y0, y);
        a.y1 = std::max(a.y1, y);
    }
    if (a.x0 > a.x1)
        a = {0, 1, 0, 1};
    a.y0 = std::min(a.y0, 0.0); // times and errors start at zero
    if (a.x1 - a.x0 <= 0.0)
        a.x1 = a.x0 + 1.0;
    if (a.y1 - a.y0 <= 0.0)
        a.y1 = a.y0 + 1.0;
    a.y1 += 0.05 * (a.y1 - a.y0);
    return a;
}

// A log x axis from the smallest to the largest x (errors bars included),
// widened to the round ticks around them.
void fitLogX(Axes& a, const std::vector<double>& xs) {
    double lo = std::numeric_limits<double>::max(), hi = 0.0;
    for (double x : xs)
        if (std::isfinite(x) && x > 0.0) {
            lo = std::min(lo, x);
            hi = std::max(hi, x);
        }
    if (hi <= 0.0) {
        lo = 1.0;
        hi = 10.0;
    }
    const std::vector<double> ticks = logTicks(lo, hi);
    a.x0 = std::min(lo / 1.15, ticks.front());
    a.x1 = std::max(hi * 1.15, ticks.back());
    a.logX = true;
}

OIIO::ImageBuf frame(const std::string& title, const std::string& xLabel, const std::string& yLabel,
                     const Axes& a) {
    OIIO::ImageBuf img(OIIO::ImageSpec(kWidth, kHeight, 4, OIIO::TypeDesc::FLOAT));
    const float white[] = {1, 1, 1, 1}, grey[] = {0.85f, 0.85f, 0.85f, 1}, black[] = {0.1f, 0.1f, 0.1f, 1};
    IBA::fill(img, white);
    std::vector<double> xTicks;
    if (a.logX)
        for (double t : logTicks(a.x0, a.x1)) {
            if (t >= a.x0 && t <= a.x1)
                xTicks.push_back(t);
        }
    else
        for (int i = 0; i <= 5; ++i)
            xTicks.push_back(a.x0 + (a.x1 - a.x0) * i / 5.0);
    for (double x : xTicks) {
        IBA::render_line(img, a.px(x), kTop, a.px(x), kHeight - kBottom, grey);
        text(img, a.px(x), kHeight - kBottom + 18, a.logX ? tickLabel(x) : number(x), 12, IBA::TextAlignX::Center);
    }
    for (int i = 0; i <= 5; ++i) {
        const double y = a.y0 + (a.y1 - a.y0) * i / 5.0;
        IBA::render_line(img, kLeft, a.py(y), kWidth - kRight, a.py(y), grey);
        text(img, kLeft - 6, a.py(y) + 4, number(y), 12, IBA::TextAlignX::Right);
    }
    IBA::render_box(img, kLeft, kTop, kWidth - kRight, kHeight - kBottom, black);
    text(img, kWidth / 2, 30, title, 16, IBA::TextAlignX::Center);
    text(img, (kLeft + kWidth - kRight) / 2, kHeight - 20, xLabel, 14, IBA::TextAlignX::Center);
    text(img, 8, kTop - 12, yLabel, 14);
    return img;
}

void dot(OIIO::ImageBuf& img, int x, int y, OIIO::cspan<float> c, bool filled) {
    IBA::render_box(img, x - 4, y - 4, x + 4, y + 4, c, filled);
}

scene::Image8 toImage8(const OIIO::ImageBuf& img) {
    const OIIO::ImageSpec& spec = img.spec();
    scene::Image8 out{spec.width, spec.height, 4, {}};
    out.pixels.resize(std::size_t(spec.width) * std::size_t(spec.height) * 4);
    img.get_pixels(OIIO::ROI(0, spec.width, 0, spec.height, 0, 1, 0, 4), OIIO::TypeDesc::UINT8,
                   out.pixels.data());
    return out;
}

} // namespace

scene::Image8 linePlot(const std::string& title, const std::string& xLabel, const std::string& yLabel,
                       const std::vector<PlotSeries>& series) {
    std::vector<std::pair<double, double>> all;
    for (const PlotSeries& s : series)
        all.insert(all.end(), s.points.begin(), s.points.end());
    const Axes a = fit(all);
    OIIO::ImageBuf img = frame(title, xLabel, yLabel, a);
    for (std::size_t k = 0; k < series.size(); ++k) {
        auto pts = series[k].points;
        std::ranges::sort(pts);
        for (std::size_t i = 0; i < pts.size(); ++i) {
            dot(img, a.px(pts[i].first), a.py(pts[i].second), colour(k), true);
            if (i > 0)
                IBA::render_line(img, a.px(pts[i - 1].first), a.py(pts[i - 1].second), a.px(pts[i].first),
                                 a.py(pts[i].second), colour(k));
        }
        const int ly = kTop + 10 + int(k) * 20;
        IBA::render_box(img, kWidth - kRight + 12, ly - 8, kWidth - kRight + 22, ly + 2, colour(k), true);
        text(img, kWidth - kRight + 28, ly + 2, series[k].name, 12);
    }
    return toImage8(img);
}

scene::Image8 scatterPlot(const std::string& title, const std::string& xLabel, const std::string& yLabel,
                          const std::vector<PlotPoint>& points, bool logX) {
    std::vector<std::pair<double, double>> all;
    std::vector<double> xs;
    for (const PlotPoint& p : points) {
        all.emplace_back(p.x, p.y);
        xs.push_back(p.x);
        if (p.xHigh > p.xLow) {
            all.emplace_back(p.xLow, p.y);
            all.emplace_back(p.xHigh, p.y);
            xs.push_back(p.xLow);
            xs.push_back(p.xHigh);
        }
    }
    Axes a = fit(all);
    if (logX)
        fitLogX(a, xs);
    OIIO::ImageBuf img = frame(title, xLabel, yLabel, a);
    std::vector<PlotPoint> front;
    for (const PlotPoint& p : points)
        if (p.highlighted)
            front.push_back(p);
    std::ranges::sort(front, {}, &PlotPoint::x);
    const float red[] = {0.84f, 0.15f, 0.16f, 1}, blue[] = {0.12f, 0.47f, 0.71f, 1},
                orange[] = {1.0f, 0.55f, 0.0f, 1}, grey[] = {0.45f, 0.45f, 0.45f, 1};
    for (std::size_t i = 1; i < front.size(); ++i)
        IBA::render_line(img, a.px(front[i - 1].x), a.py(front[i - 1].y), a.px(front[i].x), a.py(front[i].y),
                         red);
    for (const PlotPoint& p : points) {
        if (p.xHigh > p.xLow) { // the time's interquartile range, with end ticks
            const int y = a.py(p.y), x0 = a.px(p.xLow), x1 = a.px(p.xHigh);
            IBA::render_line(img, x0, y, x1, y, grey);
            IBA::render_line(img, x0, y - 3, x0, y + 3, grey);
            IBA::render_line(img, x1, y - 3, x1, y + 3, grey);
        }
        const float* c = p.biased ? orange : p.highlighted ? red : blue;
        dot(img, a.px(p.x), a.py(p.y), OIIO::cspan<float>(c, 4), p.highlighted);
        if (p.highlighted)
            text(img, a.px(p.x) + 7, a.py(p.y) - 6, p.label + (p.biased ? " (biased)" : ""), 11);
    }
    const int ly = kTop + 10;
    IBA::render_box(img, kWidth - kRight + 12, ly - 8, kWidth - kRight + 22, ly + 2, red, true);
    text(img, kWidth - kRight + 28, ly + 2, "Pareto front", 12);
    IBA::render_box(img, kWidth - kRight + 12, ly + 12, kWidth - kRight + 22, ly + 22, blue, false);
    text(img, kWidth - kRight + 28, ly + 22, "other settings", 12);
    IBA::render_box(img, kWidth - kRight + 12, ly + 32, kWidth - kRight + 22, ly + 42, orange, false);
    text(img, kWidth - kRight + 28, ly + 42, "biased (mean", 12);
    text(img, kWidth - kRight + 28, ly + 58, "outside 0.8-1.25x)", 12);
    IBA::render_line(img, kWidth - kRight + 10, ly + 70, kWidth - kRight + 24, ly + 70, grey);
    text(img, kWidth - kRight + 28, ly + 74, "time's spread", 12);
    return toImage8(img);
}

std::vector<double> logTicks(double lo, double hi) {
    if (!(lo > 0.0) || !(hi >= lo))
        return {1.0, 10.0};
    const int first = int(std::floor(std::log10(lo)));
    const int last = int(std::ceil(std::log10(hi)));
    const int decades = last - first;
    const std::vector<double> steps = decades <= 3 ? std::vector<double>{1, 2, 5}
                                      : decades <= 6 ? std::vector<double>{1, 3}
                                                     : std::vector<double>{1};
    std::vector<double> ticks;
    for (int e = first; e <= last; ++e)
        for (double m : steps) {
            const double t = m * std::pow(10.0, e);
            // The ticks just around the range, and every one inside it.
            if (t >= lo / 10.0 && t <= hi * 10.0)
                ticks.push_back(t);
        }
    if (ticks.empty()) // cannot happen for finite lo <= hi (10^floor(log10 lo) is in range); GCC cannot see it
        return {lo, hi};
    // Keep the largest tick at or below lo, the smallest at or above hi, and those between.
    double below = ticks.front(), above = ticks.back();
    for (double t : ticks)
        if (t <= lo)
            below = t;
    for (auto t = ticks.rbegin(); t != ticks.rend(); ++t)
        if (*t >= hi)
            above = *t;
    std::vector<double> kept;
    for (double t : ticks)
        if (t >= below && t <= above)
            kept.push_back(t);
    return kept;
}

std::string tickLabel(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

scene::Image8 contactSheet(const std::vector<std::pair<std::string, scene::Image8>>& images, int perRow) {
    if (images.empty())
        return {};
    const int w = images.front().second.width, h = images.front().second.height, caption = 22;
    const int cols = std::max(1, std::min(perRow, int(images.size())));
    const int rows = (int(images.size()) + cols - 1) / cols;
    OIIO::ImageBuf sheet(OIIO::ImageSpec(cols * (w + 4), rows * (h + caption + 4), 4, OIIO::TypeDesc::UINT8));
    const float white[] = {1, 1, 1, 1};
    IBA::fill(sheet, white);
    for (std::size_t i = 0; i < images.size(); ++i) {
        const scene::Image8& im = images[i].second;
        if (im.width != w || im.height != h || im.channels != 4)
            continue;
        const int x0 = int(i) % cols * (w + 4) + 2, y0 = int(i) / cols * (h + caption + 4) + 2;
        sheet.set_pixels(OIIO::ROI(x0, x0 + w, y0, y0 + h, 0, 1, 0, 4), OIIO::TypeDesc::UINT8,
                         im.pixels.data());
        text(sheet, x0 + 2, y0 + h + 16, images[i].first, 12);
    }
    return toImage8(sheet);
}

} // namespace lpv::bench
