#include "lpv/scene/FramingCamera.h"
#include "lpv/scene/SceneScale.h"
#include "lpv/scene/WorldMatrices.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace lpv::scene {

namespace {

// Möller-Trumbore: the distance along the ray to the triangle, or a negative value for a miss.
float rayHitDistance(const glm::vec3& origin, const glm::vec3& dir, const glm::vec3& a, const glm::vec3& b,
                     const glm::vec3& c) {
    const glm::vec3 e1 = b - a, e2 = c - a;
    const glm::vec3 p = glm::cross(dir, e2);
    const float det = glm::dot(e1, p);
    // Parallel up to rounding, relative to the edges (det is a length squared
    // for a unit dir), so a 0.1 mm triangle is hit like a 10 m one.
    if (!(std::abs(det) > 1e-7f * glm::length(e1) * glm::length(e2)))
        return -1.0f;
    const float inv = 1.0f / det;
    const glm::vec3 s = origin - a;
    // Edges overlap by 1e-5 of the triangle (barycentric, unitless): a probe
    // on a seam (a symmetric nave's centre line) hits one of the two
    // triangles whatever the rounding at this scale, instead of slipping
    // through to the back of the wall behind (Sibenik read at 1000x).
    constexpr float kEdge = 1e-5f;
    const float u = glm::dot(s, p) * inv;
    if (u < -kEdge || u > 1.0f + kEdge)
        return -1.0f;
    const glm::vec3 q = glm::cross(s, e1);
    const float v = glm::dot(dir, q) * inv;
    if (v < -kEdge || u + v > 1.0f + kEdge)
        return -1.0f;
    return glm::dot(e2, q) * inv;
}

glm::vec3 probePoint(const Bounds& b) {
    return {b.center().x, b.min.y + 0.25f * b.size().y, b.center().z};
}

} // namespace

namespace {

// The four horizontal probe directions, then up.
const std::array<glm::vec3, 5> kProbeDirs{glm::vec3(1, 0, 0), glm::vec3(-1, 0, 0), glm::vec3(0, 0, 1),
                                          glm::vec3(0, 0, -1), glm::vec3(0, 1, 0)};

struct Probe {
    std::array<bool, 5> hit{};
    std::array<bool, 5> facing{}; // the nearest hit is a front face (seen from the probe)
};

Probe probe(const Scene& scene, const glm::vec3& origin) {
    // Per direction the nearest hit and whether it faces the probe: walls of
    // a room face inward, while from inside a closed object (a bunny) the
    // nearest surface is the back of its skin.
    std::array<float, 5> nearest;
    nearest.fill(std::numeric_limits<float>::max());
    Probe p;
    const std::vector<glm::mat4> worlds = worldMatrices(scene);
    for (std::size_t o = 0; o < scene.objects.size(); ++o) {
        const Object& obj = scene.objects[o];
        if (obj.mesh < 0 || std::size_t(obj.mesh) >= scene.meshes.size())
            continue;
        const Mesh& mesh = scene.meshes[std::size_t(obj.mesh)];
        const glm::mat4& m = worlds[o];
        for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
            if (mesh.indices[i] >= mesh.positions.size() || mesh.indices[i + 1] >= mesh.positions.size() ||
                mesh.indices[i + 2] >= mesh.positions.size())
                continue;
            const glm::vec3 a = glm::vec3(m * glm::vec4(mesh.positions[mesh.indices[i]], 1.0f));
            const glm::vec3 b = glm::vec3(m * glm::vec4(mesh.positions[mesh.indices[i + 1]], 1.0f));
            const glm::vec3 c = glm::vec3(m * glm::vec4(mesh.positions[mesh.indices[i + 2]], 1.0f));
            for (std::size_t d = 0; d < kProbeDirs.size(); ++d) {
                const float t = rayHitDistance(origin, kProbeDirs[d], a, b, c);
                if (t > 0.0f && t < nearest[d]) {
                    nearest[d] = t;
                    p.hit[d] = true;
                    p.facing[d] = glm::dot(glm::cross(b - a, c - a), kProbeDirs[d]) < 0.0f;
                }
            }
        }
    }
    return p;
}

// The centre probe and four more 30% of the way towards the sides: one
// probe between two blocks (the Cornell box) can be walled in by them.
std::array<glm::vec3, 5> probePoints(const Bounds& b) {
    const glm::vec3 c = probePoint(b), s = 0.3f * b.size();
    return {c, c + glm::vec3(s.x, 0, 0), c - glm::vec3(s.x, 0, 0), c + glm::vec3(0, 0, s.z), c - glm::vec3(0, 0, s.z)};
}

struct Enclosure {
    bool enclosed = false;
    std::array<int, 4> escapes{}; // per horizontal direction, probes whose ray hit nothing
};

Enclosure enclosure(const Scene& scene, const Bounds& b) {
    Enclosure e;
    int front = 0, hits = 0, escaped = 0;
    for (const glm::vec3& origin : probePoints(b)) {
        const Probe p = probe(scene, origin);
        for (std::size_t d = 0; d < 4; ++d) {
            if (!p.hit[d]) {
                ++e.escapes[d];
                ++escaped;
                continue;
            }
            ++hits;
            front += p.facing[d] ? 1 : 0;
        }
    }
    // Walls on all four sides from every probe (a roof is optional: Sponza's
    // atrium is open; one stray gap such as a door is forgiven), mostly seen
    // from the front.
    e.enclosed = escaped <= 1 && 2 * front > hits;
    return e;
}

} // namespace

bool isEnclosed(const Scene& scene) {
    const Bounds bounds = scene.worldBounds();
    return !bounds.empty() && enclosure(scene, bounds).enclosed;
}

namespace {

Camera framingCameraNearOrigin(const Scene& scene);

} // namespace

Camera framingCamera(const Scene& scene) {
    // A scene far from the origin relative to its size is framed near the
    // origin (its root objects and lights moved in double) and the camera
    // moved back: the probe rays of a 2 m box 1,000 km away, in float world
    // space, slipped through its walls and put the camera inside it (issue #41).
    const Bounds b = scene.worldBounds();
    if (b.empty())
        return framingCameraNearOrigin(scene);
    const glm::dvec3 centre = 0.5 * (glm::dvec3(b.min) + glm::dvec3(b.max));
    const double size = double(glm::length(b.size()));
    if (!(glm::length(centre) > 16.0 * std::max(size, 1e-30)))
        return framingCameraNearOrigin(scene);
    Scene local = scene;
    moveScene(local, -centre);
    Camera camera = framingCameraNearOrigin(local);
    camera.position = glm::vec3(glm::dvec3(camera.position) + centre);
    camera.target = glm::vec3(glm::dvec3(camera.target) + centre);
    return camera;
}

namespace {

Camera framingCameraNearOrigin(const Scene& scene) {
    Camera camera;
    camera.name = "framing";
    const Bounds b = scene.worldBounds();
    if (b.empty())
        return camera;
    const glm::vec3 size = b.size();
    // Planes below are fractions of the radius; the fallback is a float guard
    // for a scene of one point (nothing to scale with), not a length.
    const float diagonal = 0.5f * glm::length(size);
    const float radius = diagonal > 0.0f && std::isfinite(diagonal) ? diagonal : 1.0f;
    const Enclosure e = enclosure(scene, b);
    if (e.enclosed) {
        // Stand 12% in from one end of the longest horizontal axis, at a
        // fifth of the height, and look to the other end, slightly upward.
        const bool alongX = size.x >= size.z;
        const glm::vec3 axis = alongX ? glm::vec3(1, 0, 0) : glm::vec3(0, 0, 1);
        const float length = alongX ? size.x : size.z;
        glm::vec3 eye = probePoint(b);
        eye.y = b.min.y + 0.2f * size.y;
        eye -= axis * (0.38f * length);
        camera.position = eye;
        camera.target = eye + axis * length + glm::vec3(0.0f, 0.15f * size.y, 0.0f);
        camera.fovY = glm::radians(60.0f);
        camera.nearPlane = radius * 1e-3f;
        camera.farPlane = radius * 4.0f;
    } else {
        // From outside, on the side most probes see out of when that side
        // is clearly the open one (the Cornell box), else from +Z.
        glm::vec3 side(0.0f, 0.0f, 1.0f);
        const auto most = std::max_element(e.escapes.begin(), e.escapes.end());
        if (std::count(e.escapes.begin(), e.escapes.end(), *most) == 1 && *most >= 3)
            side = kProbeDirs[std::size_t(most - e.escapes.begin())];
        const glm::vec3 c = b.center();
        camera.position = c + side * (2.5f * radius);
        camera.target = c;
        camera.nearPlane = 0.01f * radius;
        camera.farPlane = 10.0f * radius;
    }
    return camera;
}

} // namespace

void fitClipPlanes(Camera& camera, const Bounds& bounds) {
    if (bounds.empty())
        return;
    const glm::dvec3 eye(camera.position), lo(bounds.min), hi(bounds.max);
    double farthest = 0.0;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec3 p{corner & 1 ? hi.x : lo.x, corner & 2 ? hi.y : lo.y, corner & 4 ? hi.z : lo.z};
        farthest = std::max(farthest, glm::length(p - eye));
    }
    const double nearest = glm::length(glm::max(glm::max(lo - eye, eye - hi), glm::dvec3(0.0)));
    const double far = farthest * 1.01;
    if (!(far > 0.0) || !std::isfinite(far))
        return; // the eye on a bounds of one point: nothing to scale with
    // Far / near stays well inside the depth buffer's 1.6e7 (ValueChecks.h).
    const double near = std::max(nearest > 0.0 ? 0.5 * nearest : 0.0, far * 1e-4);
    camera.nearPlane = float(near);
    camera.farPlane = float(far);
}

} // namespace lpv::scene
