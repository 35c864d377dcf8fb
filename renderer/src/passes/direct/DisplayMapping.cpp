#include "lpv/renderer/DisplayMapping.h"

#include "lpv/renderer/AutoExposure.h"

#include <algorithm>
#include <cmath>

namespace lpv::renderer {

namespace {

// Narkowicz's fit of the ACES reference rendering transform (tonemap.frag's acesFitted).
float acesFitted(float x) {
    const float a = 2.51f, b = 0.03f, c = 2.43f, d = 0.59f, e = 0.14f;
    return std::clamp((x * (a * x + b)) / (x * (c * x + d) + e), 0.0f, 1.0f);
}

float uncharted2Curve(float x) {
    const float A = 0.15f, B = 0.50f, C = 0.10f, D = 0.20f, E = 0.02f, F = 0.30f;
    return ((x * (A * x + C * B) + D * E) / (x * (A * x + B) + D * F)) - E / F;
}

float linearToSrgb(float c) {
    c = std::clamp(c, 0.0f, 1.0f);
    return c < 0.0031308f ? c * 12.92f : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

// Khronos PBR Neutral as its specification states it (tonemap.frag's pbrNeutral).
glm::vec3 pbrNeutral(glm::vec3 c) {
    const float f90 = 0.04f, startCompression = 0.8f - f90, desaturation = 0.15f;
    const float x = std::min({c.r, c.g, c.b});
    const float offset = x < 2.0f * f90 ? x - x * x / (4.0f * f90) : f90;
    c -= offset;
    const float peak = std::max({c.r, c.g, c.b});
    if (peak <= startCompression)
        return c;
    const float d = 1.0f - startCompression;
    const float newPeak = 1.0f - d * d / (peak + d - startCompression);
    c *= newPeak / peak;
    // The further a colour is overexposed, the more it fades toward white of the new peak.
    const float g = 1.0f - 1.0f / (desaturation * (peak - newPeak) + 1.0f);
    return c + (glm::vec3(newPeak) - c) * g;
}

float mapChannel(float x, Tonemapper op) {
    switch (op) {
    case Tonemapper::Aces:
        return acesFitted(x);
    case Tonemapper::Reinhard:
        return x / (1.0f + x);
    case Tonemapper::Uncharted2:
        return uncharted2Curve(2.0f * x) / uncharted2Curve(11.2f);
    case Tonemapper::Linear:
    case Tonemapper::Neutral:
        break;
    }
    return x;
}

glm::vec3 mapColour(const glm::vec3& x, Tonemapper op) {
    if (op == Tonemapper::Neutral)
        return pbrNeutral(x);
    return {mapChannel(x.r, op), mapChannel(x.g, op), mapChannel(x.b, op)};
}

// A display value as a unorm8 target stores it (round to nearest).
int toByte(float d) { return int(std::lround(std::clamp(d, 0.0f, 1.0f) * 255.0f)); }

} // namespace

Tonemapper tonemapperOf(const std::string& name) {
    if (name == "reinhard")
        return Tonemapper::Reinhard;
    if (name == "uncharted2")
        return Tonemapper::Uncharted2;
    if (name == "linear")
        return Tonemapper::Linear;
    if (name == "neutral")
        return Tonemapper::Neutral;
    return Tonemapper::Aces;
}

double whiteInput(Tonemapper op) {
    // Every operator rises monotonically with a grey input: bisect in log
    // space between a value shown below white and one far above any sun.
    const auto isWhite = [op](double x) {
        const glm::vec3 d = mapToDisplay(glm::vec3(float(x)), {1.0, op});
        return toByte(d.r) == 255 && toByte(d.g) == 255 && toByte(d.b) == 255;
    };
    double lo = 0.5, hi = 1e6; // linear shows 0.5 below white; Reinhard reaches it near 230
    if (!isWhite(hi))
        return hi;
    for (int i = 0; i < 60; ++i) {
        const double mid = std::sqrt(lo * hi);
        (isWhite(mid) ? hi : lo) = mid;
    }
    return hi;
}

glm::vec3 mapToDisplay(const glm::vec3& hdr, const DisplayMapping& mapping) {
    const glm::vec3 mapped = mapColour(hdr * float(mapping.exposure), mapping.tonemapper);
    return {linearToSrgb(mapped.r), linearToSrgb(mapped.g), linearToSrgb(mapped.b)};
}

scene::Image8 tonemapImage(const std::vector<glm::vec3>& hdr, int width, int height,
                           const DisplayMapping& mapping) {
    scene::Image8 out{width, height, 4, {}};
    const std::size_t n = std::size_t(std::max(width, 0)) * std::size_t(std::max(height, 0));
    out.pixels.assign(n * 4, 255);
    for (std::size_t i = 0; i < n && i < hdr.size(); ++i) {
        const glm::vec3 d = mapToDisplay(hdr[i], mapping);
        for (int c = 0; c < 3; ++c)
            out.pixels[i * 4 + std::size_t(c)] = std::uint8_t(toByte(d[c]));
    }
    return out;
}

MeterTarget meterTargetOf(const scene::ParameterSet& parameters) {
    MeterTarget t;
    t.key = parameters.getFloat("output.exposureKey");
    t.highlightPercent = parameters.getFloat("output.exposureHighlights");
    t.highlightInput = whiteInput(tonemapperOf(parameters.getEnum("output.tonemapper")));
    return t;
}

DisplayMapping meteredMapping(const std::vector<glm::vec3>& hdr, const scene::ParameterSet& parameters) {
    DisplayMapping m;
    m.tonemapper = tonemapperOf(parameters.getEnum("output.tonemapper"));
    m.exposure = std::exp2(parameters.getFloat("output.exposure"));
    if (parameters.getEnum("output.exposureMode") == "auto" && !hdr.empty()) {
        const LuminanceMeter meter = meterLuminance(&hdr.front().x, hdr.size(), 3);
        m.exposure *= std::exp(targetLogExposure(meter, meterTargetOf(parameters)));
    }
    return m;
}

} // namespace lpv::renderer
