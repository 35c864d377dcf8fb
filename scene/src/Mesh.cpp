#include "lpv/scene/Mesh.h"

#include <cmath>

namespace lpv::scene {

Bounds Mesh::computeBounds() const {
    Bounds b;
    // A NaN or infinite position (an importer that let one through) would
    // make the bounds NaN and with them the sun's shadow and RSM frusta, so
    // that no indirect light is left anywhere (docs/hard-cases.md).
    for (const glm::vec3& p : positions)
        if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z))
            b.extend(p);
    return b;
}

void computeFlatAwareNormals(Mesh& mesh) {
    mesh.normals.assign(mesh.positions.size(), glm::vec3(0.0f));
    for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
        const std::uint32_t a = mesh.indices[i], b = mesh.indices[i + 1], c = mesh.indices[i + 2];
        // The unnormalised cross product weights each face by its area.
        const glm::vec3 n = glm::cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);
        mesh.normals[a] += n;
        mesh.normals[b] += n;
        mesh.normals[c] += n;
    }
    for (glm::vec3& n : mesh.normals) {
        const float len = glm::length(n);
        n = len > 0.0f ? n / len : glm::vec3(0.0f, 1.0f, 0.0f);
    }
}

} // namespace lpv::scene
