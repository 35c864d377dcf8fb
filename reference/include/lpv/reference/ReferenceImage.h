#pragma once
// What the path tracer produces at every pixel of the camera: the full image
// (radiance), the indirect diffuse irradiance at the primary hit after one
// bounce and after many, each with the variance of its mean so the
// reference's own noise is known, and a coverage mask (0 where the pixel
// sees the background).
#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace lpv::reference {

struct ReferenceImage {
    int width = 0;
    int height = 0;
    int samplesPerPixel = 0; // completed progressive passes
    double seconds = 0.0;    // wall time spent tracing

    // Rows top to bottom, width * height entries each.
    std::vector<glm::vec3> image;         // radiance (W/(m^2 sr)), before exposure and tonemapping
    std::vector<glm::vec3> indirectOne;   // irradiance (W/m^2) from light reflected once
    std::vector<glm::vec3> indirectMulti; // irradiance from light reflected up to `bounces` times
    std::vector<glm::vec3> imageVariance; // variance of the mean, per channel
    std::vector<glm::vec3> indirectOneVariance;
    std::vector<glm::vec3> indirectMultiVariance;
    std::vector<float> coverage; // 1 = geometry, 0 = background (sky)

    void resize(int w, int h);
    std::size_t pixelCount() const { return std::size_t(width) * std::size_t(height); }
};

// A named float channel, planar (one value per pixel), for multi-channel files.
struct Channel {
    std::string name; // EXR naming: "layer.R"
    std::vector<float> values;
};

// The EXR layout `lpv reference` writes: R,G,B (image), indirect1.R/G/B,
// indirect.R/G/B, variance.R/G/B, indirect1.variance.R/G/B,
// indirect.variance.R/G/B, coverage.Y.
std::vector<Channel> toChannels(const ReferenceImage& image);
// The inverse; channels missing from `channels` stay zero. Returns false if
// a channel's size does not match width x height.
bool fromChannels(const std::vector<Channel>& channels, int width, int height, ReferenceImage& out);

} // namespace lpv::reference
