#include "lpv/importers/ImportUnits.h"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

namespace lpv::importers {
namespace {

// ---- the thresholds of the size note, in one place --------------------------
//
// A scene assumed to be in metres (OBJ, 3DS, PLY and the other formats that
// state no unit) is most likely in centimetres when it is at least 100 units
// in every direction (a room or a building in centimetres; a real 100 m cube
// of geometry is rare, a flat city or terrain is not cubic) or more than 1,000
// units along its longest side (10 m in centimetres, the Crytek Sponza's
// 3,800; 1 km in metres). Below 5 cm along its longest side it is most likely
// in a larger unit, or scaled down on export.
constexpr double kSmallestSideSuggestingCentimetres = 100.0;
constexpr double kLargestSideSuggestingCentimetres = 1000.0;
constexpr double kLargestSideTooSmall = 0.05;
// Beyond 100,000 units the centimetres would make a scene over 1 km: then
// millimetres are the better guess.
constexpr double kLargestSideSuggestingMillimetres = 1e5;
// A file that states its unit (glTF, 4ds, FBX, Collada) is believed unless
// its size is absurd: over 1,000 km or under 1 mm.
constexpr double kStatedLargestAbsurd = 1e6;
constexpr double kStatedLargestTooSmall = 1e-3;

// ---- recentring -------------------------------------------------------------
//
// A float vertex |c| from its origin keeps log2(|c| / r) fewer bits for a
// mesh of radius r than one at its origin: beyond 64 radii the shape has
// lost 6 of its 24 bits, the point from which recentring (which costs nothing
// at render time) is worth changing the file's layout.
constexpr double kFarRadii = 64.0;

// "2,000" for sizes of 100 and more, "0.02" (3 significant digits) below.
std::string formatSize(double v) {
    char text[64];
    if (v < 100.0) {
        std::snprintf(text, sizeof text, "%.3g", v);
        return text;
    }
    std::snprintf(text, sizeof text, "%.0f", v);
    const std::string digits = text;
    std::string out;
    for (std::size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0)
            out += ',';
        out += digits[i];
    }
    return out;
}

// Union-find over mesh indices.
std::size_t findRoot(std::vector<std::size_t>& parent, std::size_t i) {
    while (parent[i] != i) {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    return i;
}

bool validMesh(const scene::Scene& s, int mesh) {
    return mesh >= 0 && std::size_t(mesh) < s.meshes.size();
}

// The meshes an object draws: its main mesh and its LODs (valid indices only).
std::vector<std::size_t> meshesOf(const scene::Scene& s, const scene::Object& o) {
    std::vector<std::size_t> out;
    if (validMesh(s, o.mesh))
        out.push_back(std::size_t(o.mesh));
    for (const scene::LodLevel& lod : o.lods)
        if (validMesh(s, lod.mesh))
            out.push_back(std::size_t(lod.mesh));
    return out;
}

} // namespace

std::optional<double> metresPerUnit(std::string_view name) {
    static constexpr std::array<std::pair<std::string_view, double>, 5> kUnits{
        {{"mm", 0.001}, {"cm", 0.01}, {"m", 1.0}, {"in", 0.0254}, {"ft", 0.3048}}};
    for (const auto& [unit, metres] : kUnits)
        if (unit == name)
            return metres;
    return std::nullopt;
}

const char* unitNames() {
    return "mm, cm, m, in, ft";
}

std::optional<std::string> sizeNote(const scene::Bounds& bounds, UnitKnowledge knew) {
    if (bounds.empty() || knew == UnitKnowledge::GivenByUser)
        return std::nullopt;
    const glm::dvec3 size = glm::dvec3(bounds.size());
    const double largest = std::max({size.x, size.y, size.z});
    const double smallest = std::min({size.x, size.y, size.z});
    if (!std::isfinite(largest))
        return std::nullopt;
    const std::string across = formatSize(largest);
    if (knew == UnitKnowledge::StatedByFile) {
        if (largest > kStatedLargestAbsurd)
            return "the scene is " + across +
                   " m across in the unit its file states: if it is in millimetres, import with --unit mm";
        if (largest > 0.0 && largest < kStatedLargestTooSmall)
            return "the scene is " + across +
                   " m across in the unit its file states: if that is not its size, import with --scale S "
                   "(S metres per unit of the file)";
        return std::nullopt;
    }
    if (largest > kLargestSideSuggestingCentimetres || smallest >= kSmallestSideSuggestingCentimetres) {
        if (largest > kLargestSideSuggestingMillimetres)
            return "the scene is " + across +
                   " units across: if these are millimetres, import with --unit mm (metres were assumed)";
        return "the scene is " + across +
               " units across: if these are centimetres, import with --unit cm (metres were assumed)";
    }
    if (largest > 0.0 && largest < kLargestSideTooSmall)
        return "the scene is " + across +
               " units across: if that is not its size in metres, import with --scale S (S metres per unit "
               "of the file, 1000 for kilometres)";
    return std::nullopt;
}

RecentreStats recentreFarMeshes(scene::Scene& s) {
    RecentreStats stats;
    const std::size_t meshCount = s.meshes.size();
    // Meshes one object draws (main and LODs) must move together: one group.
    std::vector<std::size_t> parent(meshCount);
    std::iota(parent.begin(), parent.end(), std::size_t(0));
    std::vector<bool> used(meshCount, false);
    for (const scene::Object& o : s.objects) {
        const std::vector<std::size_t> meshes = meshesOf(s, o);
        for (std::size_t m : meshes) {
            used[m] = true;
            parent[findRoot(parent, m)] = findRoot(parent, meshes.front());
        }
    }
    // Each group's bounds, in double.
    std::vector<glm::dvec3> lo(meshCount, glm::dvec3(std::numeric_limits<double>::max()));
    std::vector<glm::dvec3> hi(meshCount, glm::dvec3(std::numeric_limits<double>::lowest()));
    for (std::size_t m = 0; m < meshCount; ++m) {
        if (!used[m])
            continue;
        const std::size_t g = findRoot(parent, m);
        for (const glm::vec3& p : s.meshes[m].positions) {
            lo[g] = glm::min(lo[g], glm::dvec3(p));
            hi[g] = glm::max(hi[g], glm::dvec3(p));
        }
    }
    // The offset of each group that is far from its origin; the centre is
    // rounded to float first, so that an object at the world origin gets
    // exactly c as its translation.
    std::vector<std::optional<glm::dvec3>> offset(meshCount);
    for (std::size_t g = 0; g < meshCount; ++g) {
        if (findRoot(parent, g) != g || lo[g].x > hi[g].x)
            continue;
        const glm::dvec3 centre = glm::dvec3(glm::vec3(0.5 * (lo[g] + hi[g])));
        const double radius = 0.5 * glm::length(hi[g] - lo[g]);
        const double distance = glm::length(centre);
        if (!std::isfinite(distance) || distance <= 0.0 || distance <= kFarRadii * radius)
            continue;
        offset[g] = centre;
    }
    for (std::size_t m = 0; m < meshCount; ++m) {
        if (!used[m])
            continue;
        const auto& c = offset[findRoot(parent, m)];
        if (!c)
            continue;
        for (glm::vec3& p : s.meshes[m].positions)
            p = glm::vec3(glm::dvec3(p) - *c);
        ++stats.meshes;
        stats.farthest = std::max(stats.farthest, glm::length(*c));
    }
    if (stats.meshes == 0)
        return stats;
    // New translations from the old ones: world = T + R*S*(v' + c), so
    // T' = T + R*S*c; a child's local frame sat in its parent's, which moved
    // by c, so it gets T - c.
    std::vector<glm::vec3> translation(s.objects.size());
    for (std::size_t i = 0; i < s.objects.size(); ++i) {
        const scene::Object& o = s.objects[i];
        glm::dvec3 t(o.transform.translation);
        const std::vector<std::size_t> meshes = meshesOf(s, o);
        if (!meshes.empty())
            if (const auto& c = offset[findRoot(parent, meshes.front())])
                t += glm::dquat(o.transform.rotation) * (glm::dvec3(o.transform.scale) * *c);
        if (o.parent >= 0 && std::size_t(o.parent) < s.objects.size()) {
            const std::vector<std::size_t> parentMeshes = meshesOf(s, s.objects[std::size_t(o.parent)]);
            if (!parentMeshes.empty())
                if (const auto& c = offset[findRoot(parent, parentMeshes.front())])
                    t -= *c;
        }
        translation[i] = glm::vec3(t);
    }
    for (std::size_t i = 0; i < s.objects.size(); ++i)
        s.objects[i].transform.translation = translation[i];
    return stats;
}

} // namespace lpv::importers
