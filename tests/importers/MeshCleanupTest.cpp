// Mesh clean-up (importers/include/lpv/importers/MeshCleanup.h): welding,
// degenerate triangles and submesh ranges, crease-aware normals through
// OpenMesh (including faces its halfedge structure rejects), tangents with
// mirrored uvs, determinism, and the real Sibenik model.
#include "lpv/importers/MeshCleanup.h"

#include "lpv/importers/FourDsReader.h"
#include "lpv/scene/CornellBox.h"

#include "TestPaths.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <numbers>
#include <random>
#include <sstream>
#include <vector>

namespace {

using lpv::importers::cleanupMesh;
using lpv::importers::MeshCleanupOptions;
using lpv::importers::MeshCleanupStats;
using lpv::scene::Mesh;
using lpv::scene::Submesh;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

Mesh makeMesh(std::vector<glm::vec3> positions, std::vector<std::uint32_t> indices) {
    Mesh m;
    m.name = "test";
    m.positions = std::move(positions);
    m.indices = std::move(indices);
    m.submeshes.push_back(
        {.firstIndex = 0, .indexCount = std::uint32_t(m.indices.size()), .materialIndex = 0});
    return m;
}

glm::vec3 corner(const Mesh& m, std::size_t t, std::size_t k) {
    return m.positions[m.indices[3 * t + k]];
}

glm::vec3 faceNormal(const Mesh& m, std::size_t t) {
    return glm::normalize(glm::cross(corner(m, t, 1) - corner(m, t, 0), corner(m, t, 2) - corner(m, t, 0)));
}

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// What cleanupMesh promises for every output: streams of the right size,
// valid indices and ranges, finite unit normals and valid tangent frames.
void expectValidOutput(const Mesh& m) {
    const std::size_t n = m.positions.size();
    ASSERT_EQ(m.normals.size(), n);
    ASSERT_TRUE(m.uvs.empty() || m.uvs.size() == n);
    ASSERT_TRUE(m.tangents.empty() || m.tangents.size() == n);
    ASSERT_EQ(m.indices.size() % 3, 0u);
    for (std::uint32_t i : m.indices)
        ASSERT_LT(i, n);
    for (const Submesh& s : m.submeshes) {
        EXPECT_GT(s.indexCount, 0u);
        EXPECT_EQ(s.firstIndex % 3, 0u);
        EXPECT_EQ(s.indexCount % 3, 0u);
        EXPECT_LE(std::uint64_t(s.firstIndex) + s.indexCount, m.indices.size());
    }
    for (std::size_t v = 0; v < n; ++v) {
        SCOPED_TRACE("vertex " + std::to_string(v));
        ASSERT_TRUE(finite(m.positions[v]));
        ASSERT_TRUE(finite(m.normals[v]));
        EXPECT_NEAR(glm::length(m.normals[v]), 1.0f, 1e-3f);
        if (!m.uvs.empty()) {
            ASSERT_TRUE(std::isfinite(m.uvs[v].x) && std::isfinite(m.uvs[v].y));
        }
        if (!m.tangents.empty()) {
            const glm::vec3 t(m.tangents[v]);
            ASSERT_TRUE(finite(t));
            EXPECT_NEAR(glm::length(t), 1.0f, 1e-3f);
            EXPECT_NEAR(glm::dot(t, m.normals[v]), 0.0f, 1e-3f);
            EXPECT_TRUE(m.tangents[v].w == 1.0f || m.tangents[v].w == -1.0f) << m.tangents[v].w;
        }
    }
}

// A second clean-up must change nothing and report nothing.
void expectIdempotent(const Mesh& cleaned, const MeshCleanupOptions& options = {}) {
    Mesh again = cleaned;
    const MeshCleanupStats s = cleanupMesh(again, options);
    EXPECT_TRUE(again == cleaned) << "a second clean-up changed the mesh";
    EXPECT_EQ(s.verticesAfter, s.verticesBefore);
    EXPECT_EQ(s.verticesWelded, 0u);
    EXPECT_EQ(s.degenerateTrianglesDropped, 0u);
    EXPECT_EQ(s.unusedVerticesDropped, 0u);
    EXPECT_FALSE(s.normalsGenerated);
    EXPECT_EQ(s.invalidNormalsRepaired, 0u);
    EXPECT_FALSE(s.tangentsGenerated);
}

// OpenMesh reports rejected faces on std::cerr; the clean-up must never let it.
class CerrCapture {
  public:
    CerrCapture() : old_(std::cerr.rdbuf(text_.rdbuf())) {}
    ~CerrCapture() { std::cerr.rdbuf(old_); }
    CerrCapture(const CerrCapture&) = delete;
    CerrCapture& operator=(const CerrCapture&) = delete;
    std::string text() const { return text_.str(); }

  private:
    std::ostringstream text_;
    std::streambuf* old_;
};

// ---- shapes ----------------------------------------------------------------

// A unit quad in the z = 0 plane as two triangles of three vertices each.
Mesh sixVertexQuad() {
    Mesh m = makeMesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {0, 1, 2, 3, 4, 5});
    m.normals.assign(6, glm::vec3(0, 0, 1));
    m.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}};
    return m;
}

// Eight shared corners, twelve outward triangles, no normals.
Mesh cube(float half = 1.0f) {
    std::vector<glm::vec3> p;
    for (int i = 0; i < 8; ++i)
        p.emplace_back(i & 1 ? half : -half, i & 2 ? half : -half, i & 4 ? half : -half);
    const std::uint32_t faces[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                       {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
    std::vector<std::uint32_t> indices;
    for (const auto& f : faces)
        indices.insert(indices.end(), {f[0], f[1], f[2], f[0], f[2], f[3]});
    return makeMesh(std::move(p), std::move(indices));
}

glm::vec3 spherePoint(double theta, double phi) {
    return glm::vec3(float(std::sin(theta) * std::cos(phi)), float(std::cos(theta)),
                     float(-std::sin(theta) * std::sin(phi)));
}

// A UV sphere as exporters write it: a seam column whose vertices repeat the
// first column with u = 1, and one pole vertex per column (its own u). u
// increases with phi, v upwards, so every tangent frame is right-handed.
Mesh uvSphere(int stacks = 16, int slices = 32) {
    const double pi = std::numbers::pi;
    Mesh m;
    const auto add = [&](glm::vec3 position, glm::vec2 uv) {
        m.positions.push_back(position);
        m.uvs.push_back(uv);
        return std::uint32_t(m.positions.size() - 1);
    };
    std::vector<std::uint32_t> north, south;
    for (int j = 0; j < slices; ++j) {
        const double u = (j + 0.5) / slices;
        north.push_back(add({0, 1, 0}, {float(u), 1.0f}));
    }
    std::vector<std::vector<std::uint32_t>> rings;
    for (int i = 1; i < stacks; ++i) {
        rings.emplace_back();
        for (int j = 0; j <= slices; ++j)
            rings.back().push_back(add(spherePoint(pi * i / stacks, 2 * pi * (j % slices) / slices),
                                       {float(j) / float(slices), 1.0f - float(i) / float(stacks)}));
    }
    for (int j = 0; j < slices; ++j) {
        const double u = (j + 0.5) / slices;
        south.push_back(add({0, -1, 0}, {float(u), 0.0f}));
    }
    for (int j = 0; j < slices; ++j) {
        m.indices.insert(m.indices.end(), {north[j], rings.front()[j], rings.front()[j + 1]});
        for (std::size_t r = 0; r + 1 < rings.size(); ++r) {
            const std::uint32_t a = rings[r][j], b = rings[r + 1][j], c = rings[r + 1][j + 1],
                                d = rings[r][j + 1];
            m.indices.insert(m.indices.end(), {a, b, c, a, c, d});
        }
        m.indices.insert(m.indices.end(), {rings.back()[j], south[j], rings.back()[j + 1]});
    }
    m.submeshes.push_back(
        {.firstIndex = 0, .indexCount = std::uint32_t(m.indices.size()), .materialIndex = 0});
    return m;
}

// ---- welding and unused vertices -------------------------------------------

TEST(MeshCleanup, WeldsAQuadMadeOfSixVertices) {
    Mesh m = sixVertexQuad();
    const MeshCleanupStats s = cleanupMesh(m);
    EXPECT_EQ(s.verticesBefore, 6u);
    EXPECT_EQ(s.verticesAfter, 4u);
    EXPECT_EQ(s.verticesWelded, 2u);
    EXPECT_EQ(s.unusedVerticesDropped, 0u);
    EXPECT_EQ(s.degenerateTrianglesDropped, 0u);
    EXPECT_FALSE(s.normalsGenerated);
    EXPECT_TRUE(s.tangentsGenerated);
    // Vertices are numbered in the order the index buffer first uses them.
    EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3}));
    EXPECT_EQ(m.positions, (std::vector<glm::vec3>{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}));
    EXPECT_EQ(m.uvs, (std::vector<glm::vec2>{{0, 0}, {1, 0}, {1, 1}, {0, 1}}));
    EXPECT_EQ(m.submeshes, (std::vector<Submesh>{{0, 6, 0}}));
    expectValidOutput(m);
    expectIdempotent(m);
}

TEST(MeshCleanup, VerticesThatDifferInAnyAttributeStaySeparate) {
    Mesh m = sixVertexQuad();
    m.uvs[3] = {0.0f, 0.5f};                               // a uv seam at corner (0, 0)
    m.normals[4] = glm::normalize(glm::vec3(0, 0.01f, 1)); // a different normal at (1, 1)
    const MeshCleanupStats s = cleanupMesh(m);
    EXPECT_EQ(s.verticesWelded, 0u);
    EXPECT_EQ(s.verticesAfter, 6u);
    EXPECT_EQ(m.triangleCount(), 2u);
    expectValidOutput(m);
}

TEST(MeshCleanup, WeldOffKeepsEqualVerticesApart) {
    Mesh m = sixVertexQuad();
    const MeshCleanupStats s = cleanupMesh(m, {.weld = false});
    EXPECT_EQ(s.verticesWelded, 0u);
    EXPECT_EQ(s.verticesAfter, 6u);
    EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5}));
    expectValidOutput(m);
    expectIdempotent(m, {.weld = false});
}

TEST(MeshCleanup, DropsVerticesNoTriangleUses) {
    // The six-vertex quad shifted up by one, with unused vertices 0 and 7.
    Mesh m =
        makeMesh({{9, 9, 9}, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 0, 0}, {1, 1, 0}, {0, 1, 0}, {5, 5, 5}},
                 {1, 2, 3, 4, 5, 6});
    m.normals.assign(8, glm::vec3(0, 0, 1));
    m.uvs = {{0.5f, 0.5f}, {0, 0}, {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}, {0.5f, 0.5f}};
    const MeshCleanupStats s = cleanupMesh(m);
    EXPECT_EQ(s.verticesBefore, 8u);
    EXPECT_EQ(s.unusedVerticesDropped, 2u);
    EXPECT_EQ(s.verticesWelded, 2u);
    EXPECT_EQ(s.verticesAfter, 4u);
    EXPECT_EQ(m.positions.front(), glm::vec3(0, 0, 0));
    expectValidOutput(m);
}

// ---- degenerate triangles and submesh ranges ----------------------------------

TEST(MeshCleanup, DropsDegenerateTrianglesAndKeepsSubmeshRangesRight) {
    Mesh m = makeMesh({{0, 0, 0},
                       {1, 0, 0},
                       {0, 1, 0},
                       {2, 0, 0},          // 3: collinear with 0 and 1
                       {0.1f, 0.2f, 0.3f}, // 4, 5: collinear with 0 up to float rounding
                       {0.3f, 0.6f, 0.9f},
                       {kNaN, 0, 0}, // 6
                       {0, kInf, 0}, // 7
                       {1, 1, 0}},
                      {});
    m.indices = {
        0,
        1,
        2,
        /*repeated*/ 0,
        1,
        1,
        1,
        8,
        2, // submesh 0: 2 of 3 survive
        /*collinear*/ 0,
        1,
        3,
        /*rounded collinear*/ 0,
        4,
        5, // submesh 1: none survives
        /*NaN*/ 0,
        6,
        2,
        /*Inf*/ 7,
        1,
        2,
        /*out of range*/ 0,
        1,
        99,
        2,
        1,
        8, // submesh 2: 1 of 4 survives
    };
    m.submeshes = {{0, 9, 4}, {9, 6, 5}, {15, 12, 6}};
    const std::vector<std::vector<glm::vec3>> survivors = {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
                                                           {{1, 0, 0}, {1, 1, 0}, {0, 1, 0}},
                                                           {{0, 1, 0}, {1, 0, 0}, {1, 1, 0}}};
    const MeshCleanupStats s = cleanupMesh(m);
    EXPECT_EQ(s.degenerateTrianglesDropped, 6u);
    ASSERT_EQ(m.triangleCount(), 3u);
    for (std::size_t t = 0; t < 3; ++t)
        for (std::size_t k = 0; k < 3; ++k)
            EXPECT_EQ(corner(m, t, k), survivors[t][k]) << "triangle " << t << " corner " << k;
    EXPECT_EQ(m.submeshes, (std::vector<Submesh>{{0, 6, 4}, {6, 3, 6}})) << "the emptied submesh is gone";
    EXPECT_EQ(s.unusedVerticesDropped, 5u) << "3, 4, 5 and the non-finite 6, 7";
    expectValidOutput(m);
    expectIdempotent(m);
}

TEST(MeshCleanup, MeshOfOnlyDegenerateTrianglesComesOutEmpty) {
    Mesh m = makeMesh({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}, {0, 1, 2, 0, 0, 1, 2});
    m.normals.assign(3, glm::vec3(0, 0, 1));
    m.uvs.assign(3, glm::vec2(0.0f));
    const MeshCleanupStats s = cleanupMesh(m);
    EXPECT_EQ(s.degenerateTrianglesDropped, 2u) << "the trailing index is not a triangle";
    EXPECT_EQ(s.unusedVerticesDropped, 3u);
    EXPECT_EQ(s.verticesAfter, 0u);
    EXPECT_TRUE(m.positions.empty() && m.normals.empty() && m.uvs.empty() && m.indices.empty());
    EXPECT_TRUE(m.submeshes.empty());
}

// A finite corner beyond +-1e18 (the bound of every length in a project)
// made the scene's extent infinite; such triangles go like non-finite ones,
// while one at 1e17 stays (found by fuzz_4ds's render check, issue #42).
TEST(MeshCleanup, DropsTrianglesWithCornersBeyondTheLengthBound) {
    Mesh m = makeMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {3e38f, 0, 0}, {1e17f, 0, 0}, {0, 1e17f, 0}},
                      {0, 1, 3, 0, 4, 5, 0, 1, 2});
    const MeshCleanupStats s = cleanupMesh(m);
    EXPECT_EQ(s.degenerateTrianglesDropped, 1u);
    EXPECT_EQ(m.triangleCount(), 2u);
    for (const glm::vec3& p : m.positions)
        EXPECT_LE(std::abs(p.x), 1e18f);
    expectValidOutput(m);
}

TEST(MeshCleanup, KeepsThinButRealTriangles) {
    // Slivers of 1:1e3 and 1:1e5, a tiny triangle far from the origin, and a
    // triangle repeated with the same corners (double-sided export): all real.
    Mesh m = makeMesh({{0, 0, 0},
                       {1000, 0, 0},
                       {500, 1, 0},
                       {0, 0, 1},
                       {1e5f, 0, 1},
                       {0, 1, 1},
                       {1000, 1000, 1000},
                       {1000.001f, 1000, 1000},
                       {1000, 1000.001f, 1000}},
                      {0, 1, 2, 3, 4, 5, 6, 7, 8, 0, 1, 2});
    const MeshCleanupStats s = cleanupMesh(m);
    EXPECT_EQ(s.degenerateTrianglesDropped, 0u);
    EXPECT_EQ(m.triangleCount(), 4u);
    expectValidOutput(m);
}

TEST(MeshCleanup, SubmeshesAroundDroppedTrianglesShiftDown) {
    Mesh m = makeMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {0, 0, 0, 0, 1, 2, 1, 1, 2, 0, 1, 2, 2, 2, 2});
    m.submeshes = {{0, 3, 0}, {3, 6, 1}, {9, 6, 2}};
    cleanupMesh(m);
    EXPECT_EQ(m.indices.size(), 6u);
    EXPECT_EQ(m.submeshes, (std::vector<Submesh>{{0, 3, 1}, {3, 3, 2}}));
}

// ---- normals ---------------------------------------------------------------

TEST(MeshCleanup, CubeWithoutNormalsGetsFlatFacesWithHardEdges) {
    Mesh m = cube();
    const MeshCleanupStats s = cleanupMesh(m);
    EXPECT_TRUE(s.normalsGenerated);
    EXPECT_EQ(s.verticesBefore, 8u);
    EXPECT_EQ(s.verticesAfter, 24u) << "each corner splits into one vertex per face";
    EXPECT_TRUE(m.tangents.empty()) << "no uvs, no tangents";
    ASSERT_EQ(m.triangleCount(), 12u);
    for (std::size_t t = 0; t < 12; ++t) {
        const glm::vec3 face = faceNormal(m, t);
        EXPECT_GT(glm::dot(face, corner(m, t, 0)), 0.0f) << "outward";
        for (std::size_t k = 0; k < 3; ++k) {
            const glm::vec3 n = m.normals[m.indices[3 * t + k]];
            EXPECT_NEAR(glm::distance(n, face), 0.0f, 1e-6f) << "triangle " << t << " corner " << k;
        }
    }
    expectValidOutput(m);
    expectIdempotent(m);
}

TEST(MeshCleanup, CreaseAngleAboveNinetyDegreesSmoothsTheCube) {
    Mesh m = cube();
    const MeshCleanupStats s = cleanupMesh(m, {.creaseAngleDegrees = 100.0f});
    EXPECT_EQ(s.verticesAfter, 8u);
    for (std::size_t v = 0; v < m.positions.size(); ++v)
        EXPECT_GT(glm::dot(m.normals[v], glm::normalize(m.positions[v])), 0.9999f) << "vertex " << v;
    expectValidOutput(m);
}

TEST(MeshCleanup, UvSphereGetsSmoothNormalsAcrossItsSeam) {
    Mesh m = uvSphere();
    const std::size_t before = m.positions.size();
    const MeshCleanupStats s = cleanupMesh(m);
    EXPECT_TRUE(s.normalsGenerated);
    EXPECT_EQ(s.degenerateTrianglesDropped, 0u);
    EXPECT_EQ(s.verticesAfter, before) << "smooth and not mirrored: no vertex splits";
    for (std::size_t v = 0; v < m.positions.size(); ++v)
        EXPECT_GT(glm::dot(m.normals[v], glm::normalize(m.positions[v])), 0.999f) << "vertex " << v;
    // The seam's two copies of a point get the very same normal: no visible crease.
    for (std::size_t a = 0; a < m.positions.size(); ++a)
        for (std::size_t b = a + 1; b < m.positions.size(); ++b)
            if (m.positions[a] == m.positions[b]) {
                EXPECT_EQ(m.normals[a], m.normals[b]) << a << " and " << b;
            }
    expectValidOutput(m);
    expectIdempotent(m);
}

TEST(MeshCleanup, RepairsOnlyTheInvalidNormals) {
    Mesh m = cube();
    cleanupMesh(m); // flat normals, 24 vertices
    Mesh broken = m;
    broken.normals[0] = glm::vec3(kNaN, 0, 0);
    broken.normals[5] = glm::vec3(0.0f);
    broken.normals[7] *= 3.0f; // valid but not unit: renormalised, not counted
    const MeshCleanupStats s = cleanupMesh(broken);
    EXPECT_EQ(s.invalidNormalsRepaired, 2u);
    EXPECT_FALSE(s.normalsGenerated);
    EXPECT_EQ(broken.positions.size(), 24u);
    for (std::size_t v = 0; v < 24; ++v)
        EXPECT_NEAR(glm::distance(broken.normals[v], m.normals[v]), 0.0f, 1e-6f) << "vertex " << v;
    expectValidOutput(broken);
}

TEST(MeshCleanup, NonManifoldFanKeepsEveryTriangle) {
    // Four fins on the edge (0,0,0)-(0,0,1), 90 degrees apart: OpenMesh's
    // halfedge structure can hold two of them.
    Mesh m = makeMesh({{0, 0, 0}, {0, 0, 1}, {1, 0, 0.5f}, {0, 1, 0.5f}, {-1, 0, 0.5f}, {0, -1, 0.5f}},
                      {0, 1, 2, 1, 0, 3, 0, 1, 4, 1, 0, 5});
    CerrCapture cerr;
    const MeshCleanupStats s = cleanupMesh(m);
    EXPECT_EQ(cerr.text(), "") << "OpenMesh must not be left to complain";
    EXPECT_EQ(s.degenerateTrianglesDropped, 0u);
    ASSERT_EQ(m.triangleCount(), 4u);
    for (std::size_t t = 0; t < 4; ++t)
        for (std::size_t k = 0; k < 3; ++k)
            EXPECT_NEAR(glm::distance(m.normals[m.indices[3 * t + k]], faceNormal(m, t)), 0.0f, 1e-6f)
                << "fins 90 degrees apart stay flat: triangle " << t;
    expectValidOutput(m);
    expectIdempotent(m);
}

TEST(MeshCleanup, FaceAtAClosedFanIsKept) {
    // A closed fan around (0,0,0) leaves no gap there for a fifth face
    // ("complex vertex" in OpenMesh), plus a bow-tie at (1,0,0).
    Mesh m = makeMesh(
        {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}, {0, 0, 1}, {1, 0, 1}, {2, 0, 0}, {2, 1, 0}},
        {0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 1, 0, 5, 6, 1, 7, 8});
    CerrCapture cerr;
    const MeshCleanupStats s = cleanupMesh(m);
    EXPECT_EQ(cerr.text(), "");
    EXPECT_EQ(s.degenerateTrianglesDropped, 0u);
    ASSERT_EQ(m.triangleCount(), 6u);
    EXPECT_NEAR(glm::distance(m.normals[m.indices[12]], glm::vec3(0, 1, 0)), 0.0f, 1e-6f);
    for (std::size_t i : {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 15, 16, 17})
        EXPECT_NEAR(glm::distance(m.normals[m.indices[i]], glm::vec3(0, 0, 1)), 0.0f, 1e-6f)
            << "corner " << i;
    expectValidOutput(m);
}

TEST(MeshCleanup, RejectedDuplicateFaceIsSmoothedLikeItsTwin) {
    // Two triangles folded 20 degrees along the edge 0-1, and the first one
    // again (same corners, same winding): the copy cannot join the halfedge
    // structure, yet its corners on the fold are smoothed too.
    const float fold = glm::radians(20.0f);
    Mesh m = makeMesh({{0, 0, 0}, {1, 0, 0}, {0.5f, 1, 0}, {0.5f, -std::cos(fold), std::sin(fold)}},
                      {0, 1, 2, 1, 0, 3, 0, 1, 2});
    CerrCapture cerr;
    cleanupMesh(m);
    EXPECT_EQ(cerr.text(), "");
    ASSERT_EQ(m.triangleCount(), 3u);
    const glm::vec3 flat = faceNormal(m, 2);
    for (std::size_t k = 0; k < 2; ++k) { // the corners on the fold
        const glm::vec3 copy = m.normals[m.indices[6 + k]];
        const glm::vec3 twin = m.normals[m.indices[k]];
        EXPECT_GT(glm::dot(copy, twin), 0.995f);
        EXPECT_LT(glm::dot(copy, flat), std::cos(glm::radians(1.0f))) << "tilted towards the other side";
    }
    expectValidOutput(m);
}

TEST(MeshCleanup, PositionOnlyARejectedFaceUsesGetsItsFaceNormal) {
    // The second triangle runs along the edge 0-1 in the same direction as
    // the first (a complex edge), so OpenMesh refuses it; its third corner,
    // (0.5, 1, tan 20 deg), is a position no other triangle uses, so the
    // halfedge mesh holds a vertex there without any halfedge. OpenMesh 9's
    // counter-clockwise circulator asserted on it (fuzz_gltf, a mutated
    // Box.glb) and reads halfedge -1 with asserts off.
    const float tilt = std::tan(glm::radians(20.0f));
    Mesh m = makeMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.5f, 1, tilt}}, {0, 1, 2, 0, 1, 3});
    CerrCapture cerr;
    const MeshCleanupStats s = cleanupMesh(m);
    EXPECT_EQ(cerr.text(), "");
    EXPECT_EQ(s.degenerateTrianglesDropped, 0u);
    EXPECT_TRUE(s.normalsGenerated);
    ASSERT_EQ(m.triangleCount(), 2u);
    const glm::vec3 up(0, 0, 1);
    const glm::vec3 tilted = faceNormal(m, 1); // (0, -sin 20, cos 20)
    EXPECT_NEAR(glm::dot(tilted, up), std::cos(glm::radians(20.0f)), 1e-6f);
    for (std::size_t k = 0; k < 3; ++k)
        EXPECT_NEAR(glm::distance(m.normals[m.indices[k]], up), 0.0f, 1e-6f)
            << "first triangle, corner " << k;
    EXPECT_NEAR(glm::distance(m.normals[m.indices[5]], tilted), 0.0f, 1e-6f)
        << "the lone corner keeps its own face's normal";
    for (std::size_t k = 3; k < 5;
         ++k) { // on the shared edge: smoothed with the first triangle (20 < 60 degrees)
        const glm::vec3 n = m.normals[m.indices[k]];
        EXPECT_GT(glm::dot(n, up), glm::dot(tilted, up)) << "corner " << k;
        EXPECT_GT(glm::dot(n, tilted), glm::dot(up, tilted)) << "corner " << k;
    }
    expectValidOutput(m);
    expectIdempotent(m);
}

TEST(MeshCleanup, CornellBoxWithoutNormalsGetsItsHardEdgesBack) {
    const lpv::scene::Project project = lpv::scene::makeCornellBoxProject();
    ASSERT_FALSE(project.scene.meshes.empty());
    for (const Mesh& original : project.scene.meshes) {
        SCOPED_TRACE(original.name);
        Mesh m = original;
        m.normals.clear();
        m.tangents.clear();
        const MeshCleanupStats s = cleanupMesh(m);
        EXPECT_EQ(s.degenerateTrianglesDropped, 0u);
        EXPECT_EQ(m.triangleCount(), original.triangleCount());
        // Every corner's normal is its wall's (the generator's) normal.
        for (std::size_t i = 0; i < m.indices.size(); ++i)
            EXPECT_GT(glm::dot(m.normals[m.indices[i]], original.normals[original.indices[i]]), 0.9999f)
                << "corner " << i;
        expectValidOutput(m);
        expectIdempotent(m);
    }
}

// ---- tangents --------------------------------------------------------------

TEST(MeshCleanup, TangentsFollowIncreasingU) {
    Mesh m = sixVertexQuad();
    cleanupMesh(m);
    ASSERT_EQ(m.tangents.size(), 4u);
    for (const glm::vec4& t : m.tangents)
        EXPECT_EQ(t, glm::vec4(1, 0, 0, 1));
}

TEST(MeshCleanup, MirroredUvsSplitTheSharedVerticesByHandedness) {
    // Two quads side by side; the right one mirrors u, as modellers do to
    // reuse one half of a texture. Vertices 1 and 2 sit on the mirror line.
    Mesh m = makeMesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0, 0}, {2, 1, 0}},
                      {0, 1, 2, 0, 2, 3, 1, 4, 5, 1, 5, 2});
    m.normals.assign(6, glm::vec3(0, 0, 1));
    m.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}, {0, 1}};
    const MeshCleanupStats s = cleanupMesh(m);
    EXPECT_TRUE(s.tangentsGenerated);
    EXPECT_EQ(s.verticesAfter, 8u) << "the two vertices on the mirror line split";
    ASSERT_EQ(m.triangleCount(), 4u);
    for (std::size_t t = 0; t < 4; ++t) {
        const float w = t < 2 ? 1.0f : -1.0f;
        const glm::vec3 along = t < 2 ? glm::vec3(1, 0, 0) : glm::vec3(-1, 0, 0);
        for (std::size_t k = 0; k < 3; ++k) {
            const glm::vec4 tangent = m.tangents[m.indices[3 * t + k]];
            EXPECT_EQ(tangent.w, w) << "triangle " << t;
            EXPECT_GT(glm::dot(glm::vec3(tangent), along), 0.9999f) << "triangle " << t;
            // w * cross(n, t) is the direction of increasing v: +y on both sides.
            const glm::vec3 bitangent =
                tangent.w * glm::cross(m.normals[m.indices[3 * t + k]], glm::vec3(tangent));
            EXPECT_GT(bitangent.y, 0.9999f);
        }
    }
    expectValidOutput(m);
    expectIdempotent(m);
}

TEST(MeshCleanup, UvSphereTangentsAreRightHandedAndFollowU) {
    Mesh m = uvSphere();
    cleanupMesh(m);
    ASSERT_EQ(m.tangents.size(), m.positions.size());
    for (std::size_t v = 0; v < m.positions.size(); ++v) {
        SCOPED_TRACE("vertex " + std::to_string(v));
        EXPECT_EQ(m.tangents[v].w, 1.0f);
        // d position / d phi, horizontal; at the poles the vertex's own u says where.
        const glm::vec3 p = m.positions[v];
        const double phi = 2 * std::numbers::pi * m.uvs[v].x;
        const glm::vec3 alongU = glm::vec3(float(-std::sin(phi)), 0.0f, float(-std::cos(phi)));
        EXPECT_GT(glm::dot(glm::vec3(m.tangents[v]), alongU), 0.99f) << p.x << " " << p.y << " " << p.z;
    }
}

TEST(MeshCleanup, DegenerateUvsStillGiveAValidTangent) {
    Mesh m = makeMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {3, 0, 0}, {4, 0, 0}, {3, 0, 1}}, {0, 1, 2, 3, 4, 5});
    m.uvs = {{0.5f, 0.5f}, {0.5f, 0.5f}, {0.5f, 0.5f}, {0, 0}, {1, 1}, {2, 2}}; // a point, a line
    const MeshCleanupStats s = cleanupMesh(m);
    EXPECT_TRUE(s.tangentsGenerated);
    ASSERT_EQ(m.tangents.size(), 6u);
    for (const glm::vec4& t : m.tangents)
        EXPECT_EQ(t.w, 1.0f);
    expectValidOutput(m);
    expectIdempotent(m);
}

TEST(MeshCleanup, InvalidTangentsAreReplacedAndValidOnesKept) {
    Mesh m = sixVertexQuad();
    cleanupMesh(m);
    Mesh broken = m;
    broken.tangents[1] = glm::vec4(kNaN, 0, 0, 1);
    broken.tangents[2] = glm::vec4(1, 0, 0, 0); // no handedness
    const MeshCleanupStats s = cleanupMesh(broken);
    EXPECT_TRUE(s.tangentsGenerated);
    EXPECT_TRUE(broken == m);
}

TEST(MeshCleanup, GenerateTangentsOffLeavesThemAlone) {
    Mesh m = sixVertexQuad();
    const MeshCleanupStats s = cleanupMesh(m, {.generateTangents = false});
    EXPECT_FALSE(s.tangentsGenerated);
    EXPECT_TRUE(m.tangents.empty());
}

// ---- anything at all ---------------------------------------------------------

// Random soups of shared, duplicated, collinear and non-finite corners with
// broken normals and uvs: every output is valid, triangles are only lost to
// degeneracy, the same input gives the same bytes, and a second pass is a no-op.
TEST(MeshCleanup, RandomSoupsGiveValidDeterministicIdempotentOutput) {
    std::mt19937 rng(20240611u);
    const auto pick = [&](std::uint32_t n) { return std::uint32_t(rng() % n); };
    for (int round = 0; round < 40; ++round) {
        SCOPED_TRACE("round " + std::to_string(round));
        Mesh m;
        const std::uint32_t vertexCount = 6 + pick(40);
        for (std::uint32_t v = 0; v < vertexCount; ++v) {
            glm::vec3 p(float(pick(4)), float(pick(4)), float(pick(3)) * 0.5f);
            if (pick(30) == 0)
                p.y = pick(2) ? kNaN : -kInf;
            m.positions.push_back(p);
        }
        if (round % 2 == 0)
            for (std::uint32_t v = 0; v < vertexCount; ++v) {
                const glm::vec3 choices[] = {{0, 0, 1}, {0, 1, 0}, {0.6f, 0.8f, 0}, {0, 0, 0}, {kNaN, 0, 1}};
                m.normals.push_back(choices[pick(5)]);
            }
        if (round % 3 != 0)
            for (std::uint32_t v = 0; v < vertexCount; ++v)
                m.uvs.push_back({float(pick(3)) * 0.5f, float(pick(3)) * 0.5f});
        const std::uint32_t triangles = 10 + pick(200);
        for (std::uint32_t i = 0; i < 3 * triangles; ++i)
            m.indices.push_back(pick(vertexCount));
        const std::uint32_t split = 3 * pick(triangles);
        m.submeshes = {{0, split, 0}, {split, 3 * triangles - split, 1}};

        Mesh copy = m;
        CerrCapture cerr;
        const MeshCleanupStats s = cleanupMesh(m);
        const MeshCleanupStats s2 = cleanupMesh(copy);
        EXPECT_EQ(cerr.text(), "");
        EXPECT_TRUE(m == copy) << "deterministic";
        EXPECT_EQ(s.verticesAfter, s2.verticesAfter);
        EXPECT_EQ(m.triangleCount(), triangles - s.degenerateTrianglesDropped);
        std::uint32_t covered = 0;
        for (const Submesh& sub : m.submeshes)
            covered += sub.indexCount;
        EXPECT_EQ(covered, m.indices.size());
        expectValidOutput(m);
        expectIdempotent(m);
    }
}

// ---- real data -------------------------------------------------------------

TEST(MeshCleanup, SibenikKeepsEveryRealTriangleWithValidFrames) {
    const std::filesystem::path file =
        std::filesystem::path(lpv::test::kSharedScenesDir) / "4ds" / "sibenik.4ds";
    std::ifstream in(file, std::ios::binary);
    const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                                          std::istreambuf_iterator<char>());
    ASSERT_FALSE(bytes.empty()) << file;
    const auto r = lpv::importers::readFourDs(bytes, file, {});
    ASSERT_TRUE(r.has_value()) << r.error().describe();
    std::size_t trianglesBefore = 0, trianglesAfter = 0, dropped = 0, invalidNormals = 0;
    for (const Mesh& original : r->scene.meshes) {
        SCOPED_TRACE(original.name);
        Mesh m = original;
        CerrCapture cerr;
        const MeshCleanupStats s = cleanupMesh(m);
        EXPECT_EQ(cerr.text(), "");
        EXPECT_EQ(m.triangleCount(), original.triangleCount() - s.degenerateTrianglesDropped);
        EXPECT_FALSE(s.normalsGenerated) << "the file has normals";
        EXPECT_TRUE(s.tangentsGenerated) << "uvs and normals but no tangents";
        ASSERT_EQ(m.tangents.size(), m.positions.size());
        ASSERT_EQ(m.uvs.size(), m.positions.size());
        std::uint32_t covered = 0;
        for (const Submesh& sub : m.submeshes)
            covered += sub.indexCount;
        EXPECT_EQ(covered, m.indices.size()) << "the face groups still cover every triangle";
        expectValidOutput(m);
        trianglesBefore += original.triangleCount();
        trianglesAfter += m.triangleCount();
        dropped += s.degenerateTrianglesDropped;
        invalidNormals += s.invalidNormalsRepaired;
    }
    EXPECT_EQ(trianglesBefore, 72524u);
    EXPECT_EQ(trianglesAfter, trianglesBefore - dropped);
    // Measured: 8 triangles of exactly zero area and 3 whose flattest angle
    // has a sine of about 1e-7 (collinear up to float rounding); the next
    // thinnest keep a sine above 1e-6.
    EXPECT_EQ(dropped, 11u);
    EXPECT_EQ(invalidNormals, 18u) << "normals of (nearly) zero length in the file";
}

} // namespace
