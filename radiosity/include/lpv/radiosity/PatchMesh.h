#pragma once
// The scene cut into radiosity patches: every visible object's triangles,
// merged back into quads where two coplanar triangles form one, subdivided
// until no patch is larger than `radiosity.maxPatchArea` (docs/radiosity.md).
#include "lpv/scene/Scene.h"

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace lpv::radiosity {

// A planar triangle or quad in world space, corners counter-clockwise seen
// from the front (the side its normal points to).
struct Patch {
    std::array<glm::vec3, 4> corners{};
    std::array<glm::vec2, 4> uvs{};          // texture coordinates of the corners (0 where the mesh has none)
    std::array<std::uint32_t, 4> vertices{}; // welded corner indices into PatchMesh::vertices
    std::uint8_t cornerCount = 3;
    glm::vec3 center{0.0f};
    glm::vec3 normal{0.0f, 0.0f, 1.0f};
    float area = 0.0f;
    std::uint32_t material = 0;
    std::uint32_t object = 0;
};

struct PatchMesh {
    std::vector<Patch> patches;
    // Welded corner positions (per object, so objects never share a vertex).
    std::vector<glm::vec3> vertices;
    // Patches sharing an edge, as compressed rows: the neighbours of patch i
    // are neighbours[neighbourOffsets[i] .. neighbourOffsets[i + 1]).
    std::vector<std::uint32_t> neighbourOffsets;
    std::vector<std::uint32_t> neighbours;
    // Patches touching each welded vertex, same layout (for smoothing).
    std::vector<std::uint32_t> vertexPatchOffsets;
    std::vector<std::uint32_t> vertexPatches;
    // Source quads kept as quads (a count for reports and tests).
    std::size_t sourceQuads = 0;
    std::size_t sourceTriangles = 0;

    std::size_t size() const { return patches.size(); }
    float totalArea() const;
};

struct MeshingOptions {
    float maxPatchArea = 0.05f; // radiosity.maxPatchArea
};

// Centre, normal and area from the corners.
void computePatchGeometry(Patch& patch);

// Patches of every visible object with a mesh. Degenerate triangles are skipped.
PatchMesh buildPatchMesh(const scene::Scene& scene, const MeshingOptions& options);
// How many patches buildPatchMesh would make, without storing them (the
// radiosity.maxPatches check runs before meshing allocates).
std::size_t countPatches(const scene::Scene& scene, const MeshingOptions& options);

// Splits each patch in `which` into children of at most a quarter of its
// area (a square into 2x2, a triangle at its edge midpoints), keeping the
// others, and rebuilds welding and adjacency.
// `parentOf` receives, for every new patch, the index of the patch it came
// from, so a solver can carry radiosity over.
PatchMesh refinePatches(const PatchMesh& mesh, const std::vector<std::uint32_t>& which,
                        std::vector<std::uint32_t>& parentOf);

// Fills vertices, patch vertex indices, neighbours and vertex-patch lists
// (OpenMesh halfedge structure per object). Called by the builders above.
void buildAdjacency(PatchMesh& mesh);

} // namespace lpv::radiosity
