// Crease-aware normal generation on OpenMesh's halfedge structure.
//
// Every triangle becomes an OpenMesh face on vertices shared by exact
// position. Around each vertex the fan of faces is walked in order and cut at
// crease edges (face normals at or beyond the crease angle apart) and at
// boundaries; each piece (a "wedge") gets one angle-weighted normal, so a
// vertex is split exactly where the surface has a hard edge.
//
// OpenMesh's halfedge structure cannot hold a non-manifold face: a third face
// on one edge ("complex edge") or a face at a vertex whose fan is already
// closed ("complex vertex"). Real scenes (Sponza, Sibenik) have them, and
// losing a triangle is not an option, so such a face is added on three fresh
// vertices of its own, and its corners are then smoothed with the faces
// around the shared vertex of their position that are within the crease
// angle of it. The checks that OpenMesh's add_face makes are repeated before
// calling it, so it never prints its complaints to std::cerr.
#include "MeshCleanupDetail.h"

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <numbers>
#include <unordered_map>

namespace lpv::importers::detail {
namespace {

// Double precision: face normals of thin triangles far from the origin stay accurate.
struct DoubleTraits : OpenMesh::DefaultTraits {
    using Point = OpenMesh::Vec3d;
    using Normal = OpenMesh::Vec3d;
};
using OmMesh = OpenMesh::TriMesh_ArrayKernelT<DoubleTraits>;
using OpenMesh::FaceHandle;
using OpenMesh::HalfedgeHandle;
using OpenMesh::VertexHandle;

// Exact position bits; adding +0 first makes -0 and +0 the same position.
struct PositionKey {
    std::array<std::uint32_t, 3> bits;
    bool operator==(const PositionKey&) const = default;
};

PositionKey positionKey(const glm::vec3& p) {
    return {std::bit_cast<std::uint32_t>(p.x + 0.0f), std::bit_cast<std::uint32_t>(p.y + 0.0f),
            std::bit_cast<std::uint32_t>(p.z + 0.0f)};
}

struct PositionKeyHash {
    std::size_t operator()(const PositionKey& k) const {
        std::uint64_t h = 0x9e3779b97f4a7c15ull;
        for (std::uint32_t b : k.bits)
            h = (h ^ b) * 0xff51afd7ed558ccdull;
        return std::size_t(h ^ (h >> 32));
    }
};

glm::dvec3 toGlm(const OpenMesh::Vec3d& v) {
    return {v[0], v[1], v[2]};
}

class NormalBuilder {
public:
    NormalBuilder(std::span<const glm::vec3> positions, std::span<const double> angles, float creaseAngleDegrees)
        : positions_(positions), angles_(angles),
          cosCrease_(std::cos(std::clamp(double(creaseAngleDegrees), 0.0, 180.0) * std::numbers::pi / 180.0)),
          cornerVertex_(positions.size()), sharedVertex_(positions.size()), isolated_(positions.size() / 3, 0),
          normals_(positions.size(), glm::vec3(0.0f)) {}

    std::vector<glm::vec3> run() {
        mesh_.reserve(positions_.size() / 2, positions_.size() * 3 / 2, positions_.size() / 3);
        for (std::size_t t = 0; t < isolated_.size(); ++t)
            addTriangle(t);
        mesh_.request_face_normals();
        mesh_.update_face_normals();
        for (VertexHandle v : mesh_.vertices())
            if (!mesh_.is_isolated(v))
                assignWedges(v);
        for (std::size_t t = 0; t < isolated_.size(); ++t)
            if (isolated_[t])
                assignIsolated(t);
        return std::move(normals_);
    }

private:
    VertexHandle sharedVertexAt(const glm::vec3& p) {
        auto [it, inserted] = byPosition_.try_emplace(positionKey(p));
        if (inserted)
            it->second = mesh_.add_vertex(OpenMesh::Vec3d(p.x, p.y, p.z));
        return it->second;
    }

    // Face index == triangle index: exactly one face is added per triangle.
    void addTriangle(std::size_t t) {
        std::array<VertexHandle, 3> v;
        for (std::size_t k = 0; k < 3; ++k)
            v[k] = sharedVertex_[3 * t + k] = sharedVertexAt(positions_[3 * t + k]);
        FaceHandle f;
        if (fitsManifold(v))
            f = mesh_.add_face(v[0], v[1], v[2]);
        if (!f.is_valid()) {
            isolated_[t] = 1;
            for (std::size_t k = 0; k < 3; ++k) {
                const glm::vec3& p = positions_[3 * t + k];
                v[k] = mesh_.add_vertex(OpenMesh::Vec3d(p.x, p.y, p.z));
            }
            mesh_.add_face(v[0], v[1], v[2]);
        }
        std::copy(v.begin(), v.end(), cornerVertex_.begin() + std::ptrdiff_t(3 * t));
    }

    // The checks of OpenMesh's PolyConnectivity::add_face, read-only (it
    // defers its relinking until all of them passed, so they see the same state).
    bool fitsManifold(const std::array<VertexHandle, 3>& v) const {
        std::array<HalfedgeHandle, 3> he;
        for (std::size_t i = 0; i < 3; ++i) {
            if (!mesh_.is_boundary(v[i]))
                return false; // complex vertex: its fan is closed, no gap for another face
            he[i] = mesh_.find_halfedge(v[i], v[(i + 1) % 3]);
            if (he[i].is_valid() && !mesh_.is_boundary(he[i]))
                return false; // complex edge: this side of the edge already has a face
        }
        for (std::size_t i = 0; i < 3; ++i) {
            const HalfedgeHandle innerPrev = he[i], innerNext = he[(i + 1) % 3];
            if (!innerPrev.is_valid() || !innerNext.is_valid() || mesh_.next_halfedge_handle(innerPrev) == innerNext)
                continue;
            // OpenMesh moves the faces between the two edges into another gap of the fan; there must be one.
            HalfedgeHandle gap = mesh_.opposite_halfedge_handle(innerNext);
            do
                gap = mesh_.opposite_halfedge_handle(mesh_.next_halfedge_handle(gap));
            while (!mesh_.is_boundary(gap));
            if (gap == innerPrev)
                return false;
        }
        return true;
    }

    static FaceHandle faceOfTriangle(std::size_t t) { return FaceHandle(static_cast<int>(t)); }

    glm::dvec3 faceNormal(FaceHandle f) const { return toGlm(mesh_.normal(f)); }

    bool smooth(FaceHandle a, FaceHandle b) const {
        return a.is_valid() && b.is_valid() && glm::dot(faceNormal(a), faceNormal(b)) > cosCrease_;
    }

    // An edge cuts the fan where it is a boundary or a crease.
    bool cutsFan(HalfedgeHandle outgoing) const {
        return !smooth(mesh_.face_handle(outgoing), mesh_.opposite_face_handle(outgoing));
    }

    std::size_t cornerOf(FaceHandle f, VertexHandle v, const std::vector<VertexHandle>& corners) const {
        const std::size_t first = 3 * std::size_t(f.idx());
        for (std::size_t k = 0; k < 3; ++k)
            if (corners[first + k] == v)
                return first + k;
        return first; // unreachable: a face's vertex is one of its corners
    }

    // A vertex without faces is skipped by run(): it is a shared position
    // whose every triangle was isolated (its first one added the vertex and
    // was then refused, e.g. for a complex edge), so it has no corner of its
    // own, and OpenMesh 9's counter-clockwise circulator steps from its
    // missing halfedge (halfedge -1) before checking it. The corners at such
    // a position get their normals in assignIsolated.
    void assignWedges(VertexHandle v) {
        ring_.clear();
        for (HalfedgeHandle h : mesh_.voh_ccw_range(v))
            ring_.push_back(h);
        // Start at a cut so that no wedge wraps around the end of the ring; a
        // closed fan without cuts is one wedge.
        const auto cut = std::find_if(ring_.begin(), ring_.end(), [&](HalfedgeHandle h) { return cutsFan(h); });
        std::rotate(ring_.begin(), cut == ring_.end() ? ring_.begin() : cut, ring_.end());
        wedge_.clear();
        for (std::size_t i = 0; i < ring_.size(); ++i) {
            if (i > 0 && cutsFan(ring_[i]))
                finishWedge();
            // The face of an outgoing halfedge lies between it and the next one counter-clockwise.
            if (const FaceHandle f = mesh_.face_handle(ring_[i]); f.is_valid())
                wedge_.push_back(cornerOf(f, v, cornerVertex_));
        }
        finishWedge();
    }

    void finishWedge() {
        if (wedge_.empty())
            return;
        glm::dvec3 sum(0.0);
        for (std::size_t c : wedge_)
            sum += angles_[c] * faceNormal(faceOfTriangle(c / 3));
        for (std::size_t c : wedge_)
            normals_[c] = finish(sum, faceOfTriangle(c / 3));
        wedge_.clear();
    }

    // A sum that cancels out (faces folded onto each other) falls back to the corner's own face.
    glm::vec3 finish(const glm::dvec3& sum, FaceHandle own) const {
        const double length = glm::length(sum);
        if (std::isfinite(length) && length > 1e-12)
            return glm::vec3(sum / length);
        return glm::vec3(faceNormal(own));
    }

    void assignIsolated(std::size_t t) {
        const FaceHandle own = faceOfTriangle(t);
        const glm::dvec3 n = faceNormal(own);
        for (std::size_t k = 0; k < 3; ++k) {
            const std::size_t corner = 3 * t + k;
            const VertexHandle shared = sharedVertex_[corner];
            glm::dvec3 sum = angles_[corner] * n;
            for (FaceHandle f : mesh_.vf_range(shared))
                if (glm::dot(faceNormal(f), n) > cosCrease_)
                    sum += angles_[cornerOf(f, shared, cornerVertex_)] * faceNormal(f);
            normals_[corner] = finish(sum, own);
        }
    }

    std::span<const glm::vec3> positions_;
    std::span<const double> angles_;
    double cosCrease_;
    OmMesh mesh_;
    std::unordered_map<PositionKey, VertexHandle, PositionKeyHash> byPosition_;
    std::vector<VertexHandle> cornerVertex_; // the vertex each corner's face was added with
    std::vector<VertexHandle> sharedVertex_; // the vertex of the corner's position
    std::vector<std::uint8_t> isolated_;     // per triangle: added on vertices of its own
    std::vector<glm::vec3> normals_;
    std::vector<HalfedgeHandle> ring_;
    std::vector<std::size_t> wedge_; // corners of the wedge being collected
};

} // namespace

std::vector<glm::vec3> generateCornerNormals(std::span<const glm::vec3> cornerPositions,
                                             std::span<const double> angles, float creaseAngleDegrees) {
    return NormalBuilder(cornerPositions, angles, creaseAngleDegrees).run();
}

} // namespace lpv::importers::detail
