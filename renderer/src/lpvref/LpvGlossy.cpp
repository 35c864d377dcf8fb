#include "lpv/renderer/lpv/LpvGlossy.h"

#include <algorithm>
#include <cmath>

namespace lpv::renderer::lpvref {

float cascadeMargin(const GridFrame& frame, const glm::vec3& x) {
    const glm::vec3 u = (x - frame.origin) / frame.cellSize;
    const glm::vec3 m = glm::min(u, glm::vec3(float(frame.n)) - u);
    return std::min(m.x, std::min(m.y, m.z));
}

int glossyCascade(std::span<const GridFrame> frames, const glm::vec3& x, float footprint) {
    int found = -1;
    for (std::size_t k = 0; k < frames.size(); ++k) {
        // The same one-cell margin as the diffuse lookup: the trilinear filter stays inside the cube.
        if (cascadeMargin(frames[k], x) < 1.0f)
            continue;
        found = int(k);
        if (frames[k].cellSize >= footprint)
            break;
    }
    return found;
}

glm::vec3 radianceToward(const ShGrid& accumulated, const GridFrame& frame, const glm::vec3& x,
                         const glm::vec3& travel) {
    const glm::vec3 u = (x - frame.origin) / frame.cellSize;
    const glm::vec4 basis = sh::basis(travel);
    glm::vec3 l(0.0f);
    for (int c = 0; c < 3; ++c)
        l[c] = std::max(0.0f, glm::dot(sampleTrilinear(accumulated, c, u), basis));
    return l / (frame.cellSize * frame.cellSize);
}

glm::vec3 glossyIncoming(std::span<const ShGrid> accumulated, std::span<const GridFrame> frames,
                         const glm::vec3& x, const glm::vec3& r, float glossiness, const GlossyMarch& march) {
    if (frames.empty() || march.steps <= 0)
        return glm::vec3(0.0f);
    // Steps grow geometrically from one finest cell to the maximum distance, so
    // equal weights per sample favour what is near (each covers dt / t alike)
    // and far samples, which read coarse cascades, are few.
    const float s0 = frames[0].cellSize;
    const float t0 = s0;
    const float tMax = std::max(march.maxDistanceCells * s0, t0);
    const float growth = march.steps > 1 ? std::pow(tMax / t0, 1.0f / float(march.steps - 1)) : 1.0f;
    // tan of the cone's half angle: a mirror reads the finest cells, a rough surface coarser ones.
    const float spread = 1.0f - std::clamp(glossiness, 0.0f, 1.0f);
    glm::vec3 sum(0.0f);
    int samples = 0;
    float t = t0;
    for (int i = 0; i < march.steps; ++i) {
        const glm::vec3 p = x + r * t;
        const int k = glossyCascade(frames, p, 2.0f * t * spread);
        if (k < 0)
            break; // left the coarsest cascade: a ray does not come back into a cube it left
        sum += radianceToward(accumulated[std::size_t(k)], frames[std::size_t(k)], p, -r);
        ++samples;
        t *= growth;
    }
    return samples > 0 ? sum / float(samples) * march.intensity : glm::vec3(0.0f);
}

glm::vec3 glossyReflectance(const glm::vec3& f0, float glossiness, float nDotV) {
    const float m = std::pow(1.0f - std::clamp(nDotV, 0.0f, 1.0f), 5.0f);
    return std::clamp(glossiness, 0.0f, 1.0f) * (f0 + (glm::vec3(1.0f) - f0) * m);
}

} // namespace lpv::renderer::lpvref
