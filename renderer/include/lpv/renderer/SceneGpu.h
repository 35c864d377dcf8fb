#pragma once
// GPU copy of a scene's geometry: one vertex and one index buffer for all
// meshes, and a flat draw list (object x submesh) with world matrices and
// world bounds for culling.
#include "lpv/renderer/DrawList.h"
#include "lpv/renderer/GlHandle.h"
#include "lpv/scene/Scene.h"

#include <functional>
#include <vector>

namespace lpv::renderer {

struct DrawItem {
    glm::mat4 model{1.0f};
    glm::mat3 normalMatrix{1.0f};
    GLsizei indexCount = 0;
    std::size_t indexByteOffset = 0;
    GLint baseVertex = 0;
    std::uint32_t material = 0;
    scene::Bounds worldBounds;
    DrawBucket bucket = DrawBucket::Opaque;
};

// Which bucket a material draws in (opaque, alpha mask or blend/additive).
DrawBucket bucketOf(const scene::Material& material);

class SceneGpu {
public:
    explicit SceneGpu(const scene::Scene& scene);

    // Rebuilds the draw list (world matrices, bounds, visibility, buckets)
    // for a scene whose meshes are unchanged: an object moved, hid or
    // changed material, no vertex re-upload.
    void updateDraws(const scene::Scene& scene);

    void bindGeometry() const;
    // Draws `items` with `program` (sets uModel and uNormalMatrix per item);
    // `bindMaterial` runs whenever the material changes from one item to the next.
    void draw(GLuint program, const std::vector<const DrawItem*>& items,
              const std::function<void(std::uint32_t material)>& bindMaterial) const;
    const std::vector<DrawItem>& draws() const { return draws_; }
    std::size_t vertexBytes() const { return vertexBytes_; }

private:
    struct MeshRange {
        GLint baseVertex;
        std::size_t firstIndex;
    };
    std::vector<MeshRange> ranges_; // per scene mesh, into the shared buffers
    VertexArray vao_;
    Buffer vertices_;
    Buffer indices_;
    std::vector<DrawItem> draws_;
    std::size_t vertexBytes_ = 0;
};

} // namespace lpv::renderer
