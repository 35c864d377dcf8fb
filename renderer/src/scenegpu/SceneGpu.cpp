#include "lpv/renderer/SceneGpu.h"
#include "lpv/scene/WorldMatrices.h"

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>

namespace lpv::renderer {
namespace {

// Interleaved layout shared by every pass: position, normal, tangent, uv.
struct Vertex {
    glm::vec3 position;
    glm::vec3 normal;
    glm::vec4 tangent;
    glm::vec2 uv;
};

scene::Bounds transformBounds(const scene::Bounds& b, const glm::mat4& m) {
    scene::Bounds out;
    if (b.empty())
        return out;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p{corner & 1 ? b.max.x : b.min.x, corner & 2 ? b.max.y : b.min.y,
                          corner & 4 ? b.max.z : b.min.z};
        out.extend(glm::vec3(m * glm::vec4(p, 1.0f)));
    }
    return out;
}

// Bounds of the vertices one submesh's triangles use.
scene::Bounds submeshBounds(const scene::Mesh& mesh, const scene::Submesh& sub) {
    scene::Bounds b;
    const std::size_t end = std::min<std::size_t>(std::size_t(sub.firstIndex) + sub.indexCount, mesh.indices.size());
    for (std::size_t i = sub.firstIndex; i < end; ++i)
        if (mesh.indices[i] < mesh.positions.size())
            b.extend(mesh.positions[mesh.indices[i]]);
    return b;
}

} // namespace

DrawBucket bucketOf(const scene::Material& m) {
    if (m.alphaMode == scene::AlphaMode::Blend || m.additive)
        return DrawBucket::Blended;
    if (m.alphaMode == scene::AlphaMode::Mask || m.colorKey || !m.alphaTexture.empty())
        return DrawBucket::Masked;
    return DrawBucket::Opaque;
}

SceneGpu::SceneGpu(const scene::Scene& scene) {
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices;
    for (const scene::Mesh& mesh : scene.meshes) {
        ranges_.push_back({GLint(vertices.size()), indices.size()});
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

    updateDraws(scene);

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

void SceneGpu::updateDraws(const scene::Scene& scene) {
    draws_.clear();
    const std::vector<glm::mat4> worlds = scene::worldMatrices(scene); // linear in any parent chain
    for (std::size_t o = 0; o < scene.objects.size(); ++o) {
        const scene::Object& obj = scene.objects[o];
        if (!obj.visible || obj.mesh < 0 || std::size_t(obj.mesh) >= ranges_.size() ||
            std::size_t(obj.mesh) >= scene.meshes.size())
            continue;
        const glm::mat4 model = worlds[o];
        const glm::mat3 normalMatrix = glm::inverseTranspose(glm::mat3(model));
        const MeshRange& r = ranges_[std::size_t(obj.mesh)];
        const scene::Mesh& mesh = scene.meshes[std::size_t(obj.mesh)];
        for (const scene::Submesh& sub : mesh.submeshes) {
            const scene::Material material =
                sub.materialIndex < scene.materials.size() ? scene.materials[sub.materialIndex] : scene::Material{};
            draws_.push_back(DrawItem{model, normalMatrix, GLsizei(sub.indexCount),
                                      (r.firstIndex + sub.firstIndex) * sizeof(std::uint32_t), r.baseVertex,
                                      sub.materialIndex, transformBounds(submeshBounds(mesh, sub), model),
                                      bucketOf(material)});
        }
    }
}

void SceneGpu::bindGeometry() const { glBindVertexArray(vao_.id()); }

void SceneGpu::draw(GLuint program, const std::vector<const DrawItem*>& items,
                    const std::function<void(std::uint32_t material)>& bindMaterial) const {
    bindGeometry();
    const GLint model = glGetUniformLocation(program, "uModel");
    const GLint normalMatrix = glGetUniformLocation(program, "uNormalMatrix");
    std::int64_t boundMaterial = -1;
    for (const DrawItem* d : items) {
        glProgramUniformMatrix4fv(program, model, 1, GL_FALSE, glm::value_ptr(d->model));
        if (normalMatrix >= 0)
            glProgramUniformMatrix3fv(program, normalMatrix, 1, GL_FALSE, glm::value_ptr(d->normalMatrix));
        if (bindMaterial && std::int64_t(d->material) != boundMaterial) {
            bindMaterial(d->material);
            boundMaterial = d->material;
        }
        glDrawElementsBaseVertex(GL_TRIANGLES, d->indexCount, GL_UNSIGNED_INT,
                                 reinterpret_cast<const void*>(d->indexByteOffset), d->baseVertex);
    }
}

} // namespace lpv::renderer
