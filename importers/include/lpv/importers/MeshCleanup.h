#pragma once
// Mesh clean-up shared by every importer: weld exact duplicates, drop
// degenerate triangles and unused vertices, generate or repair normals
// (crease-aware, through OpenMesh's halfedge structure) and generate tangents.
//
// What it guarantees for any input (it cannot fail and never throws beyond
// std::bad_alloc):
// - every non-degenerate triangle survives, in its original order, and every
//   submesh range covers exactly its surviving triangles (submeshes left with
//   none are removed);
// - normals are present, finite and unit length; tangents (unless
//   generateTangents is off) are finite, unit, orthogonal to the normal, with
//   w = +1 or -1 (the convention of scene::Mesh::tangents);
// - vertices are numbered in the order the index buffer first uses them, so
//   the same input always gives the same bytes, and cleaning a cleaned mesh
//   changes nothing.
#include "lpv/scene/Mesh.h"

#include <cstddef>

namespace lpv::importers {

struct MeshCleanupOptions {
    // Merge vertices whose position, normal, uv and tangent are bitwise equal.
    // Off: only the copies the clean-up itself makes of one vertex are merged.
    bool weld = true;
    // Generated normals are smoothed across an edge only where the two face
    // normals differ by less than this; a box keeps hard edges, a sphere is smooth.
    float creaseAngleDegrees = 60.0f;
    // Generate tangents when the mesh has uvs but no tangents; replace invalid
    // ones and those whose normal was replaced. Off: tangents pass through as they are.
    bool generateTangents = true;
};

struct MeshCleanupStats {
    std::size_t verticesBefore = 0;
    std::size_t verticesAfter = 0;
    // Referenced input vertices equal to an earlier one (merged by weld).
    std::size_t verticesWelded = 0;
    // Repeated or out-of-range index, (near) zero area, or a non-finite corner.
    std::size_t degenerateTrianglesDropped = 0;
    // Input vertices that no surviving triangle references.
    std::size_t unusedVerticesDropped = 0;
    // The mesh had no normals and all were generated.
    bool normalsGenerated = false;
    // Referenced input vertices whose normal was non-finite or zero length.
    std::size_t invalidNormalsRepaired = 0;
    // Some tangents were generated (none existed, or invalid ones were replaced).
    bool tangentsGenerated = false;
};

// Cleans `mesh` in place; see the guarantees above. Streams whose size is not
// positions.size() break scene::Mesh's contract and are treated as absent;
// trailing indices that do not make a whole triangle are dropped.
MeshCleanupStats cleanupMesh(scene::Mesh& mesh, const MeshCleanupOptions& options = {});

} // namespace lpv::importers
