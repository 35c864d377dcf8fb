#include "passes/direct/ShadowCascades.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace lpv::renderer {

std::vector<float> cascadeSplits(int count, float near, float far, float lambda) {
    count = std::max(count, 1);
    // The log spacing needs near > 0: a float guard relative to far (the
    // camera's planes scale with the scene), not the 0.1 mm it was, which
    // cut into a centimetre scene's view.
    if (far > 0.0f && std::isfinite(far))
        near = std::max(near, far * 1e-7f);
    near = std::max(near, std::numeric_limits<float>::min());
    far = std::max(far, near * 1.001f);
    std::vector<float> splits(std::size_t(count) + 1);
    for (int i = 0; i <= count; ++i) {
        const float t = float(i) / float(count);
        const float logSplit = near * std::pow(far / near, t);
        const float uniformSplit = near + (far - near) * t;
        splits[std::size_t(i)] = lambda * logSplit + (1.0f - lambda) * uniformSplit;
    }
    splits.front() = near; // exact ends despite rounding
    splits.back() = far;
    return splits;
}

glm::mat4 lightRotation(const glm::vec3& lightDir) {
    const glm::vec3 d = glm::normalize(lightDir);
    const glm::vec3 up = std::abs(d.y) > 0.99f ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
    return glm::lookAt(glm::vec3(0.0f), d, up);
}

namespace {

template <class F>
void forEachCorner(const scene::Bounds& b, F&& f) {
    for (int corner = 0; corner < 8; ++corner)
        f(glm::vec3{corner & 1 ? b.max.x : b.min.x, corner & 2 ? b.max.y : b.min.y, corner & 4 ? b.max.z : b.min.z});
}

// Light-space depth (distance along the light) that the scene spans, with a margin.
glm::vec2 sceneDepthRange(const glm::mat4& lightView, const scene::Bounds& bounds, const glm::vec2& fallback) {
    if (bounds.empty())
        return fallback;
    float lo = std::numeric_limits<float>::max(), hi = std::numeric_limits<float>::lowest();
    forEachCorner(bounds, [&](const glm::vec3& p) {
        const float depth = -(lightView * glm::vec4(p, 1.0f)).z;
        lo = std::min(lo, depth);
        hi = std::max(hi, depth);
    });
    // 1% of the depth span; a scene flat across the light (a floor under a
    // zenith sun) gets a thousandth of its size instead: no millimetre floor.
    const float margin = std::max(0.01f * (hi - lo), 1e-3f * glm::length(bounds.size()));
    if (!(margin > 0.0f)) // a scene of one point: nothing to scale with
        return {lo - 1.0f, hi + 1.0f};
    return {lo - margin, hi + margin};
}

// The splits follow the scene's far corner, which moves with the camera; a
// radius rounded up to 1/16 of its power of two keeps the texel size (and so
// the texel grid) fixed under small moves, at most 6.25% larger.
// The power of two is taken of r relative to `unit` (the scene's largest
// side), so the same scene in another unit quantises the same way: in
// absolute powers of two a scene scaled by 0.01 got other texel sizes
// relative to its walls, and Sibenik's sunlit slivers 6% more direct light
// at 0.01x and 25% at 1000x (issue #41, LpvFitHardCasesGLTest).
float quantizeRadius(float r, float unit) {
    if (!(r > 0.0f))
        return r;
    if (!(unit > 0.0f) || !std::isfinite(unit))
        unit = 1.0f;
    const float step = unit * std::exp2(std::floor(std::log2(r / unit))) / 16.0f;
    return std::ceil(r / step) * step;
}

} // namespace

float cascadeFarDistance(const CascadeCamera& camera, const scene::Bounds& bounds) {
    if (bounds.empty())
        return camera.farPlane;
    float farthest = 0.0f;
    forEachCorner(bounds, [&](const glm::vec3& p) { farthest = std::max(farthest, glm::length(p - camera.position)); });
    return std::clamp(farthest, camera.nearPlane * 1.01f, camera.farPlane);
}

std::vector<ShadowCascade> buildCascades(const CascadeCamera& camera, const glm::vec3& lightDir,
                                         const scene::Bounds& bounds, const CascadeSettings& settings) {
    const std::vector<float> splits =
        cascadeSplits(settings.count, camera.nearPlane, cascadeFarDistance(camera, bounds), settings.lambda);
    const glm::mat4 lightView = lightRotation(lightDir);
    const float mapSize = float(std::max(settings.mapSize, 1));
    // Half-diagonal of the view frustum per unit distance.
    const float tanY = std::tan(0.5f * camera.fovY);
    const float k2 = tanY * tanY * (1.0f + camera.aspect * camera.aspect);
    const glm::vec3 forward = glm::normalize(camera.forward);

    std::vector<ShadowCascade> cascades;
    for (std::size_t i = 0; i + 1 < splits.size(); ++i) {
        ShadowCascade c;
        c.splitNear = splits[i];
        c.splitFar = splits[i + 1];
        // Smallest sphere through the slice's near and far corners: its centre
        // lies on the view axis, where both are equally far (or at the far
        // plane's centre for wide, short slices).
        const float n = c.splitNear, f = c.splitFar;
        const float along = std::min(0.5f * (n + f) * (1.0f + k2), f);
        c.radius = std::sqrt((f - along) * (f - along) + f * f * k2);
        c.sphereRadius = c.radius;
        if (settings.stabilize)
            // Two texels (2 r / mapSize each) of room before rounding: the
            // centre's snapping moves the square by up to one, and the square
            // must still hold its own slice (cascadeCovers).
            c.radius = quantizeRadius(c.radius * (1.0f + 4.0f / mapSize),
                                      bounds.empty() ? 1.0f
                                                     : std::max({bounds.size().x, bounds.size().y, bounds.size().z}));
        c.center = camera.position + forward * along;
        c.texelWorld = 2.0f * c.radius / mapSize;

        glm::vec2 centerLs = glm::vec2(lightView * glm::vec4(c.center, 1.0f));
        if (settings.stabilize) {
            // Whole texels only: the projected texel grid then stays fixed in
            // the world while the camera moves, so edges do not shimmer. The
            // radius is a whole number of texels too (mapSize / 2).
            centerLs = glm::floor(centerLs / c.texelWorld) * c.texelWorld;
        }
        c.lightCenter = centerLs;
        const glm::vec2 depth = sceneDepthRange(lightView, bounds, {-c.radius, c.radius});
        c.depthNear = depth.x;
        c.depthFar = depth.y;
        c.depthRange = depth.y - depth.x;
        const glm::mat4 projection = glm::ortho(centerLs.x - c.radius, centerLs.x + c.radius, centerLs.y - c.radius,
                                                centerLs.y + c.radius, depth.x, depth.y);
        c.viewProj = projection * lightView;
        cascades.push_back(c);
    }
    return cascades;
}

bool cascadeCovers(const ShadowCascade& drawn, const ShadowCascade& wanted, const glm::vec3& lightDir) {
    const glm::vec2 center = glm::vec2(lightRotation(lightDir) * glm::vec4(wanted.center, 1.0f));
    const glm::vec2 offset = glm::abs(center - drawn.lightCenter);
    return std::max(offset.x, offset.y) + wanted.sphereRadius <= drawn.radius;
}

glm::mat4 cascadeUnionViewProj(const std::vector<ShadowCascade>& cascades, const glm::vec3& lightDir,
                               const scene::Bounds& bounds) {
    const glm::mat4 lightView = lightRotation(lightDir);
    if (cascades.empty())
        return lightView;
    glm::vec2 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
    for (const ShadowCascade& c : cascades) {
        lo = glm::min(lo, c.lightCenter - glm::vec2(c.radius));
        hi = glm::max(hi, c.lightCenter + glm::vec2(c.radius));
    }
    const glm::vec2 depth = sceneDepthRange(lightView, bounds, {cascades[0].depthNear, cascades[0].depthFar});
    return glm::ortho(lo.x, hi.x, lo.y, hi.y, depth.x, depth.y) * lightView;
}

} // namespace lpv::renderer
