#include "lpv/renderer/lpv/LpvSubsurfaceReference.h"

#include <cmath>

namespace lpv::renderer::lpvref {

ShGrid injectSubsurface(const GridFrame& grid, std::span<const TranslucentVpl> vpls) {
    ShGrid out(grid.n);
    for (const TranslucentVpl& t : vpls) {
        if (!(t.translucency > 0.0f))
            continue;
        // No offset: the light starts inside the material at the lit surface and
        // travels into it, away from the light that lit it.
        const glm::ivec3 c(glm::floor((t.vpl.position - grid.origin) / grid.cellSize));
        if (!out.inside(c.x, c.y, c.z))
            continue;
        const glm::vec3 inward = -t.vpl.normal;
        for (int ch = 0; ch < 3; ++ch)
            out.at(ch, c.x, c.y, c.z) += sh::vplIntensity(inward, t.vpl.flux[ch] * t.translucency);
    }
    return out;
}

ShGrid propagateSubsurface(const ShGrid& injected, int steps, float attenuation) {
    ShGrid accumulated = injected;
    ShGrid current = injected;
    const float keep = 1.0f - attenuation;
    for (int i = 0; i < steps; ++i) {
        // No geometry volume: the material's own surfaces would block the light inside it.
        current = propagateStep(current, nullptr);
        for (auto& channel : current.channel)
            for (glm::vec4& v : channel)
                v *= keep;
        accumulated += current;
    }
    return accumulated;
}

glm::vec3 subsurfaceIrradianceAt(const ShGrid& accumulated, const GridFrame& grid, const glm::vec3& x,
                                 const glm::vec3& n) {
    return irradianceAt(accumulated, grid, x, -n);
}

} // namespace lpv::renderer::lpvref
