// Meshing: triangles -> (quads where two coplanar triangles form one) ->
// a regular grid of patches per source face, sized from edge lengths so two
// faces sharing an edge usually cut it at the same points (no T-junctions).
#include "lpv/radiosity/PatchMesh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

namespace lpv::radiosity {
namespace {

struct Corner {
    glm::vec3 p;
    glm::vec2 uv;
};

float triangleArea(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    return 0.5f * glm::length(glm::cross(b - a, c - a));
}

// At most 32768 cuts per edge: a billion patches per face, far over any
// radiosity.maxPatches, and nu * nv stays an int at any patch area.
constexpr float kMaxCuts = 32768.0f;

// The 1e-4 is of a cut (unitless): a length that is a whole number of steps up
// to float rounding is not cut once more.
int cutsFor(float length, float step) {
    return std::max(1, int(std::min(std::ceil(length / step - 1e-4f), kMaxCuts)));
}

// Zero area up to float rounding of its own edges (relative, so a 1 um
// triangle of a centimetre scene is kept and a needle of a kilometre one is not).
bool degenerate(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    const float longest = std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
    const float area = triangleArea(a, b, c);
    return !(area > 1e-12f * longest * longest);
}

// Source face -> patches, appended to `out`.
class Subdivider {
  public:
    // With `countOnly`, patches are counted there and not stored (countPatches).
    Subdivider(float maxArea, std::uint32_t material, std::uint32_t object, std::vector<Patch>& out,
               std::size_t* countOnly = nullptr)
        : maxArea_(maxArea), step_(std::sqrt(maxArea)), material_(material), object_(object), out_(out),
          countOnly_(countOnly) {}

    void quad(const std::array<Corner, 4>& q) {
        int nu = std::max(cutsFor(glm::length(q[1].p - q[0].p), step_),
                          cutsFor(glm::length(q[2].p - q[3].p), step_));
        int nv = std::max(cutsFor(glm::length(q[3].p - q[0].p), step_),
                          cutsFor(glm::length(q[2].p - q[1].p), step_));
        const float area = triangleArea(q[0].p, q[1].p, q[2].p) + triangleArea(q[0].p, q[2].p, q[3].p);
        while (area / float(nu * nv) > maxArea_ * 1.0001f && float(std::max(nu, nv)) < kMaxCuts) {
            ++nu;
            ++nv;
        }
        auto at = [&](int i, int j) {
            const float u = float(i) / float(nu), v = float(j) / float(nv);
            const float w0 = (1 - u) * (1 - v), w1 = u * (1 - v), w2 = u * v, w3 = (1 - u) * v;
            return Corner{w0 * q[0].p + w1 * q[1].p + w2 * q[2].p + w3 * q[3].p,
                          w0 * q[0].uv + w1 * q[1].uv + w2 * q[2].uv + w3 * q[3].uv};
        };
        for (int j = 0; j < nv; ++j)
            for (int i = 0; i < nu; ++i)
                emit({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)}, 4);
    }

    void triangle(const std::array<Corner, 3>& t) {
        int n = std::max({cutsFor(glm::length(t[1].p - t[0].p), step_),
                          cutsFor(glm::length(t[2].p - t[1].p), step_),
                          cutsFor(glm::length(t[0].p - t[2].p), step_)});
        const float area = triangleArea(t[0].p, t[1].p, t[2].p);
        n = std::max(n, int(std::min(std::ceil(std::sqrt(area / maxArea_) - 1e-4f), kMaxCuts)));
        auto at = [&](int i, int j) {
            const float u = float(i) / float(n), v = float(j) / float(n);
            return Corner{t[0].p + u * (t[1].p - t[0].p) + v * (t[2].p - t[0].p),
                          t[0].uv + u * (t[1].uv - t[0].uv) + v * (t[2].uv - t[0].uv)};
        };
        for (int j = 0; j < n; ++j)
            for (int i = 0; i + j < n; ++i) {
                emit({at(i, j), at(i + 1, j), at(i, j + 1), Corner{}}, 3);
                if (i + j < n - 1)
                    emit({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1), Corner{}}, 3);
            }
    }

  private:
    void emit(const std::array<Corner, 4>& c, std::uint8_t count) {
        Patch p;
        p.cornerCount = count;
        for (int k = 0; k < count; ++k) {
            p.corners[k] = c[k].p;
            p.uvs[k] = c[k].uv;
        }
        p.material = material_;
        p.object = object_;
        computePatchGeometry(p);
        if (p.area <= 0.0f)
            return;
        if (countOnly_)
            ++*countOnly_;
        else
            out_.push_back(p);
    }

    float maxArea_;
    float step_;
    std::uint32_t material_;
    std::uint32_t object_;
    std::vector<Patch>& out_;
    std::size_t* countOnly_;
};

// Triangles of one submesh in world space, paired into quads where the
// longest edges of two coplanar triangles coincide (the usual split of a quad).
void meshObject(const scene::Scene& scene, std::uint32_t objectIndex, float maxArea, PatchMesh& out,
                std::size_t* countOnly = nullptr) {
    const scene::Object& object = scene.objects[objectIndex];
    const scene::Mesh& mesh = scene.meshes[std::size_t(object.mesh)];
    const glm::mat4 world = scene.worldMatrix(int(objectIndex));
    std::vector<glm::vec3> positions(mesh.positions.size());
    for (std::size_t i = 0; i < positions.size(); ++i)
        positions[i] = glm::vec3(world * glm::vec4(mesh.positions[i], 1.0f));
    auto uvOf = [&](std::uint32_t i) { return mesh.uvs.empty() ? glm::vec2(0.0f) : mesh.uvs[i]; };
    // A mirroring transform flips the winding; keep corners counter-clockwise.
    const bool mirrored = glm::determinant(glm::mat3(world)) < 0.0f;

    for (const scene::Submesh& sub : mesh.submeshes) {
        std::vector<std::array<std::uint32_t, 3>> tris;
        for (std::uint32_t k = 0; k + 2 < sub.indexCount; k += 3) {
            std::array<std::uint32_t, 3> t{mesh.indices[sub.firstIndex + k],
                                           mesh.indices[sub.firstIndex + k + 1],
                                           mesh.indices[sub.firstIndex + k + 2]};
            if (mirrored)
                std::swap(t[1], t[2]);
            if (!degenerate(positions[t[0]], positions[t[1]], positions[t[2]]))
                tris.push_back(t);
        }
        // Longest edge of each triangle as (corner index of its start), and an
        // edge map keyed by the (welded by index) vertex pair.
        auto longest = [&](const std::array<std::uint32_t, 3>& t) {
            int best = 0;
            float bestLen = -1.0f;
            for (int e = 0; e < 3; ++e) {
                const float len = glm::length(positions[t[(e + 1) % 3]] - positions[t[e]]);
                if (len > bestLen) {
                    bestLen = len;
                    best = e;
                }
            }
            return best;
        };
        std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::size_t>> byEdge;
        std::vector<int> longestEdge(tris.size());
        for (std::size_t i = 0; i < tris.size(); ++i) {
            longestEdge[i] = longest(tris[i]);
            const auto a = tris[i][std::size_t(longestEdge[i])],
                       b = tris[i][std::size_t(longestEdge[i] + 1) % 3];
            byEdge[{std::min(a, b), std::max(a, b)}].push_back(i);
        }
        std::vector<bool> used(tris.size(), false);
        Subdivider subdivider(maxArea, sub.materialIndex, objectIndex, out.patches, countOnly);
        for (std::size_t i = 0; i < tris.size(); ++i) {
            if (used[i])
                continue;
            const auto& t = tris[i];
            const int e = longestEdge[i];
            const std::uint32_t a = t[std::size_t(e)], b = t[std::size_t(e + 1) % 3],
                                c = t[std::size_t(e + 2) % 3];
            const auto& candidates = byEdge[{std::min(a, b), std::max(a, b)}];
            bool merged = false;
            if (candidates.size() == 2) {
                const std::size_t j = candidates[0] == i ? candidates[1] : candidates[0];
                const auto& u = tris[j];
                const int ue = longestEdge[j];
                // The partner runs the shared edge the other way: (b, a, d).
                if (!used[j] && u[std::size_t(ue)] == b && u[std::size_t(ue + 1) % 3] == a) {
                    const std::uint32_t d = u[std::size_t(ue + 2) % 3];
                    const glm::vec3 n1 =
                        glm::normalize(glm::cross(positions[b] - positions[a], positions[c] - positions[a]));
                    const glm::vec3 n2 =
                        glm::normalize(glm::cross(positions[a] - positions[b], positions[d] - positions[b]));
                    if (glm::dot(n1, n2) > 0.9999f) {
                        subdivider.quad({Corner{positions[a], uvOf(a)}, Corner{positions[d], uvOf(d)},
                                         Corner{positions[b], uvOf(b)}, Corner{positions[c], uvOf(c)}});
                        used[i] = used[j] = true;
                        merged = true;
                        ++out.sourceQuads;
                    }
                }
            }
            if (!merged) {
                subdivider.triangle({Corner{positions[t[0]], uvOf(t[0])}, Corner{positions[t[1]], uvOf(t[1])},
                                     Corner{positions[t[2]], uvOf(t[2])}});
                used[i] = true;
                ++out.sourceTriangles;
            }
        }
    }
}

} // namespace

void computePatchGeometry(Patch& patch) {
    const auto& c = patch.corners;
    if (patch.cornerCount == 4) {
        const glm::vec3 n = glm::cross(c[2] - c[0], c[3] - c[1]);
        patch.area = 0.5f * glm::length(n);
        patch.normal = patch.area > 0.0f ? glm::normalize(n) : glm::vec3(0, 0, 1);
        patch.center = 0.25f * (c[0] + c[1] + c[2] + c[3]);
    } else {
        const glm::vec3 n = glm::cross(c[1] - c[0], c[2] - c[0]);
        patch.area = 0.5f * glm::length(n);
        patch.normal = patch.area > 0.0f ? glm::normalize(n) : glm::vec3(0, 0, 1);
        patch.center = (c[0] + c[1] + c[2]) / 3.0f;
    }
}

float PatchMesh::totalArea() const {
    double sum = 0.0;
    for (const Patch& p : patches)
        sum += p.area;
    return float(sum);
}

std::size_t countPatches(const scene::Scene& scene, const MeshingOptions& options) {
    PatchMesh none; // receives the quad and triangle counts only
    std::size_t count = 0;
    // A float guard only (the area divides): any positive area is a length squared of some scene.
    const float maxArea = std::max(options.maxPatchArea, std::numeric_limits<float>::min());
    for (std::uint32_t i = 0; i < scene.objects.size(); ++i) {
        const scene::Object& o = scene.objects[i];
        if (!o.visible || o.mesh < 0 || std::size_t(o.mesh) >= scene.meshes.size())
            continue;
        meshObject(scene, i, maxArea, none, &count);
    }
    return count;
}

PatchMesh buildPatchMesh(const scene::Scene& scene, const MeshingOptions& options) {
    PatchMesh out;
    // A float guard only (the area divides): any positive area is a length squared of some scene.
    const float maxArea = std::max(options.maxPatchArea, std::numeric_limits<float>::min());
    for (std::uint32_t i = 0; i < scene.objects.size(); ++i) {
        const scene::Object& o = scene.objects[i];
        if (!o.visible || o.mesh < 0 || std::size_t(o.mesh) >= scene.meshes.size())
            continue;
        meshObject(scene, i, maxArea, out);
    }
    buildAdjacency(out);
    return out;
}

PatchMesh refinePatches(const PatchMesh& mesh, const std::vector<std::uint32_t>& which,
                        std::vector<std::uint32_t>& parentOf) {
    std::vector<bool> split(mesh.patches.size(), false);
    for (std::uint32_t i : which)
        if (i < split.size())
            split[i] = true;
    PatchMesh out;
    out.sourceQuads = mesh.sourceQuads;
    out.sourceTriangles = mesh.sourceTriangles;
    parentOf.clear();
    for (std::uint32_t i = 0; i < mesh.patches.size(); ++i) {
        const Patch& p = mesh.patches[i];
        if (!split[i]) {
            out.patches.push_back(p);
            parentOf.push_back(i);
            continue;
        }
        // Half the longest side in each direction gives four children.
        const std::size_t before = out.patches.size();
        Subdivider sub(p.area / 4.0f, p.material, p.object, out.patches);
        if (p.cornerCount == 4)
            sub.quad({Corner{p.corners[0], p.uvs[0]}, Corner{p.corners[1], p.uvs[1]},
                      Corner{p.corners[2], p.uvs[2]}, Corner{p.corners[3], p.uvs[3]}});
        else
            sub.triangle({Corner{p.corners[0], p.uvs[0]}, Corner{p.corners[1], p.uvs[1]},
                          Corner{p.corners[2], p.uvs[2]}});
        parentOf.insert(parentOf.end(), out.patches.size() - before, i);
    }
    buildAdjacency(out);
    return out;
}

} // namespace lpv::radiosity
