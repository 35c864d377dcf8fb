#pragma once
#include <glm/glm.hpp>

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace lpv::scene {

struct Bounds {
    glm::vec3 min{std::numeric_limits<float>::max()};
    glm::vec3 max{std::numeric_limits<float>::lowest()};

    bool empty() const { return min.x > max.x; }
    void extend(const glm::vec3& p) {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    glm::vec3 center() const { return 0.5f * (min + max); }
    glm::vec3 size() const { return max - min; }
};

// A contiguous range of the index buffer drawn with one material.
struct Submesh {
    std::uint32_t firstIndex = 0;
    std::uint32_t indexCount = 0;
    std::uint32_t materialIndex = 0;

    bool operator==(const Submesh&) const = default;
};

// Indexed triangle mesh. All vertex streams have positions.size() entries;
// normals/tangents/uvs may be empty when the source had none.
// Conventions: right-handed, counter-clockwise front faces; uv (0, 0) is the
// bottom-left corner of the image (OBJ/OpenGL; importers of top-left formats
// such as glTF store 1 - v).
struct Mesh {
    std::string name;
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    // xyz = direction of increasing u; w = +1/-1 such that w * cross(normal, xyz)
    // points along increasing v (image up), the normal map's green axis.
    std::vector<glm::vec4> tangents;
    std::vector<glm::vec2> uvs;
    std::vector<std::uint32_t> indices;
    std::vector<Submesh> submeshes;

    std::size_t triangleCount() const { return indices.size() / 3; }
    Bounds computeBounds() const;

    // Exact comparison of every stream (project round trips must be lossless).
    bool operator==(const Mesh&) const = default;
};

// Fills per-vertex normals from area-weighted face normals.
void computeFlatAwareNormals(Mesh& mesh);

} // namespace lpv::scene
