#pragma once
// Temporal stability of indirect light (issue #11 item 5, docs/flicker.md):
// the frame-to-frame change of indirect irradiance on pixels whose geometry
// did not change. Each pixel of the current frame is reprojected into the
// previous frame; it counts only if the previous frame saw the same surface
// there (position and normal within tolerance), so disocclusions and
// silhouettes are left out and what remains is the renderer's own flicker
// (plus any real change of the light, e.g. a moving sun). No GL: the images
// come from any renderer.
#include <glm/glm.hpp>

#include <cstddef>
#include <vector>

namespace lpv::reference {

// One frame: images of width x height, rows top to bottom.
struct FlickerFrame {
    int width = 0;
    int height = 0;
    const std::vector<glm::vec3>* indirect = nullptr; // irradiance (any linear unit)
    const std::vector<glm::vec3>* position = nullptr; // world; a non-finite value = background
    const std::vector<glm::vec3>* normal = nullptr;   // world, unit length; zero = background
    glm::mat4 viewProjection{1.0f};                   // this frame's camera, world to clip (GL conventions)
    glm::vec3 cameraPosition{0.0f};
};

struct FlickerOptions {
    // Same surface: positions closer than this fraction of the distance to the
    // camera (about 3 pixels at 160 px across a 45 degree view; nearest-pixel
    // lookup misses by up to a pixel footprint, more on grazing surfaces) ...
    float positionTolerance = 0.02f;
    // ... and normals within acos(0.95) = 18 degrees.
    float normalCosTolerance = 0.95f;
    // Added to the denominator as a fraction of the mean luminance of the kept
    // pixels, so near-black pixels do not dominate (as in Metrics.h).
    float epsilonFraction = 0.01f;
};

struct FlickerResult {
    std::size_t candidates = 0; // current pixels with geometry
    std::size_t pixels = 0;     // of those, the ones the previous frame saw the same surface at
    // Per kept pixel |L1 - L0| / ((L0 + L1) / 2 + eps), L = luminance.
    double meanRelativeChange = 0.0;
    double p95RelativeChange = 0.0;
    double meanLuminance = 0.0; // (L0 + L1) / 2 over the kept pixels
};

FlickerResult measureFlicker(const FlickerFrame& previous, const FlickerFrame& current,
                             const FlickerOptions& options = {});

// World positions from window-space depth (0..1, 1 = background, rows top to
// bottom) and the inverse of the camera's view-projection; background pixels
// get NaN.
std::vector<glm::vec3> positionsFromDepth(const std::vector<float>& depth, int width, int height,
                                          const glm::mat4& inverseViewProjection);

} // namespace lpv::reference
