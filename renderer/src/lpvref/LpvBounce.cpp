#include "lpv/renderer/lpv/LpvBounce.h"

#include <algorithm>

namespace lpv::renderer::lpvref {

ShGrid bounceVpls(const ShGrid& accumulated, const GvGrid& gv, float albedo) {
    const int n = accumulated.n;
    ShGrid out(n);
    for (int z = 0; z < n; ++z)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                // GV cells sit on the LPV cell corners: the cell centre is GV coordinate p + 0.5.
                const glm::vec4 b = gv.sample(glm::vec3(x, y, z) + 0.5f);
                // B = sum of coverage * cosineLobe(n): its band-1 part is the net oriented area.
                const glm::vec3 oriented = glm::vec3(-b.w, -b.y, b.z) / sh::kCos1;
                const float length = glm::length(oriented);
                if (!(length > 1e-6f))
                    continue;
                const glm::vec3 normal = oriented / length;
                const float coverage = std::min(length, 1.0f);
                const glm::vec4 receive = sh::cosineLobe(-normal), emit = sh::cosineLobe(normal) / sh::kPi;
                for (int c = 0; c < 3; ++c) {
                    // E s^2: the lookup's irradiance times the cell face; times the covered fraction, the
                    // flux received.
                    const float received = std::max(0.0f, glm::dot(accumulated.at(c, x, y, z), receive));
                    out.at(c, x, y, z) = (albedo * coverage * received) * emit;
                }
            }
    return out;
}

ShGrid propagateWithBounces(const ShGrid& injected, const GvGrid& gv, bool occlude, int steps, int bounces,
                            float albedo, std::vector<ShGrid>* perBounce, bool occludeFirstStep) {
    const GvGrid* blocking = occlude ? &gv : nullptr;
    // Every bounce's propagation starts like the first: lpv.occlusionFirstStep applies to each.
    ShGrid bounce = propagateAndAccumulate(injected, blocking, steps, nullptr, occludeFirstStep);
    ShGrid total = bounce;
    if (perBounce)
        perBounce->push_back(bounce);
    for (int b = 2; b <= bounces; ++b) {
        bounce = propagateAndAccumulate(bounceVpls(bounce, gv, albedo), blocking, steps, nullptr, occludeFirstStep);
        total += bounce;
        if (perBounce)
            perBounce->push_back(bounce);
    }
    return total;
}

} // namespace lpv::renderer::lpvref
