#include "passes/radiosity/PatchVertices.h"

#include <algorithm>
#include <cstddef>

namespace lpv::renderer {

namespace {

PatchVertex corner(const radiosity::Patch& p, std::span<const glm::vec3> values, std::size_t patch, int k) {
    return {p.corners[std::size_t(k)], values[4 * patch + std::size_t(k)], p.normal};
}

} // namespace

std::vector<PatchVertex> patchTriangles(const radiosity::PatchMesh& mesh,
                                        std::span<const glm::vec3> cornerValues,
                                        const std::function<bool(const radiosity::Patch&)>& keep) {
    std::vector<PatchVertex> out;
    out.reserve(mesh.size() * 6);
    for (std::size_t i = 0; i < mesh.size(); ++i) {
        const radiosity::Patch& p = mesh.patches[i];
        if (keep && !keep(p))
            continue;
        for (int k : {0, 1, 2})
            out.push_back(corner(p, cornerValues, i, k));
        if (p.cornerCount == 4)
            for (int k : {0, 2, 3})
                out.push_back(corner(p, cornerValues, i, k));
    }
    return out;
}

std::vector<PatchVertex> patchOutlines(const radiosity::PatchMesh& mesh,
                                       std::span<const glm::vec3> cornerValues) {
    std::vector<PatchVertex> out;
    out.reserve(mesh.size() * 8);
    for (std::size_t i = 0; i < mesh.size(); ++i) {
        const radiosity::Patch& p = mesh.patches[i];
        for (int k = 0; k < p.cornerCount; ++k) {
            out.push_back(corner(p, cornerValues, i, k));
            out.push_back(corner(p, cornerValues, i, (k + 1) % p.cornerCount));
        }
    }
    return out;
}

PatchDraw uploadPatchVertices(const std::vector<PatchVertex>& vertices) {
    PatchDraw draw;
    draw.buffer = createBuffer();
    glNamedBufferStorage(draw.buffer.id(),
                         GLsizeiptr(std::max<std::size_t>(vertices.size(), 1) * sizeof(PatchVertex)),
                         vertices.empty() ? nullptr : vertices.data(), 0);
    draw.vao = createVertexArray();
    const GLuint vao = draw.vao.id();
    glVertexArrayVertexBuffer(vao, 0, draw.buffer.id(), 0, sizeof(PatchVertex));
    const GLuint offsets[] = {offsetof(PatchVertex, position), offsetof(PatchVertex, value),
                              offsetof(PatchVertex, normal)};
    for (GLuint a = 0; a < 3; ++a) {
        glEnableVertexArrayAttrib(vao, a);
        glVertexArrayAttribFormat(vao, a, 3, GL_FLOAT, GL_FALSE, offsets[a]);
        glVertexArrayAttribBinding(vao, a, 0);
    }
    draw.vertices = GLsizei(vertices.size());
    return draw;
}

} // namespace lpv::renderer
