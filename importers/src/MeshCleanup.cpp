// cleanupMesh: the order of the stages and their bookkeeping (MeshCleanup.h).
//
// The surviving triangles are expanded into corners (MeshCleanupDetail.h),
// normals and tangents are filled in per corner, and one weld at the end
// turns corners with bit-identical attributes back into shared vertices. A
// vertex that needs two normals (a hard edge) or two tangents (mirrored uvs)
// therefore splits by itself, and exact duplicates in the input merge.
#include "lpv/importers/MeshCleanup.h"

#include "MeshCleanupDetail.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <optional>
#include <unordered_map>

namespace lpv::importers {
namespace {

using detail::isUsableDirection;
using detail::remapSubmeshes;
using detail::survivingTriangles;

// Squared lengths further than this from 1 are renormalised; closer ones keep
// their bits, so cleaning a cleaned mesh changes nothing.
constexpr float kUnitTolerance = 2e-3f;

// A kept tangent whose cosine with the normal exceeds this is re-orthogonalised.
constexpr float kOrthogonalTolerance = 1e-3f;

glm::vec3 unitLength(const glm::vec3& v) {
    const float lengthSquared = glm::dot(v, v);
    return std::abs(lengthSquared - 1.0f) > kUnitTolerance ? v / std::sqrt(lengthSquared) : v;
}

// ---- corners --------------------------------------------------------------

struct Corners {
    std::vector<std::uint32_t> source; // the input vertex of each corner
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;  // empty: the mesh has none (yet)
    std::vector<glm::vec2> uvs;      // empty: the mesh has none
    std::vector<glm::vec4> tangents; // empty: the mesh has none (yet)
    std::size_t size() const { return source.size(); }
};

template <class T>
std::vector<T> perCorner(const std::vector<T>& stream, const std::vector<std::uint32_t>& source) {
    std::vector<T> out;
    if (stream.empty())
        return out;
    out.reserve(source.size());
    for (std::uint32_t v : source)
        out.push_back(stream[v]);
    return out;
}

Corners gatherCorners(const scene::Mesh& mesh, const std::vector<std::uint8_t>& keep) {
    Corners c;
    for (std::size_t t = 0; t < keep.size(); ++t)
        if (keep[t])
            c.source.insert(c.source.end(), mesh.indices.begin() + std::ptrdiff_t(3 * t),
                            mesh.indices.begin() + std::ptrdiff_t(3 * t + 3));
    c.positions = perCorner(mesh.positions, c.source);
    c.normals = perCorner(mesh.normals, c.source);
    c.uvs = perCorner(mesh.uvs, c.source);
    c.tangents = perCorner(mesh.tangents, c.source);
    return c;
}

std::size_t countSources(const Corners& c, const std::vector<std::uint8_t>& selected, std::size_t vertexCount) {
    std::vector<std::uint8_t> seen(vertexCount, 0);
    std::size_t n = 0;
    for (std::size_t i = 0; i < c.size(); ++i)
        if (selected[i] && !seen[c.source[i]]) {
            seen[c.source[i]] = 1;
            ++n;
        }
    return n;
}

// ---- welding --------------------------------------------------------------

// Exact bits of what a vertex carries; word 0 holds the source vertex when
// only the clean-up's own copies may merge (weld off).
using VertexKey = std::array<std::uint32_t, 13>;

struct VertexKeyHash {
    std::size_t operator()(const VertexKey& k) const {
        std::uint64_t h = 0x9e3779b97f4a7c15ull;
        for (std::uint32_t w : k)
            h = (h ^ w) * 0xff51afd7ed558ccdull;
        return std::size_t(h ^ (h >> 32));
    }
};

template <int N>
void putBits(VertexKey& key, std::size_t at, const glm::vec<N, float>& v) {
    for (int i = 0; i < N; ++i)
        key[at + std::size_t(i)] = std::bit_cast<std::uint32_t>(v[i]);
}

template <class T>
void putStream(VertexKey& key, std::size_t at, const std::vector<T>& stream, std::size_t i) {
    if (!stream.empty())
        putBits(key, at, stream[i]);
}

VertexKey cornerKey(const Corners& c, std::size_t i, bool weld) {
    VertexKey key{};
    key[0] = weld ? 0 : c.source[i];
    putBits(key, 1, c.positions[i]);
    putStream(key, 4, c.normals, i);
    putStream(key, 7, c.uvs, i);
    putStream(key, 9, c.tangents, i);
    return key;
}

VertexKey inputKey(const scene::Mesh& mesh, std::uint32_t v) {
    VertexKey key{};
    putBits(key, 1, mesh.positions[v]);
    putStream(key, 4, mesh.normals, v);
    putStream(key, 7, mesh.uvs, v);
    putStream(key, 9, mesh.tangents, v);
    return key;
}

struct Ids {
    std::vector<std::uint32_t> of; // per item
    std::uint32_t count = 0;
};

// Ids in order of first use, so the output order follows the index buffer
// and never the hash table's iteration order.
template <class KeyOf>
Ids assignIds(std::size_t n, KeyOf keyOf) {
    Ids ids;
    ids.of.resize(n);
    std::unordered_map<VertexKey, std::uint32_t, VertexKeyHash> idOfKey;
    idOfKey.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
        const auto [it, inserted] = idOfKey.try_emplace(keyOf(i), ids.count);
        ids.count += inserted ? 1 : 0;
        ids.of[i] = it->second;
    }
    return ids;
}

Ids weldCorners(const Corners& c, bool weld) {
    return assignIds(c.size(), [&](std::size_t i) { return cornerKey(c, i, weld); });
}

// Referenced input vertices equal to an earlier referenced one.
std::size_t countDuplicates(const scene::Mesh& mesh, const std::vector<std::uint8_t>& referenced) {
    std::vector<std::uint32_t> used;
    for (std::uint32_t v = 0; v < referenced.size(); ++v)
        if (referenced[v])
            used.push_back(v);
    return used.size() - assignIds(used.size(), [&](std::size_t i) { return inputKey(mesh, used[i]); }).count;
}

// ---- normals and tangents -------------------------------------------------

// Fills missing and invalid normals with generated ones; returns which corners got one.
std::vector<std::uint8_t> repairNormals(Corners& c, const std::vector<double>& angles, std::size_t vertexCount,
                                        const MeshCleanupOptions& options, MeshCleanupStats& stats) {
    const bool hadNormals = !c.normals.empty();
    std::vector<std::uint8_t> replace(c.size(), hadNormals ? 0 : 1);
    if (!hadNormals)
        c.normals.assign(c.size(), glm::vec3(0.0f));
    for (std::size_t i = 0; i < c.size(); ++i)
        replace[i] |= isUsableDirection(c.normals[i]) ? 0 : 1;
    if (std::find(replace.begin(), replace.end(), 1) != replace.end()) {
        const std::vector<glm::vec3> generated =
            detail::generateCornerNormals(c.positions, angles, options.creaseAngleDegrees);
        for (std::size_t i = 0; i < c.size(); ++i)
            if (replace[i])
                c.normals[i] = generated[i];
    }
    for (glm::vec3& n : c.normals)
        n = unitLength(n);
    stats.normalsGenerated = !hadNormals && c.size() > 0;
    stats.invalidNormalsRepaired = hadNormals ? countSources(c, replace, vertexCount) : 0;
    return replace;
}

// An existing tangent made unit, orthogonal to n and w = +-1; none if it cannot be.
std::optional<glm::vec4> tidyTangent(const glm::vec4& t, const glm::vec3& n) {
    glm::vec3 xyz(t);
    if (!isUsableDirection(xyz) || !std::isfinite(t.w) || t.w == 0.0f)
        return std::nullopt;
    const float lengthSquared = glm::dot(xyz, xyz);
    const float along = glm::dot(xyz, n);
    if (along * along > kOrthogonalTolerance * kOrthogonalTolerance * lengthSquared) {
        xyz -= n * along;
        // Nearly parallel to the normal: the projection is mostly rounding noise.
        if (glm::dot(xyz, xyz) < 1e-6f * lengthSquared)
            return std::nullopt;
        xyz = glm::normalize(xyz);
    } else {
        xyz = unitLength(xyz);
    }
    return glm::vec4(xyz, t.w < 0.0f ? -1.0f : 1.0f);
}

// Generates tangents where there are none, where they are invalid, and where
// the normal was replaced (the old tangent belonged to the old normal).
void repairTangents(Corners& c, const std::vector<std::uint8_t>& normalReplaced, const std::vector<double>& angles,
                    bool weld, MeshCleanupStats& stats) {
    const bool hadTangents = !c.tangents.empty();
    if (!hadTangents && c.uvs.empty())
        return;
    if (!hadTangents)
        c.tangents.assign(c.size(), glm::vec4(0.0f));
    std::vector<std::uint8_t> wanted(c.size(), 0);
    for (std::size_t i = 0; i < c.size(); ++i) {
        const std::optional<glm::vec4> kept =
            hadTangents && !normalReplaced[i] ? tidyTangent(c.tangents[i], c.normals[i]) : std::nullopt;
        // A zero tangent marks a wanted corner, so the grouping below groups
        // those by position, normal and uv alone.
        c.tangents[i] = kept.value_or(glm::vec4(0.0f));
        wanted[i] = kept ? 0 : 1;
    }
    if (std::find(wanted.begin(), wanted.end(), 1) == wanted.end())
        return;
    const Ids groups = weldCorners(c, weld);
    const std::vector<glm::vec4> generated = detail::generateCornerTangents({.positions = c.positions,
                                                                             .uvs = c.uvs,
                                                                             .normals = c.normals,
                                                                             .angles = angles,
                                                                             .groups = groups.of,
                                                                             .groupCount = groups.count,
                                                                             .wanted = wanted});
    for (std::size_t i = 0; i < c.size(); ++i)
        if (wanted[i])
            c.tangents[i] = generated[i];
    stats.tangentsGenerated = true;
}

// ---- output ---------------------------------------------------------------

template <class T>
void scatter(std::vector<T>& stream, const std::vector<T>& perCornerValues, const Ids& ids) {
    stream.assign(perCornerValues.empty() ? 0 : ids.count, T{});
    if (perCornerValues.empty())
        return;
    // Every corner of an id carries the same bits, so any of them may write it.
    for (std::size_t i = 0; i < ids.of.size(); ++i)
        stream[ids.of[i]] = perCornerValues[i];
}

void writeVertices(scene::Mesh& mesh, const Corners& c, bool weld) {
    const Ids ids = weldCorners(c, weld);
    scatter(mesh.positions, c.positions, ids);
    scatter(mesh.normals, c.normals, ids);
    scatter(mesh.uvs, c.uvs, ids);
    scatter(mesh.tangents, c.tangents, ids);
    mesh.indices = ids.of;
}

// A stream of the wrong size (against Mesh's contract) cannot be matched to vertices.
void dropMissizedStreams(scene::Mesh& mesh) {
    const std::size_t n = mesh.positions.size();
    if (mesh.normals.size() != n)
        mesh.normals.clear();
    if (mesh.uvs.size() != n)
        mesh.uvs.clear();
    if (mesh.tangents.size() != n)
        mesh.tangents.clear();
}

} // namespace

MeshCleanupStats cleanupMesh(scene::Mesh& mesh, const MeshCleanupOptions& options) {
    MeshCleanupStats stats;
    stats.verticesBefore = mesh.positions.size();
    dropMissizedStreams(mesh);
    const std::vector<std::uint8_t> keep = survivingTriangles(mesh);
    stats.degenerateTrianglesDropped = std::size_t(std::count(keep.begin(), keep.end(), 0));
    remapSubmeshes(mesh.submeshes, keep);

    Corners corners = gatherCorners(mesh, keep);
    std::vector<std::uint8_t> referenced(mesh.positions.size(), 0);
    for (std::uint32_t v : corners.source)
        referenced[v] = 1;
    stats.unusedVerticesDropped = std::size_t(std::count(referenced.begin(), referenced.end(), 0));
    if (options.weld)
        stats.verticesWelded = countDuplicates(mesh, referenced);

    const std::vector<double> angles = detail::cornerAngles(corners.positions);
    const std::vector<std::uint8_t> normalReplaced =
        repairNormals(corners, angles, mesh.positions.size(), options, stats);
    if (options.generateTangents)
        repairTangents(corners, normalReplaced, angles, options.weld, stats);

    writeVertices(mesh, corners, options.weld);
    stats.verticesAfter = mesh.positions.size();
    return stats;
}

} // namespace lpv::importers
