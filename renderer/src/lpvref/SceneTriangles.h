#pragma once
// The scene's triangles in world space, as the CPU samplers of the LPV read
// them (emissive VPLs, the scene's geometry volume): every visible object's
// mesh, each triangle facing the side its shading normals point to (the
// winding may disagree), and the regular m^2 subdivision both cut them into.
#include "lpv/scene/Scene.h"
#include "lpv/scene/WorldMatrices.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace lpv::renderer::lpvref::detail {

struct WorldTriangle {
    glm::vec3 a, b, c;
    glm::vec3 normal;          // unit, toward the side the shading normals face
    float area;                // square world units, > 0
    std::uint32_t material;    // the submesh's material index (may be out of range)
};

// Calls `visit(const WorldTriangle&)` for each triangle of positive area of
// object `o` (visible or not) placed by `world`, until it returns false
// (then returns false). `wantsMaterial(index)` skips whole submeshes before their
// triangles are transformed.
template <class WantsMaterial, class Visit>
bool forEachObjectTriangle(const scene::Scene& scene, int o, const glm::mat4& world, WantsMaterial&& wantsMaterial,
                           Visit&& visit) {
    const scene::Object& object = scene.objects[std::size_t(o)];
    if (object.mesh < 0 || std::size_t(object.mesh) >= scene.meshes.size())
        return true;
    const scene::Mesh& mesh = scene.meshes[std::size_t(object.mesh)];
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(world)));
    const bool hasNormals = mesh.normals.size() == mesh.positions.size();
    for (const scene::Submesh& sub : mesh.submeshes) {
        if (!wantsMaterial(sub.materialIndex))
            continue;
        const std::size_t end = std::min<std::size_t>(std::size_t(sub.firstIndex) + sub.indexCount, mesh.indices.size());
        for (std::size_t t = sub.firstIndex; t + 2 < end; t += 3) {
            const std::uint32_t i[3] = {mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]};
            if (i[0] >= mesh.positions.size() || i[1] >= mesh.positions.size() || i[2] >= mesh.positions.size())
                continue;
            const glm::vec3 a(world * glm::vec4(mesh.positions[i[0]], 1.0f));
            const glm::vec3 b(world * glm::vec4(mesh.positions[i[1]], 1.0f));
            const glm::vec3 c(world * glm::vec4(mesh.positions[i[2]], 1.0f));
            const glm::vec3 cross = glm::cross(b - a, c - a);
            const float length = glm::length(cross);
            if (!(length > 0.0f) || !std::isfinite(length))
                continue; // degenerate or non-finite: no area
            glm::vec3 n = cross / length;
            if (hasNormals) {
                const glm::vec3 shading = normalMatrix * (mesh.normals[i[0]] + mesh.normals[i[1]] + mesh.normals[i[2]]);
                if (glm::dot(shading, n) < 0.0f)
                    n = -n;
            }
            if (!visit(WorldTriangle{a, b, c, n, 0.5f * length, sub.materialIndex}))
                return false;
        }
    }
    return true;
}

// The same for every visible object of the scene, until `visit` returns false.
template <class WantsMaterial, class Visit>
void forEachWorldTriangle(const scene::Scene& scene, WantsMaterial&& wantsMaterial, Visit&& visit) {
    const std::vector<glm::mat4> worlds = scene::worldMatrices(scene); // linear in any parent chain
    for (int o = 0; o < int(scene.objects.size()); ++o)
        if (scene.objects[std::size_t(o)].visible &&
            !forEachObjectTriangle(scene, o, worlds[std::size_t(o)], wantsMaterial, visit))
            return;
}

// The centroids of the m^2 equal sub-triangles of a regular subdivision, as
// barycentric steps (u, v) along (b - a) / m and (c - a) / m: m (m + 1) / 2
// upright, m (m - 1) / 2 upside down.
template <class Visit>
void forEachSubTriangleCentroid(int m, Visit&& visit) {
    for (int i = 0; i < m; ++i)
        for (int j = 0; i + j < m; ++j) {
            visit(float(i) + 1.0f / 3.0f, float(j) + 1.0f / 3.0f);
            if (i + j < m - 1)
                visit(float(i) + 2.0f / 3.0f, float(j) + 2.0f / 3.0f);
        }
}

} // namespace lpv::renderer::lpvref::detail
