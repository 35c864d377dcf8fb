#pragma once
// The hemicube of Cohen and Greenberg (1985) laid out in one image: the top
// face (res x res) on the left, then the four half-height side faces
// (res x res/2 each) stacked in two columns, so one shooter fills a
// 3*res x res rectangle. Both the GPU kernel and the tests use this layout.
#include <glm/glm.hpp>

#include <array>
#include <vector>

namespace lpv::radiosity {

struct HemicubeFace {
    int x = 0, y = 0, width = 0, height = 0; // pixel rectangle in the 3*res x res layout
    // Camera basis in the shooter's tangent frame (t, b, n): the face looks
    // along `forward`, with `up` its image y axis.
    glm::vec3 forward{0.0f};
    glm::vec3 up{0.0f};
    bool side = false; // side faces see only the upper half (above the horizon)
};

struct HemicubeLayout {
    int resolution = 0; // even
    int width() const { return 3 * resolution; }
    int height() const { return resolution; }
    std::array<HemicubeFace, 5> faces() const;
};

// Delta form factor of every pixel of the layout, rows bottom to top (GL
// order): top face dA / (pi (x^2 + y^2 + 1)^2), side faces
// z dA / (pi (u^2 + z^2 + 1)^2), on a cube of half-size 1. They sum to 1 up to
// the discretisation.
std::vector<float> deltaFormFactors(int resolution);

} // namespace lpv::radiosity
