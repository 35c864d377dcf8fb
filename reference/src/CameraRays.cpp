#include "lpv/reference/CameraRays.h"
#include "lpv/reference/EmbreeScene.h"

#include <cmath>

namespace lpv::reference {

CameraRays::CameraRays(const scene::Camera& camera, float aspect)
    : inverseViewProjection_(glm::inverse(camera.projection(aspect) * camera.view())) {}

std::optional<CameraRay> CameraRays::through(float ndcX, float ndcY) const {
    const glm::vec4 nearH = inverseViewProjection_ * glm::vec4(ndcX, ndcY, -1.0f, 1.0f);
    const glm::vec4 farH = inverseViewProjection_ * glm::vec4(ndcX, ndcY, 1.0f, 1.0f);
    if (!(nearH.w != 0.0f) || !(farH.w != 0.0f)) // also false for NaN
        return std::nullopt;
    const glm::vec3 nearP = glm::vec3(nearH) / nearH.w;
    const glm::vec3 farP = glm::vec3(farH) / farH.w;
    const float length = glm::length(farP - nearP);
    if (!std::isfinite(length) || !(length > 0.0f))
        return std::nullopt;
    // glm::normalize, as the path tracer always did: its images stay bit for bit.
    CameraRay ray{nearP, glm::normalize(farP - nearP), length};
    if (!embreeAcceptsRay(ray.origin, ray.direction, 0.0f, ray.length))
        return std::nullopt;
    return ray;
}

} // namespace lpv::reference
