#include "lpv/scene/Primitives.h"

#include <glm/gtc/constants.hpp>

namespace lpv::scene {
namespace {

void finish(Mesh& mesh) {
    mesh.submeshes = {Submesh{0, std::uint32_t(mesh.indices.size()), 0}};
}

// One grid of quads spanning origin + [0,1]·u + [0,1]·v, normal = cross(u, v) direction.
void addGrid(Mesh& mesh, glm::vec3 origin, glm::vec3 u, glm::vec3 v, int divisions) {
    const glm::vec3 normal = glm::normalize(glm::cross(u, v));
    const auto first = std::uint32_t(mesh.positions.size());
    const int n = divisions + 1;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const float s = float(i) / float(divisions), t = float(j) / float(divisions);
            mesh.positions.push_back(origin + s * u + t * v);
            mesh.normals.push_back(normal);
            mesh.tangents.emplace_back(glm::normalize(u), 1.0f);
            mesh.uvs.emplace_back(s, t);
        }
    for (int j = 0; j < divisions; ++j)
        for (int i = 0; i < divisions; ++i) {
            const std::uint32_t a = first + std::uint32_t(j * n + i), b = a + 1, c = a + std::uint32_t(n), d = c + 1;
            mesh.indices.insert(mesh.indices.end(), {a, b, d, a, d, c});
        }
}

} // namespace

Mesh makePlane(int divisions) {
    Mesh mesh;
    mesh.name = "plane";
    // u = +X, v = -Z: cross(+X, -Z) = +Y, counter-clockwise seen from above.
    addGrid(mesh, {-0.5f, 0.0f, 0.5f}, {1.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -1.0f}, std::max(divisions, 1));
    finish(mesh);
    return mesh;
}

Mesh makeBox() {
    Mesh mesh;
    mesh.name = "box";
    const glm::vec3 x{1.0f, 0.0f, 0.0f}, y{0.0f, 1.0f, 0.0f}, z{0.0f, 0.0f, 1.0f};
    addGrid(mesh, {-0.5f, -0.5f, 0.5f}, x, y, 1);   // +Z
    addGrid(mesh, {0.5f, -0.5f, -0.5f}, -x, y, 1);  // -Z
    addGrid(mesh, {0.5f, -0.5f, 0.5f}, -z, y, 1);   // +X
    addGrid(mesh, {-0.5f, -0.5f, -0.5f}, z, y, 1);  // -X
    addGrid(mesh, {-0.5f, 0.5f, 0.5f}, x, -z, 1);   // +Y
    addGrid(mesh, {-0.5f, -0.5f, -0.5f}, x, z, 1);  // -Y
    finish(mesh);
    return mesh;
}

Mesh makeSphere(int segments, int rings) {
    Mesh mesh;
    mesh.name = "sphere";
    segments = std::max(segments, 3);
    rings = std::max(rings, 2);
    for (int r = 0; r <= rings; ++r) {
        const float v = float(r) / float(rings);
        const float theta = v * glm::pi<float>(); // from the south pole up
        for (int s = 0; s <= segments; ++s) {
            const float u = float(s) / float(segments);
            const float phi = u * glm::two_pi<float>();
            const glm::vec3 n{-std::sin(theta) * std::sin(phi), -std::cos(theta), -std::sin(theta) * std::cos(phi)};
            mesh.positions.push_back(0.5f * n);
            mesh.normals.push_back(n);
            mesh.tangents.emplace_back(-std::cos(phi), 0.0f, std::sin(phi), 1.0f);
            mesh.uvs.emplace_back(u, v);
        }
    }
    const int row = segments + 1;
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            const std::uint32_t a = std::uint32_t(r * row + s), b = a + 1, c = a + std::uint32_t(row), d = c + 1;
            if (r != 0)
                mesh.indices.insert(mesh.indices.end(), {a, b, c});
            if (r != rings - 1)
                mesh.indices.insert(mesh.indices.end(), {b, d, c});
        }
    finish(mesh);
    return mesh;
}

} // namespace lpv::scene
