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

float mapChannel(float x, Tonemapper op) {
    switch (op) {
    case Tonemapper::Aces:
        return acesFitted(x);
    case Tonemapper::Reinhard:
        return x / (1.0f + x);
    case Tonemapper::Uncharted2:
        return uncharted2Curve(2.0f * x) / uncharted2Curve(11.2f);
    case Tonemapper::Linear:
        break;
    }
    return x;
}

} // namespace

Tonemapper tonemapperOf(const std::string& name) {
    if (name == "reinhard")
        return Tonemapper::Reinhard;
    if (name == "uncharted2")
        return Tonemapper::Uncharted2;
    if (name == "linear")
        return Tonemapper::Linear;
    return Tonemapper::Aces;
}

glm::vec3 mapToDisplay(const glm::vec3& hdr, const DisplayMapping& mapping) {
    const float scale = float(mapping.exposure);
    glm::vec3 out;
    for (int c = 0; c < 3; ++c)
        out[c] = linearToSrgb(mapChannel(hdr[c] * scale, mapping.tonemapper));
    return out;
}

scene::Image8 tonemapImage(const std::vector<glm::vec3>& hdr, int width, int height,
                           const DisplayMapping& mapping) {
    scene::Image8 out{width, height, 4, {}};
    const std::size_t n = std::size_t(std::max(width, 0)) * std::size_t(std::max(height, 0));
    out.pixels.assign(n * 4, 255);
    for (std::size_t i = 0; i < n && i < hdr.size(); ++i) {
        const glm::vec3 d = mapToDisplay(hdr[i], mapping);
        for (int c = 0; c < 3; ++c) // a unorm8 target rounds to nearest
            out.pixels[i * 4 + std::size_t(c)] =
                std::uint8_t(std::lround(std::clamp(d[c], 0.0f, 1.0f) * 255.0f));
    }
    return out;
}

DisplayMapping meteredMapping(const std::vector<glm::vec3>& hdr, const scene::ParameterSet& parameters) {
    DisplayMapping m;
    m.tonemapper = tonemapperOf(parameters.getEnum("output.tonemapper"));
    m.exposure = std::exp2(parameters.getFloat("output.exposure"));
    if (parameters.getEnum("output.exposureMode") == "auto" && !hdr.empty()) {
        const renderer::LogLuminanceSum sum = renderer::meterLogLuminance(&hdr.front().x, hdr.size(), 3);
        m.exposure *= std::exp(renderer::targetLogExposure(sum, parameters.getFloat("output.exposureKey")));
    }
    return m;
}

} // namespace lpv::renderer
