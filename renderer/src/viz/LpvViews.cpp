#include "lpv/renderer/viz/LpvViews.h"

#include "lpv/renderer/lpv/Sh.h"
#include "lpv/renderer/viz/LeakMaps.h"

#include <algorithm>
#include <cctype>
#include <cstdio>

namespace lpv::renderer::viz {

using scene::ErrorCode;
using scene::makeError;

namespace {

constexpr const char* kSources[] = {"injected", "step", "accumulated", "gv", "leak", "backside"};
constexpr const char* kQuantities[] = {"band0", "coefficient", "directional"};
constexpr const char* kChannels[] = {"red", "green", "blue", "luminance", "rgb"};

std::string upper(std::string s) {
    for (char& c : s)
        c = char(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

std::string formatDirection(const glm::vec3& d) {
    char text[64];
    std::snprintf(text, sizeof text, "(%.2g,%.2g,%.2g)", double(d.x), double(d.y), double(d.z));
    return text;
}

// How much a geometry-volume cell blocks light along its most blocked axis
// direction: a surface in the cell blocks one of the six strongly.
float strongestBlocking(const glm::vec4& potential) {
    float most = 0.0f;
    for (int axis = 0; axis < 3; ++axis)
        for (const float sign : {-1.0f, 1.0f}) {
            glm::vec3 d(0.0f);
            d[axis] = sign;
            most = std::max(most, std::clamp(sh::evaluate(potential, d), 0.0f, 1.0f));
        }
    return most;
}

// Where the slice lies in the world and which of its cells the geometry
// crosses (the geometry volume's blocking at or above the wall threshold):
// for an LPV slice, any of the cell's eight corners (GV cells sit on the LPV
// cell corners); for a GV slice, the cell itself.
SliceGuides guidesFor(const LpvSnapshot& snapshot, const LpvViewSpec& spec, const SliceField& field) {
    const LpvGridFrame& frame = snapshot.frame;
    const bool gvSlice = spec.source == LpvSource::Geometry;
    const glm::ivec2 uv = inPlaneAxes(spec.slice.axis);
    const int axis = int(spec.slice.axis);
    // A GV cell is centred on an LPV corner: its pixel starts half a cell before it.
    const float shift = gvSlice ? -0.5f : 0.0f;
    SliceGuides guides;
    guides.axis = spec.slice.axis;
    guides.cellSize = frame.cellSize;
    guides.origin = {frame.origin[uv.x] + shift * frame.cellSize,
                     frame.origin[uv.y] + shift * frame.cellSize};
    guides.plane = frame.origin[axis] + (float(spec.slice.index) + (gvSlice ? 0.0f : 0.5f)) * frame.cellSize;
    const int g = frame.gridSize + 1;
    if (snapshot.geometry.size() != std::size_t(g) * std::size_t(g) * std::size_t(g))
        return guides; // occlusion off: no geometry volume, no outline
    auto blocked = [&](glm::ivec3 c) {
        if (glm::any(glm::lessThan(c, glm::ivec3(0))) || glm::any(glm::greaterThanEqual(c, glm::ivec3(g))))
            return false;
        const std::size_t at =
            std::size_t(c.x) + std::size_t(g) * (std::size_t(c.y) + std::size_t(g) * std::size_t(c.z));
        return strongestBlocking(snapshot.geometry[at]) >= spec.wallThreshold;
    };
    guides.geometry.assign(std::size_t(field.width) * std::size_t(field.height), 0);
    for (int v = 0; v < field.height; ++v)
        for (int u = 0; u < field.width; ++u) {
            glm::ivec3 cell(0);
            cell[uv.x] = u;
            cell[uv.y] = v;
            cell[axis] = spec.slice.index;
            bool any = gvSlice && blocked(cell);
            for (int corner = 0; !gvSlice && !any && corner < 8; ++corner)
                any = blocked(cell + glm::ivec3(corner & 1, corner >> 1 & 1, corner >> 2 & 1));
            guides.geometry[std::size_t(v) * std::size_t(field.width) + std::size_t(u)] = any ? 1 : 0;
        }
    return guides;
}

} // namespace

LpvCaptureRequest captureFor(const LpvViewSpec& spec) {
    // The step volume of step 0 is the injected volume; the leak views read the accumulator.
    const int last = 1 << 20; // clamped by the renderer to the frame's step count
    int step = spec.step < 0 ? last : spec.step;
    if (spec.source == LpvSource::Injected)
        step = 0;
    return {spec.cascade, step};
}

const char* sourceName(LpvSource source) {
    return kSources[int(source)];
}
std::optional<LpvSource> sourceFromName(const std::string& name) {
    for (int i = 0; i < 6; ++i)
        if (name == kSources[i])
            return LpvSource(i);
    return std::nullopt;
}
const char* quantityName(Quantity quantity) {
    return kQuantities[int(quantity)];
}
std::optional<Quantity> quantityFromName(const std::string& name) {
    for (int i = 0; i < 3; ++i)
        if (name == kQuantities[i])
            return Quantity(i);
    return std::nullopt;
}
const char* channelName(Channel channel) {
    return kChannels[int(channel)];
}
std::optional<Channel> channelFromName(const std::string& name) {
    for (int i = 0; i < 5; ++i)
        if (name == kChannels[i])
            return Channel(i);
    return std::nullopt;
}
std::optional<Axis> axisFromName(const std::string& name) {
    if (name == "x")
        return Axis::X;
    if (name == "y")
        return Axis::Y;
    if (name == "z")
        return Axis::Z;
    return std::nullopt;
}

int sliceCount(const LpvSnapshot& snapshot, LpvSource source) {
    return snapshot.frame.gridSize + (source == LpvSource::Geometry ? 1 : 0);
}

std::string viewTitle(const LpvSnapshot& snapshot, const LpvViewSpec& spec) {
    static const char* axes[] = {"X", "Y", "Z"};
    std::string title = "CASCADE " + std::to_string(snapshot.cascade) + "  " + axes[int(spec.slice.axis)] +
                        " = " + std::to_string(spec.slice.index) + "  ";
    switch (spec.source) {
    case LpvSource::Injected:
        title += "INJECTED";
        break;
    case LpvSource::Step:
    case LpvSource::Accumulated:
        title += "STEP " + std::to_string(snapshot.step) + "/" + std::to_string(snapshot.propagationSteps) +
                 (spec.source == LpvSource::Step ? " ALONE" : " ACCUMULATED");
        break;
    case LpvSource::Geometry:
        title += "GEOMETRY VOLUME";
        break;
    case LpvSource::LeakHeat:
        title += "LEAK FLUX TO STEP " + std::to_string(snapshot.step);
        break;
    case LpvSource::Backside:
        title += "BACK-SIDE LIGHT";
        break;
    }
    title += "  ";
    switch (spec.slice.quantity) {
    case Quantity::Band0:
        title += spec.source == LpvSource::LeakHeat
                     ? "W"
                     : (spec.source == LpvSource::Backside ? "W/M^2" : "BAND 0");
        break;
    case Quantity::Coefficient:
        title += "COEFFICIENT " + std::to_string(spec.slice.coefficient);
        break;
    case Quantity::Directional:
        title += (spec.source == LpvSource::Geometry ? "BLOCKING ALONG " : "IRRADIANCE W/M^2 FACING ") +
                 formatDirection(spec.slice.direction);
        break;
    }
    if (spec.source != LpvSource::Geometry)
        title += "  " + upper(channelName(spec.slice.channel));
    return title;
}

scene::Expected<SliceField> lpvViewField(const LpvSnapshot& snapshot, const LpvViewSpec& spec) {
    const int n = snapshot.frame.gridSize;
    VolumeView view{n, snapshot.frame.cellSize, {}};
    auto coloured = [&](const ShVolume& v) { view.channels = {&v[0], &v[1], &v[2]}; };
    ShVolume derived; // leak views: computed here, sliced below
    const bool needsGv = spec.source == LpvSource::Geometry || spec.source == LpvSource::LeakHeat ||
                         spec.source == LpvSource::Backside;
    if (needsGv && snapshot.geometry.empty())
        return makeError(ErrorCode::InvalidValue, "lpv view", "source",
                         std::string(sourceName(spec.source)) +
                             " needs the geometry volume: lpv.occlusion is off");
    if (spec.source == LpvSource::Injected && snapshot.step != 0)
        return makeError(ErrorCode::InvalidValue, "lpv view", "step",
                         "the read-back holds step " + std::to_string(snapshot.step) +
                             ", not the injected volume");
    SliceSpec slice = spec.slice;
    switch (spec.source) {
    case LpvSource::Injected:
    case LpvSource::Step:
        coloured(snapshot.stepVolume);
        break;
    case LpvSource::Accumulated:
        coloured(snapshot.accumulatedToStep);
        break;
    case LpvSource::Geometry:
        view.size = n + 1;
        view.channels = {&snapshot.geometry, nullptr, nullptr};
        break;
    case LpvSource::LeakHeat:
        derived = leakHeat(snapshot.accumulatedToStep, snapshot.geometry, n, true, spec.wallThreshold);
        coloured(derived);
        slice.quantity = Quantity::Band0; // the maps hold a value per cell, not SH
        break;
    case LpvSource::Backside:
        derived =
            backsideLight(snapshot.accumulatedToStep, snapshot.geometry, snapshot.frame, spec.wallThreshold);
        coloured(derived);
        slice.quantity = Quantity::Band0;
        break;
    }
    return extractSlice(view, slice);
}

scene::Expected<scene::Image8> renderLpvView(const LpvSnapshot& snapshot, const LpvViewSpec& spec,
                                             SliceRange* usedRange) {
    auto field = lpvViewField(snapshot, spec);
    if (!field)
        return std::unexpected(field.error());
    ColourSpec colour = spec.colour;
    if (colour.title.empty())
        colour.title = viewTitle(snapshot, spec);
    const SliceGuides guides = guidesFor(snapshot, spec, *field);
    return renderSlice(*field, colour, usedRange, &guides);
}

} // namespace lpv::renderer::viz
