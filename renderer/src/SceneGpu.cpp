#include "lpv/renderer/SceneGpu.h"

#include <glm/gtc/matrix_inverse.hpp>

namespace lpv::renderer {
namespace {

// Interleaved layout shared by every pass: position, normal, tangent, uv.
struct Vertex {
    glm::vec3 position;
    glm::vec3 normal;
    glm::vec4 tangent;
    glm::vec2 uv;
};

} // namespace

SceneGpu::SceneGpu(const scene::Scene& scene) {
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices;
    struct MeshRange {
        GLint baseVertex;
        std::size_t firstIndex;
    };
    std::vector<MeshRange> ranges;
    for (const scene::Mesh& mesh : scene.meshes) {
        ranges.push_back({GLint(vertices.size()), indices.size()});
        scene::Mesh withNormals;
        const scene::Mesh* src = &mesh;
        if (mesh.normals.size() != mesh.positions.size()) {
            withNormals = mesh;
            scene::computeFlatAwareNormals(withNormals);
            src = &withNormals;
        }
        for (std::size_t i = 0; i < src->positions.size(); ++i) {
            Vertex v{};
            v.position = src->positions[i];
            v.normal = src->normals[i];
            v.tangent = i < src->tangents.size() ? src->tangents[i] : glm::vec4(0.0f);
            v.uv = i < src->uvs.size() ? src->uvs[i] : glm::vec2(0.0f);
            vertices.push_back(v);
        }
        indices.insert(indices.end(), mesh.indices.begin(), mesh.indices.end());
    }

    for (std::size_t o = 0; o < scene.objects.size(); ++o) {
        const scene::Object& obj = scene.objects[o];
        if (!obj.visible || obj.mesh < 0 || std::size_t(obj.mesh) >= scene.meshes.size())
            continue;
        const glm::mat4 model = scene.worldMatrix(int(o));
        const glm::mat3 normalMatrix = glm::inverseTranspose(glm::mat3(model));
        const MeshRange& r = ranges[std::size_t(obj.mesh)];
        for (const scene::Submesh& sub : scene.meshes[std::size_t(obj.mesh)].submeshes)
            draws_.push_back(DrawItem{model, normalMatrix, GLsizei(sub.indexCount),
                                      (r.firstIndex + sub.firstIndex) * sizeof(std::uint32_t), r.baseVertex,
                                      sub.materialIndex});
    }

    vao_ = createVertexArray();
    vertices_ = createBuffer();
    indices_ = createBuffer();
    vertexBytes_ = vertices.size() * sizeof(Vertex);
    // Empty scenes still get valid (1-byte) buffers so binding never fails.
    glNamedBufferStorage(vertices_.id(), GLsizeiptr(std::max<std::size_t>(vertexBytes_, 1)),
                         vertices.empty() ? nullptr : vertices.data(), 0);
    glNamedBufferStorage(indices_.id(), GLsizeiptr(std::max<std::size_t>(indices.size() * 4, 1)),
                         indices.empty() ? nullptr : indices.data(), 0);
    glVertexArrayVertexBuffer(vao_.id(), 0, vertices_.id(), 0, sizeof(Vertex));
    glVertexArrayElementBuffer(vao_.id(), indices_.id());
    const GLuint offsets[] = {offsetof(Vertex, position), offsetof(Vertex, normal), offsetof(Vertex, tangent),
                              offsetof(Vertex, uv)};
    const GLint sizes[] = {3, 3, 4, 2};
    for (GLuint a = 0; a < 4; ++a) {
        glEnableVertexArrayAttrib(vao_.id(), a);
        glVertexArrayAttribFormat(vao_.id(), a, sizes[a], GL_FLOAT, GL_FALSE, offsets[a]);
        glVertexArrayAttribBinding(vao_.id(), a, 0);
    }
}

void SceneGpu::bindGeometry() const { glBindVertexArray(vao_.id()); }

} // namespace lpv::renderer
