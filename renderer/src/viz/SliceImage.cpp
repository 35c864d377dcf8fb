#include "lpv/renderer/viz/SliceImage.h"

#include "lpv/renderer/lpv/Sh.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace lpv::renderer::viz {

using scene::ErrorCode;
using scene::makeError;

namespace {

constexpr glm::vec3 kLuminance{0.2126f, 0.7152f, 0.0722f};
const char* const kAxisNames[] = {"x", "y", "z"};

// Cell (x, y, z) of in-plane position (u, v) on slice `index` across `axis`.
glm::ivec3 cellOf(Axis axis, int u, int v, int index) {
    switch (axis) {
    case Axis::X:
        return {index, v, u};
    case Axis::Y:
        return {u, index, v};
    case Axis::Z:
        break;
    }
    return {u, v, index};
}

// The scalar a cell shows for one colour channel.
float cellValue(const VolumeView& volume, const SliceSpec& spec, int channel, std::size_t cell) {
    const glm::vec4& f = (*volume.channels[std::size_t(channel)])[cell];
    switch (spec.quantity) {
    case Quantity::Band0:
        return f.x;
    case Quantity::Coefficient:
        return f[spec.coefficient];
    case Quantity::Directional:
        break;
    }
    const glm::vec3 d = glm::normalize(spec.direction);
    if (!volume.coloured()) // blocking potential of light travelling along d (docs/lpv.md, Occlusion)
        return std::clamp(sh::evaluate(f, -d), 0.0f, 1.0f);
    // As lpv_lookup.glsl reads the accumulator: intensity over the cell face area taken as radiance.
    return sh::irradiance(f, d) / (volume.cellSize * volume.cellSize);
}

std::uint8_t toByte(float v) {
    return std::uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
}

void setPixel(scene::Image8& image, int x, int y, const glm::vec3& c) {
    if (x < 0 || y < 0 || x >= image.width || y >= image.height)
        return;
    std::uint8_t* p = &image.pixels[(std::size_t(y) * std::size_t(image.width) + std::size_t(x)) * 4];
    p[0] = toByte(c.r);
    p[1] = toByte(c.g);
    p[2] = toByte(c.b);
    p[3] = 255;
}

std::string formatValue(float v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", double(v));
    return text;
}

// Maps a value to 0..1 (signed: -1..1) of the colour range.
struct Mapping {
    Scale scale = Scale::Linear;
    float high = 1.0f;
    float low = 0.0f; // log scale: the smallest magnitude shown
    bool isSigned = false;

    float operator()(float v) const {
        const float sign = v < 0.0f ? -1.0f : 1.0f;
        const float m = std::abs(v);
        float t = 0.0f;
        if (high <= 0.0f || !std::isfinite(v))
            t = 0.0f;
        else if (scale == Scale::Linear)
            t = m / high;
        else
            t = m <= low ? 0.0f : std::log(m / low) / std::log(high / low);
        t = std::clamp(t, 0.0f, 1.0f);
        return isSigned ? sign * t : (v < 0.0f ? 0.0f : t);
    }
    // The value at ramp position t (0..1, signed -1..1): the legend's labels. A log
    // ramp starts at `low` (signed: 0 in the middle, where everything below low lands).
    float valueAt(float t) const {
        if (!(high > 0.0f))
            return 0.0f; // an empty slice: low = high = 0 would label its log ramp NaN
        const float m = std::abs(t);
        const float v = scale == Scale::Linear
                            ? m * high
                            : (m <= 0.0f && isSigned ? 0.0f : low * std::pow(high / low, m));
        return t < 0.0f ? -v : v;
    }
};

const char* const kUpperAxisNames[] = {"X", "Y", "Z"};

void fillRect(scene::Image8& image, int x, int y, int width, int height, const glm::vec3& c) {
    for (int j = 0; j < height; ++j)
        for (int i = 0; i < width; ++i)
            setPixel(image, x + i, y + j, c);
}

// The caption's groups (separated by two spaces, as viewTitle writes them).
std::vector<std::string> captionGroups(const std::string& text) {
    std::vector<std::string> groups;
    std::size_t start = 0;
    while (start < text.size()) {
        const std::size_t end = std::min(text.find("  ", start), text.size());
        std::string group = text.substr(start, end - start);
        const auto first = group.find_first_not_of(' ');
        if (first != std::string::npos)
            groups.push_back(group.substr(first));
        start = end + 2;
    }
    return groups;
}

// The groups packed greedily into lines at most `width` pixels wide (a group
// wider than that has a line of its own; the caller makes the image that wide).
std::vector<std::string> wrapCaption(const std::vector<std::string>& groups, int width, int scale) {
    std::vector<std::string> lines;
    for (const std::string& g : groups) {
        if (!lines.empty() && textWidth(lines.back() + "  " + g, scale) <= width)
            lines.back() += "  " + g;
        else
            lines.push_back(g);
    }
    return lines;
}

// The geometry's boundary over the slice: an edge of a geometry cell whose
// neighbour across it has none (or is outside), drawn inside the cell.
void drawOutline(scene::Image8& image, const SliceField& field, const std::vector<std::uint8_t>& geometry,
                 int ppc) {
    if (geometry.size() != std::size_t(field.width) * std::size_t(field.height))
        return;
    const int line = ppc >= 6 ? 2 : 1;
    auto solid = [&](int u, int v) {
        return u >= 0 && v >= 0 && u < field.width && v < field.height &&
               geometry[std::size_t(v) * std::size_t(field.width) + std::size_t(u)] != 0;
    };
    for (int v = 0; v < field.height; ++v)
        for (int u = 0; u < field.width; ++u) {
            if (!solid(u, v))
                continue;
            const int left = u * ppc, top = (field.height - 1 - v) * ppc;
            if (!solid(u - 1, v))
                fillRect(image, left, top, line, ppc, kOutlineColour);
            if (!solid(u + 1, v))
                fillRect(image, left + ppc - line, top, line, ppc, kOutlineColour);
            if (!solid(u, v + 1)) // v up: the cell above is the image's row above
                fillRect(image, left, top, ppc, line, kOutlineColour);
            if (!solid(u, v - 1))
                fillRect(image, left, top + ppc - line, ppc, line, kOutlineColour);
        }
}

} // namespace

glm::ivec2 inPlaneAxes(Axis axis) {
    switch (axis) {
    case Axis::X:
        return {2, 1};
    case Axis::Y:
        return {0, 2};
    case Axis::Z:
        break;
    }
    return {0, 1};
}

float scaleBarLength(float worldWidth) {
    const float target = worldWidth / 3.0f;
    if (!(target > 0.0f) || !std::isfinite(target))
        return 0.0f;
    const float decade = std::pow(10.0f, std::floor(std::log10(target)));
    for (const float m : {5.0f, 2.0f, 1.0f})
        if (m * decade <= target * 1.0001f)
            return m * decade;
    return decade;
}

scene::Expected<SliceField> extractSlice(const VolumeView& volume, const SliceSpec& spec) {
    const int n = volume.size;
    const std::size_t cells = std::size_t(n) * std::size_t(n) * std::size_t(n);
    if (n <= 0 || !volume.channels[0] || volume.channels[0]->size() != cells ||
        (volume.coloured() && (volume.channels[1]->size() != cells || volume.channels[2]->size() != cells)))
        return makeError(ErrorCode::InvalidValue, "slice", "volume",
                         "no volume to slice (is the LPV running?)");
    const int axis = int(spec.axis);
    if (spec.index < 0 || spec.index >= n)
        return makeError(ErrorCode::OutOfRange, "slice", "slice",
                         std::to_string(spec.index) + " is outside 0.." + std::to_string(n - 1) + " along " +
                             kAxisNames[axis]);
    if (spec.quantity == Quantity::Coefficient && (spec.coefficient < 0 || spec.coefficient > 3))
        return makeError(ErrorCode::OutOfRange, "slice", "coefficient",
                         std::to_string(spec.coefficient) + " is outside 0..3");
    if (spec.quantity == Quantity::Directional && glm::length(spec.direction) < 1e-6f)
        return makeError(ErrorCode::InvalidValue, "slice", "direction", "the direction has no length");

    SliceField field;
    field.width = field.height = n;
    const bool rgb = volume.coloured() && spec.channel == Channel::Rgb;
    field.components = rgb ? 3 : 1;
    field.isSigned = spec.quantity == Quantity::Coefficient;
    field.values.resize(std::size_t(n) * std::size_t(n) * std::size_t(field.components));
    std::size_t out = 0;
    for (int v = 0; v < n; ++v)
        for (int u = 0; u < n; ++u) {
            const glm::ivec3 c = cellOf(spec.axis, u, v, spec.index);
            const std::size_t cell =
                std::size_t(c.x) + std::size_t(n) * (std::size_t(c.y) + std::size_t(n) * std::size_t(c.z));
            if (!volume.coloured()) {
                field.values[out++] = cellValue(volume, spec, 0, cell);
                continue;
            }
            const glm::vec3 value(cellValue(volume, spec, 0, cell), cellValue(volume, spec, 1, cell),
                                  cellValue(volume, spec, 2, cell));
            switch (spec.channel) {
            case Channel::Red:
            case Channel::Green:
            case Channel::Blue:
                field.values[out++] = value[int(spec.channel)];
                break;
            case Channel::Luminance:
                field.values[out++] = glm::dot(value, kLuminance);
                break;
            case Channel::Rgb:
                for (int k = 0; k < 3; ++k)
                    field.values[out++] = value[k];
                break;
            }
        }
    return field;
}

glm::vec3 falseColour(float t) {
    // Five stops of a perceptually ordered ramp (close to matplotlib's inferno).
    static const glm::vec3 stops[] = {{0.0f, 0.0f, 0.016f},
                                      {0.341f, 0.063f, 0.431f},
                                      {0.737f, 0.216f, 0.329f},
                                      {0.976f, 0.557f, 0.035f},
                                      {0.988f, 1.0f, 0.643f}};
    const float x = std::clamp(t, 0.0f, 1.0f) * 4.0f;
    const int i = std::min(int(x), 3);
    return glm::mix(stops[i], stops[i + 1], x - float(i));
}

glm::vec3 divergingColour(float t) {
    const glm::vec3 blue(0.231f, 0.298f, 0.753f), white(0.96f), red(0.706f, 0.016f, 0.149f);
    const float x = std::clamp(t, -1.0f, 1.0f);
    return x < 0.0f ? glm::mix(white, blue, -x) : glm::mix(white, red, x);
}

scene::Image8 renderSlice(const SliceField& field, const ColourSpec& colour, SliceRange* usedRange,
                          const SliceGuides* guides) {
    const int ppc = std::max(colour.pixelsPerCell, 1);
    constexpr int kFont = 2, kMargin = 4, kRamp = 12;
    const int lineHeight = 5 * kFont + 4;
    const int sliceWidth = field.width * ppc, sliceHeight = field.height * ppc;

    // Beside the slice: the world coordinates of its top and bottom edges;
    // under it, those of its left and right edges, then a scale bar in scene
    // units and the plane's coordinate (issue #46: the slices had no axes or scale).
    std::string vTop, vBottom, uLeft, uRight, barText, planeText;
    int besideWidth = 0, guidesHeight = 0, barPixels = 0;
    if (guides) {
        const glm::ivec2 uv = inPlaneAxes(guides->axis);
        const float worldWidth = guides->cellSize * float(field.width);
        const float worldHeight = guides->cellSize * float(field.height);
        auto coordinate = [](int axis, float value) {
            return std::string(kUpperAxisNames[axis]) + " " + formatValue(value);
        };
        uLeft = coordinate(uv.x, guides->origin.x);
        uRight = coordinate(uv.x, guides->origin.x + worldWidth);
        vBottom = coordinate(uv.y, guides->origin.y);
        vTop = coordinate(uv.y, guides->origin.y + worldHeight);
        const float bar = scaleBarLength(worldWidth);
        barPixels = int(std::lround(bar / guides->cellSize * float(ppc)));
        barText = formatValue(bar) + (bar == 1.0f ? " UNIT" : " UNITS"); // scene units: the scene's own scale
        planeText =
            std::string("PLANE ") + kUpperAxisNames[int(guides->axis)] + " = " + formatValue(guides->plane);
        besideWidth = kMargin + std::max(textWidth(vTop, kFont), textWidth(vBottom, kFont)) + kMargin;
        guidesHeight = kMargin + 2 * lineHeight;
    }
    // The legend needs room for three numbers; the guides for the bar and the plane.
    int width = std::max({sliceWidth + besideWidth, 3 * textWidth("-0.000E-00", kFont) + 4 * kMargin});
    if (guides)
        width = std::max(width, 2 * kMargin + barPixels + textWidth(barText, kFont) + 4 * kMargin +
                                    textWidth(planeText, kFont));
    // The caption wraps between its groups; one group wider than the image widens it.
    const std::string caption =
        colour.title.empty() ? std::string() : colour.title + (colour.scale == Scale::Log ? "  LOG" : "");
    const std::vector<std::string> groups = captionGroups(caption);
    for (const std::string& g : groups)
        width = std::max(width, textWidth(g, kFont) + 2 * kMargin);
    const std::vector<std::string> captionLines = wrapCaption(groups, width - 2 * kMargin, kFont);

    const int legendTop = sliceHeight + guidesHeight;
    const int legendHeight = kMargin + kRamp + kMargin + lineHeight * (1 + int(captionLines.size()));
    scene::Image8 image{width, legendTop + legendHeight, 4, {}};
    image.pixels.assign(std::size_t(image.width) * std::size_t(image.height) * 4, 0);
    for (std::size_t i = 3; i < image.pixels.size(); i += 4)
        image.pixels[i] = 255;

    float peak = 0.0f;
    for (float v : field.values)
        if (std::isfinite(v))
            peak = std::max(peak, std::abs(v));
    Mapping map;
    map.scale = colour.scale;
    map.isSigned = field.isSigned;
    map.high = colour.rangeMax.value_or(peak);
    map.low = map.high * std::pow(10.0f, -float(std::max(colour.logDecades, 1)));
    if (usedRange)
        *usedRange = {field.isSigned ? -map.high : (map.scale == Scale::Log ? map.low : 0.0f), map.high};
    const bool trueColour = field.components == 3 || !colour.falseColour;
    auto shade = [&](float t) {
        if (field.isSigned)
            return divergingColour(t);
        return trueColour ? glm::vec3(t) : falseColour(t);
    };

    for (int v = 0; v < field.height; ++v)
        for (int u = 0; u < field.width; ++u) {
            glm::vec3 c;
            if (field.components == 3)
                c = {map(field.at(u, v, 0)), map(field.at(u, v, 1)), map(field.at(u, v, 2))};
            else
                c = shade(map(field.at(u, v)));
            const int top = (field.height - 1 - v) * ppc;
            for (int y = 0; y < ppc; ++y)
                for (int x = 0; x < ppc; ++x)
                    setPixel(image, u * ppc + x, top + y, c);
        }

    if (guides) {
        drawOutline(image, field, guides->geometry, ppc);
        const int besideX = sliceWidth + kMargin;
        drawText(image, besideX, 0, vTop, kFont, kAxisLabelColour);
        drawText(image, besideX, std::max(sliceHeight - 5 * kFont, lineHeight), vBottom, kFont,
                 kAxisLabelColour);
        const int uTop = sliceHeight + kMargin;
        drawText(image, 0, uTop, uLeft, kFont, kAxisLabelColour);
        drawText(image,
                 std::max(sliceWidth - textWidth(uRight, kFont), textWidth(uLeft, kFont) + 2 * kMargin), uTop,
                 uRight, kFont, kAxisLabelColour);
        // The bar with end ticks, its length, and where the plane lies.
        const int barTop = uTop + lineHeight;
        fillRect(image, kMargin, barTop + 4, barPixels, 2, kScaleBarColour);
        fillRect(image, kMargin, barTop, 1, 5 * kFont, kScaleBarColour);
        fillRect(image, kMargin + barPixels - 1, barTop, 1, 5 * kFont, kScaleBarColour);
        const int barTextX = 2 * kMargin + barPixels;
        drawText(image, barTextX, barTop, barText, kFont, kAxisLabelColour);
        drawText(image, barTextX + textWidth(barText, kFont) + 4 * kMargin, barTop, planeText, kFont,
                 kAxisLabelColour);
    }

    // Legend: the ramp, its low / middle / high values, the caption.
    const int rampTop = legendTop + kMargin, rampWidth = width - 2 * kMargin;
    const float tLow = field.isSigned ? -1.0f : 0.0f;
    for (int x = 0; x < rampWidth; ++x) {
        const float t = tLow + (1.0f - tLow) * float(x) / float(std::max(rampWidth - 1, 1));
        for (int y = 0; y < kRamp; ++y)
            setPixel(image, kMargin + x, rampTop + y, shade(t));
    }
    const int labelTop = rampTop + kRamp + kMargin;
    const float tMid = 0.5f * (tLow + 1.0f);
    const std::string low = formatValue(map.valueAt(tLow)), mid = formatValue(map.valueAt(tMid)),
                      high = formatValue(map.valueAt(1.0f));
    drawText(image, kMargin, labelTop, low, kFont);
    drawText(image, (width - textWidth(mid, kFont)) / 2, labelTop, mid, kFont);
    drawText(image, width - kMargin - textWidth(high, kFont), labelTop, high, kFont);
    for (std::size_t i = 0; i < captionLines.size(); ++i)
        drawText(image, kMargin, labelTop + lineHeight * int(i + 1), captionLines[i], kFont, kCaptionColour);
    return image;
}

} // namespace lpv::renderer::viz
