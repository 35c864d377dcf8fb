// Welding and neighbours of the patch mesh. Corners are welded per object by
// position on a grid far finer than any patch; OpenMesh's halfedge structure
// then gives the patches across each edge. A face OpenMesh refuses (a
// non-manifold edge) keeps its welded corners for smoothing but has no
// neighbours.
#include "lpv/radiosity/PatchMesh.h"

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

namespace lpv::radiosity {
namespace {

using OmMesh = OpenMesh::PolyMesh_ArrayKernelT<>;

// Rows of a compressed adjacency list from per-row vectors.
void compress(const std::vector<std::vector<std::uint32_t>>& rows, std::vector<std::uint32_t>& offsets,
              std::vector<std::uint32_t>& items) {
    offsets.assign(1, 0);
    items.clear();
    for (const auto& row : rows) {
        items.insert(items.end(), row.begin(), row.end());
        offsets.push_back(std::uint32_t(items.size()));
    }
}

} // namespace

void buildAdjacency(PatchMesh& mesh) {
    scene::Bounds bounds;
    for (const Patch& p : mesh.patches)
        for (int k = 0; k < p.cornerCount; ++k)
            bounds.extend(p.corners[std::size_t(k)]);
    // Welded within a millionth of the mesh's diagonal (scene-relative); the
    // fallback is a float guard for a mesh of one point, not a length.
    const float diagonal = bounds.empty() ? 0.0f : glm::length(bounds.size());
    const float extent = diagonal > 0.0f && std::isfinite(diagonal) ? diagonal : 1.0f;
    const double quantum = double(extent) * 1e-6;

    using Key = std::tuple<std::uint32_t, long long, long long, long long>;
    std::map<Key, std::uint32_t> welded;
    mesh.vertices.clear();
    for (Patch& p : mesh.patches)
        for (int k = 0; k < p.cornerCount; ++k) {
            const glm::vec3 c = p.corners[std::size_t(k)];
            const Key key{p.object, std::llround(c.x / quantum), std::llround(c.y / quantum),
                          std::llround(c.z / quantum)};
            auto [it, inserted] = welded.try_emplace(key, std::uint32_t(mesh.vertices.size()));
            if (inserted)
                mesh.vertices.push_back(c);
            p.vertices[std::size_t(k)] = it->second;
        }

    std::vector<std::vector<std::uint32_t>> vertexPatches(mesh.vertices.size());
    for (std::uint32_t i = 0; i < mesh.patches.size(); ++i)
        for (int k = 0; k < mesh.patches[i].cornerCount; ++k)
            vertexPatches[mesh.patches[i].vertices[std::size_t(k)]].push_back(i);
    compress(vertexPatches, mesh.vertexPatchOffsets, mesh.vertexPatches);

    // Real scenes have many non-manifold edges; OpenMesh would print one line for each.
    struct QuietOpenMesh {
        QuietOpenMesh() { omerr().disable(); }
        ~QuietOpenMesh() { omerr().enable(); }
    } quiet;
    // One halfedge mesh over everything: welding is per object, so objects stay apart.
    OmMesh om;
    std::vector<OmMesh::VertexHandle> handles;
    handles.reserve(mesh.vertices.size());
    for (const glm::vec3& v : mesh.vertices)
        handles.push_back(om.add_vertex(OmMesh::Point(v.x, v.y, v.z)));
    std::vector<int> patchOfFace;
    std::vector<OmMesh::FaceHandle> faceOfPatch(mesh.patches.size());
    for (std::uint32_t i = 0; i < mesh.patches.size(); ++i) {
        const Patch& p = mesh.patches[i];
        std::vector<OmMesh::VertexHandle> face;
        for (int k = 0; k < p.cornerCount; ++k)
            face.push_back(handles[p.vertices[std::size_t(k)]]);
        // Two corners welded into one (a sliver) cannot be a face.
        std::vector<OmMesh::VertexHandle> unique = face;
        std::sort(unique.begin(), unique.end());
        if (std::unique(unique.begin(), unique.end()) != unique.end())
            continue;
        const auto fh = om.add_face(face); // invalid for a non-manifold edge
        faceOfPatch[i] = fh;
        if (fh.is_valid()) {
            if (patchOfFace.size() <= std::size_t(fh.idx()))
                patchOfFace.resize(std::size_t(fh.idx()) + 1, -1);
            patchOfFace[std::size_t(fh.idx())] = int(i);
        }
    }
    std::vector<std::vector<std::uint32_t>> neighbours(mesh.patches.size());
    for (std::uint32_t i = 0; i < mesh.patches.size(); ++i) {
        if (!faceOfPatch[i].is_valid())
            continue;
        for (auto ff : om.ff_range(faceOfPatch[i]))
            neighbours[i].push_back(std::uint32_t(patchOfFace[std::size_t(ff.idx())]));
    }
    compress(neighbours, mesh.neighbourOffsets, mesh.neighbours);
}

} // namespace lpv::radiosity
