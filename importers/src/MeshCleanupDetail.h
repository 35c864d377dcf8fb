#pragma once
// Internals of cleanupMesh (MeshCleanup.cpp), split by stage: triangles
// (MeshTriangles.cpp), normals (MeshNormals.cpp, OpenMesh) and tangents
// (MeshTangents.cpp). Normals and tangents work on triangle corners (3 per
// surviving triangle, in index-buffer order) so that splitting a vertex is
// simply giving its corners different values; the final weld turns equal
// corners back into shared vertices.
#include "lpv/scene/Mesh.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace lpv::importers::detail {

// Per triangle of the index buffer: 1 if it survives, 0 if it is degenerate
// (repeated or out-of-range index, a corner not finite or beyond +-1e18, or no area relative
// to its size). Trailing indices that make no whole triangle are not listed.
std::vector<std::uint8_t> survivingTriangles(const scene::Mesh& mesh);

// Makes each submesh cover exactly its surviving triangles once the others
// are removed from the index buffer; submeshes left empty are removed.
void remapSubmeshes(std::vector<scene::Submesh>& submeshes, const std::vector<std::uint8_t>& keep);

// Unit vector or not: anything that cannot be normalised safely.
bool isUsableDirection(const glm::vec3& v);

// A unit vector perpendicular to the unit vector n (deterministic).
glm::vec3 anyPerpendicular(const glm::vec3& n);

// Interior angle of each corner of each triangle (radians), the weight of a
// face in its corners' averages: unlike area weights it does not depend on
// how a surface happens to be split into triangles.
std::vector<double> cornerAngles(std::span<const glm::vec3> cornerPositions);

// Crease-aware smooth normals for every corner. Corners meet where their
// positions are equal (not their indices: uv seams must not crease); a
// corner's normal averages the faces around its position reachable without
// crossing an edge whose face normals differ by the crease angle or more.
// Faces that would make the halfedge structure non-manifold still get a
// normal (see MeshNormals.cpp).
std::vector<glm::vec3> generateCornerNormals(std::span<const glm::vec3> cornerPositions,
                                             std::span<const double> angles, float creaseAngleDegrees);

struct TangentInput {
    std::span<const glm::vec3> positions; // per corner
    std::span<const glm::vec2> uvs;       // per corner, may be empty (then no uv gradient)
    std::span<const glm::vec3> normals;   // per corner, unit
    std::span<const double> angles;       // per corner
    // Corners with equal group ids share one vertex (position, normal, uv);
    // ids are dense from 0.
    std::span<const std::uint32_t> groups;
    std::uint32_t groupCount = 0;
    // Which corners need a tangent; the others are left zero.
    std::span<const std::uint8_t> wanted;
};

// Tangent per wanted corner: xyz unit, orthogonal to the corner's normal, w =
// +1/-1. Corners of one group with the same handedness get bit-identical
// tangents; a group whose triangles disagree on handedness (mirrored uvs)
// gets one tangent per sign, which the final weld turns into two vertices.
std::vector<glm::vec4> generateCornerTangents(const TangentInput& input);

} // namespace lpv::importers::detail
