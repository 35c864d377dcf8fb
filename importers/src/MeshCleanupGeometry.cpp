// Small geometric helpers shared by the clean-up stages (MeshCleanupDetail.h).
#include "MeshCleanupDetail.h"

#include <cmath>

namespace lpv::importers::detail {

bool isUsableDirection(const glm::vec3& v) {
    const float lengthSquared = glm::dot(v, v);
    // The finite check on the square also rejects huge vectors whose length
    // overflows, which normalize() would turn into zeros.
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(lengthSquared) &&
           lengthSquared > 1e-12f;
}

glm::vec3 anyPerpendicular(const glm::vec3& n) {
    // Crossing with the axis least aligned with n keeps the result well conditioned.
    const glm::vec3 a = glm::abs(n);
    const glm::vec3 axis = a.x <= a.y && a.x <= a.z ? glm::vec3(1, 0, 0)
                           : a.y <= a.z             ? glm::vec3(0, 1, 0)
                                                    : glm::vec3(0, 0, 1);
    return glm::normalize(glm::cross(n, axis));
}

std::vector<double> cornerAngles(std::span<const glm::vec3> cornerPositions) {
    std::vector<double> angles(cornerPositions.size(), 0.0);
    for (std::size_t t = 0; t + 2 < cornerPositions.size(); t += 3) {
        for (std::size_t k = 0; k < 3; ++k) {
            const glm::dvec3 p(cornerPositions[t + k]);
            const glm::dvec3 a = glm::dvec3(cornerPositions[t + (k + 1) % 3]) - p;
            const glm::dvec3 b = glm::dvec3(cornerPositions[t + (k + 2) % 3]) - p;
            // atan2 stays accurate for angles near 0 and pi, where acos of a dot does not.
            angles[t + k] = std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
        }
    }
    return angles;
}

} // namespace lpv::importers::detail
