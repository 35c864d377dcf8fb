// Degenerate triangles and the submesh ranges around them (MeshCleanupDetail.h).
#include "MeshCleanupDetail.h"

#include "lpv/scene/ValueChecks.h"

#include <algorithm>
#include <cmath>

namespace lpv::importers::detail {
namespace {

// A corner the renderers can place: finite and within +-kMaxLength (1e18),
// the bound every other length in a project has (ValueChecks.h). A finite
// 3e38 corner made the scene's extent infinite, and with it the LPV cells
// and shadow frusta (found by fuzz_4ds's render check, issue #42).
bool isUsablePosition(const glm::vec3& p) {
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(p[i]) || std::abs(double(p[i])) > scene::kMaxLength)
            return false;
    return true;
}

// A triangle whose |cross| is below this fraction of its longest squared edge
// has no area: the sine of its flattest angle is about 1e-6 or less, where
// float corners no longer define a plane (rounded collinear corners give ~1e-7).
constexpr double kMinRelativeArea = 1e-6;

bool hasArea(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2) {
    // Double precision: exactly collinear float corners then give exactly zero.
    const glm::dvec3 e0 = glm::dvec3(p1) - glm::dvec3(p0);
    const glm::dvec3 e1 = glm::dvec3(p2) - glm::dvec3(p0);
    const glm::dvec3 e2 = glm::dvec3(p2) - glm::dvec3(p1);
    const double longest = std::max({glm::dot(e0, e0), glm::dot(e1, e1), glm::dot(e2, e2)});
    return glm::length(glm::cross(e0, e1)) > kMinRelativeArea * longest;
}

bool isDegenerate(const scene::Mesh& mesh, std::size_t firstIndex) {
    const std::uint32_t a = mesh.indices[firstIndex], b = mesh.indices[firstIndex + 1],
                        c = mesh.indices[firstIndex + 2];
    const std::size_t n = mesh.positions.size();
    if (a >= n || b >= n || c >= n || a == b || b == c || a == c)
        return true;
    const glm::vec3 &p0 = mesh.positions[a], &p1 = mesh.positions[b], &p2 = mesh.positions[c];
    return !isUsablePosition(p0) || !isUsablePosition(p1) || !isUsablePosition(p2) || !hasArea(p0, p1, p2);
}

} // namespace

std::vector<std::uint8_t> survivingTriangles(const scene::Mesh& mesh) {
    std::vector<std::uint8_t> keep(mesh.triangleCount());
    for (std::size_t t = 0; t < keep.size(); ++t)
        keep[t] = isDegenerate(mesh, 3 * t) ? 0 : 1;
    return keep;
}

// Counting survivors before each triangle works whatever the layout of the
// ranges (gaps, overlaps, any order).
void remapSubmeshes(std::vector<scene::Submesh>& submeshes, const std::vector<std::uint8_t>& keep) {
    std::vector<std::uint32_t> keptBefore(keep.size() + 1, 0);
    for (std::size_t t = 0; t < keep.size(); ++t)
        keptBefore[t + 1] = keptBefore[t] + keep[t];
    const auto triangleAt = [&](std::uint64_t index) {
        return std::min<std::uint64_t>(index / 3, keep.size());
    };
    std::vector<scene::Submesh> out;
    for (const scene::Submesh& s : submeshes) {
        const std::uint64_t first = triangleAt(s.firstIndex);
        const std::uint64_t end = triangleAt(std::uint64_t(s.firstIndex) + s.indexCount);
        const std::uint32_t count = keptBefore[end] - keptBefore[first];
        if (count > 0)
            out.push_back({.firstIndex = 3 * keptBefore[first],
                           .indexCount = 3 * count,
                           .materialIndex = s.materialIndex});
    }
    submeshes = std::move(out);
}

} // namespace lpv::importers::detail
