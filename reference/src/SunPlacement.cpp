#include "lpv/reference/SunPlacement.h"
#include "lpv/reference/CameraRays.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace lpv::reference {
namespace {

constexpr float kDegrees = 180.0f / std::numbers::pi_v<float>;

struct ViewPoint {
    glm::vec3 position, normal; // normal faces the camera
};

std::vector<ViewPoint> viewPoints(const EmbreeScene& embree, const scene::Camera& camera, int gridW, int gridH) {
    // The camera in Embree's frame (EmbreeScene.h), where the hits are.
    scene::Camera framed = camera;
    framed.position = embree.toFrame(camera.position);
    framed.target = embree.toFrame(camera.target);
    const CameraRays rays(framed, float(gridW) / float(gridH));
    std::vector<ViewPoint> out;
    for (int y = 0; y < gridH; ++y)
        for (int x = 0; x < gridW; ++x) {
            const float nx = 2.0f * (float(x) + 0.5f) / float(gridW) - 1.0f;
            const float ny = 1.0f - 2.0f * (float(y) + 0.5f) / float(gridH);
            // A degenerate camera (issue #42: up along the view) sees nothing, not NaN.
            const auto ray = rays.through(nx, ny);
            if (!ray)
                continue;
            if (const auto hit = embree.intersect(ray->origin, ray->direction, 0.0f, ray->length))
                out.push_back({hit->position, hit->geometricNormal});
        }
    return out;
}

SunChoice share(const EmbreeScene& embree, const std::vector<ViewPoint>& points, const glm::vec3& direction) {
    SunChoice c;
    c.direction = glm::normalize(direction);
    const glm::vec3 toSun = -c.direction;
    c.elevationDegrees = std::asin(std::clamp(toSun.y, -1.0f, 1.0f)) * kDegrees;
    c.azimuthDegrees = std::atan2(toSun.x, toSun.z) * kDegrees;
    c.viewHits = int(points.size());
    int lit = 0;
    for (const ViewPoint& p : points) {
        if (glm::dot(p.normal, toSun) <= 0.0f)
            continue;
        const glm::vec3 origin = embree.offsetOrigin(p.position, p.normal);
        lit += embree.occluded(origin, toSun, 0.0f, std::numeric_limits<float>::infinity()) ? 0 : 1;
    }
    c.litFraction = points.empty() ? 0.0f : float(lit) / float(points.size());
    return c;
}

} // namespace

SunChoice sunlitShare(const EmbreeScene& embree, const scene::Camera& camera, const glm::vec3& direction, int gridW,
                      int gridH) {
    return share(embree, viewPoints(embree, camera, gridW, gridH), direction);
}

SunChoice chooseSunDirection(const EmbreeScene& embree, const scene::Camera& camera, const glm::vec3& fallback) {
    const std::vector<ViewPoint> points = viewPoints(embree, camera, 48, 27);
    SunChoice best = share(embree, points, fallback);
    for (const float elevation : {20.0f, 35.0f, 50.0f, 65.0f})
        for (int k = 0; k < 8; ++k) {
            const float az = float(k) * 45.0f / kDegrees, el = elevation / kDegrees;
            const glm::vec3 toSun(std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az));
            const SunChoice c = share(embree, points, -toSun);
            if (c.litFraction > best.litFraction + 1e-6f)
                best = c;
        }
    return best;
}

} // namespace lpv::reference
