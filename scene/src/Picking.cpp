#include "lpv/scene/Picking.h"
#include "lpv/scene/WorldMatrices.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <limits>

namespace lpv::scene {
namespace {

Bounds transformed(const Bounds& b, const glm::mat4& m) {
    Bounds out;
    if (b.empty())
        return out;
    for (int corner = 0; corner < 8; ++corner)
        out.extend(glm::vec3(m * glm::vec4(corner & 1 ? b.max.x : b.min.x, corner & 2 ? b.max.y : b.min.y,
                                           corner & 4 ? b.max.z : b.min.z, 1.0f)));
    return out;
}

// Slab test; the entry distance, or nothing when the ray misses the box.
std::optional<float> rayBox(const glm::vec3& o, const glm::vec3& d, const Bounds& b) {
    float tNear = 0.0f, tFar = std::numeric_limits<float>::max();
    for (int a = 0; a < 3; ++a) {
        if (std::abs(d[a]) < 1e-12f) {
            if (o[a] < b.min[a] || o[a] > b.max[a])
                return std::nullopt;
            continue;
        }
        float t0 = (b.min[a] - o[a]) / d[a], t1 = (b.max[a] - o[a]) / d[a];
        if (t0 > t1)
            std::swap(t0, t1);
        tNear = std::max(tNear, t0);
        tFar = std::min(tFar, t1);
        if (tNear > tFar)
            return std::nullopt;
    }
    return tNear;
}

// Möller–Trumbore, both faces; distance along d or nothing.
std::optional<float> rayTriangle(const glm::vec3& o, const glm::vec3& d, const glm::vec3& a, const glm::vec3& b,
                                 const glm::vec3& c) {
    const glm::vec3 e1 = b - a, e2 = c - a, p = glm::cross(d, e2);
    const float det = glm::dot(e1, p);
    // Parallel up to rounding, relative to the edges and the direction (det
    // is their product), so a 0.1 mm triangle is picked like a 10 m one.
    if (!(std::abs(det) > 1e-7f * glm::length(e1) * glm::length(e2) * glm::length(d)))
        return std::nullopt;
    const float inv = 1.0f / det;
    const glm::vec3 s = o - a;
    const float u = glm::dot(s, p) * inv;
    if (u < 0.0f || u > 1.0f)
        return std::nullopt;
    const glm::vec3 q = glm::cross(s, e1);
    const float v = glm::dot(d, q) * inv;
    if (v < 0.0f || u + v > 1.0f)
        return std::nullopt;
    const float t = glm::dot(e2, q) * inv;
    return t > 0.0f ? std::optional<float>(t) : std::nullopt;
}

} // namespace

Bounds objectWorldBounds(const Scene& scene, int object) {
    const Object& obj = scene.objects.at(std::size_t(object));
    if (obj.mesh < 0 || std::size_t(obj.mesh) >= scene.meshes.size())
        return {};
    return transformed(scene.meshes[std::size_t(obj.mesh)].computeBounds(), scene.worldMatrix(object));
}

std::optional<PickHit> pickObject(const Scene& scene, const glm::vec3& origin, const glm::vec3& direction) {
    const glm::vec3 dir = glm::normalize(direction);
    std::optional<PickHit> best;
    const std::vector<glm::mat4> worlds = worldMatrices(scene);
    for (std::size_t o = 0; o < scene.objects.size(); ++o) {
        const Object& obj = scene.objects[o];
        if (!obj.visible || obj.mesh < 0 || std::size_t(obj.mesh) >= scene.meshes.size())
            continue;
        const Mesh& mesh = scene.meshes[std::size_t(obj.mesh)];
        const glm::mat4& world = worlds[o];
        const auto boxHit = rayBox(origin, dir, transformed(mesh.computeBounds(), world));
        if (!boxHit || (best && *boxHit > best->distance))
            continue;
        // Intersect in object space: one inverse per object instead of transforming every vertex.
        const glm::mat4 inv = glm::inverse(world);
        const glm::vec3 o2 = glm::vec3(inv * glm::vec4(origin, 1.0f));
        const glm::vec3 d2 = glm::vec3(inv * glm::vec4(dir, 0.0f));
        for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
            const auto t = rayTriangle(o2, d2, mesh.positions[mesh.indices[i]], mesh.positions[mesh.indices[i + 1]],
                                       mesh.positions[mesh.indices[i + 2]]);
            if (!t)
                continue;
            const glm::vec3 hitWorld = glm::vec3(world * glm::vec4(o2 + *t * d2, 1.0f));
            const float distance = glm::length(hitWorld - origin);
            if (!best || distance < best->distance)
                best = PickHit{int(o), distance, hitWorld};
        }
    }
    return best;
}

Ray cameraRay(const Camera& camera, float x, float y, int width, int height) {
    const float aspect = float(width) / float(height);
    const glm::mat4 inv = glm::inverse(camera.projection(aspect) * camera.view());
    const float ndcX = 2.0f * x / float(width) - 1.0f, ndcY = 1.0f - 2.0f * y / float(height);
    glm::vec4 nearP = inv * glm::vec4(ndcX, ndcY, -1.0f, 1.0f), farP = inv * glm::vec4(ndcX, ndcY, 1.0f, 1.0f);
    const glm::vec3 n = glm::vec3(nearP) / nearP.w, f = glm::vec3(farP) / farP.w;
    return {camera.position, glm::normalize(f - n)};
}

} // namespace lpv::scene
