#include "lpv/radiosity/Hemicube.h"

#include <numbers>

namespace lpv::radiosity {

std::array<HemicubeFace, 5> HemicubeLayout::faces() const {
    const int r = resolution, h = resolution / 2;
    // Tangent frame: x = t, y = b, z = n. Side faces keep n as their up axis.
    return {{
        {0, 0, r, r, {0, 0, 1}, {0, 1, 0}, false},
        {r, 0, r, h, {1, 0, 0}, {0, 0, 1}, true},
        {r, h, r, h, {-1, 0, 0}, {0, 0, 1}, true},
        {2 * r, 0, r, h, {0, 1, 0}, {0, 0, 1}, true},
        {2 * r, h, r, h, {0, -1, 0}, {0, 0, 1}, true},
    }};
}

std::vector<float> deltaFormFactors(int resolution) {
    const HemicubeLayout layout{resolution};
    std::vector<float> out(std::size_t(layout.width() * layout.height()), 0.0f);
    const double pixel = 2.0 / resolution; // cube face spans [-1, 1]
    const double dA = pixel * pixel;
    for (const HemicubeFace& f : layout.faces())
        for (int y = 0; y < f.height; ++y)
            for (int x = 0; x < f.width; ++x) {
                const double u = -1.0 + (x + 0.5) * pixel;
                double value = 0.0;
                if (!f.side) {
                    const double v = -1.0 + (y + 0.5) * pixel;
                    const double d = u * u + v * v + 1.0;
                    value = dA / (std::numbers::pi * d * d);
                } else {
                    const double z = (y + 0.5) * pixel; // height above the horizon, 0..1
                    const double d = u * u + z * z + 1.0;
                    value = z * dA / (std::numbers::pi * d * d);
                }
                out[std::size_t((f.y + y) * layout.width() + f.x + x)] = float(value);
            }
    return out;
}

} // namespace lpv::radiosity
