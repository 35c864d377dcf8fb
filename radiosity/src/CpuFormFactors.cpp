#include "lpv/radiosity/FormFactors.h"

#include <cmath>
#include <numbers>

namespace lpv::radiosity {
namespace {

// Sutherland-Hodgman against the plane dot(normal, x - point) >= 0.
std::vector<glm::dvec3> clipToFront(const std::vector<glm::dvec3>& polygon, const glm::dvec3& point,
                                    const glm::dvec3& normal) {
    std::vector<glm::dvec3> out;
    const std::size_t n = polygon.size();
    for (std::size_t k = 0; k < n; ++k) {
        const glm::dvec3& a = polygon[k];
        const glm::dvec3& b = polygon[(k + 1) % n];
        const double da = glm::dot(normal, a - point), db = glm::dot(normal, b - point);
        if (da >= 0.0)
            out.push_back(a);
        if ((da >= 0.0) != (db >= 0.0))
            out.push_back(a + (b - a) * (da / (da - db)));
    }
    return out;
}

// Moller-Trumbore; true when the segment origin + t*dir, t in (0, 1), hits the triangle.
bool segmentHitsTriangle(const glm::dvec3& origin, const glm::dvec3& dir, const glm::dvec3& a,
                         const glm::dvec3& b, const glm::dvec3& c) {
    const glm::dvec3 e1 = b - a, e2 = c - a;
    const glm::dvec3 p = glm::cross(dir, e2);
    const double det = glm::dot(e1, p);
    // Parallel up to rounding: relative to the lengths multiplied (det is a
    // length cubed), so the test reads the same in centimetres or kilometres.
    if (!(std::abs(det) > 1e-12 * glm::length(e1) * glm::length(e2) * glm::length(dir)))
        return false;
    const double inv = 1.0 / det;
    const glm::dvec3 s = origin - a;
    const double u = glm::dot(s, p) * inv;
    if (u < 0.0 || u > 1.0)
        return false;
    const glm::dvec3 q = glm::cross(s, e1);
    const double v = glm::dot(dir, q) * inv;
    if (v < 0.0 || u + v > 1.0)
        return false;
    const double t = glm::dot(e2, q) * inv;
    return t > 1e-6 && t < 1.0 - 1e-6; // fractions of the segment: unitless
}

bool segmentHitsPatch(const glm::dvec3& origin, const glm::dvec3& dir, const Patch& p) {
    const glm::dvec3 c0(p.corners[0]), c1(p.corners[1]), c2(p.corners[2]);
    if (segmentHitsTriangle(origin, dir, c0, c1, c2))
        return true;
    return p.cornerCount == 4 && segmentHitsTriangle(origin, dir, c0, c2, glm::dvec3(p.corners[3]));
}

} // namespace

double pointToPolygonFormFactor(const glm::dvec3& point, const glm::dvec3& normal,
                                const std::vector<glm::dvec3>& polygon) {
    const std::vector<glm::dvec3> clipped = clipToFront(polygon, point, normal);
    if (clipped.size() < 3)
        return 0.0;
    double sum = 0.0;
    for (std::size_t k = 0; k < clipped.size(); ++k) {
        const glm::dvec3 a = clipped[k] - point, b = clipped[(k + 1) % clipped.size()] - point;
        const glm::dvec3 c = glm::cross(a, b);
        const double len = glm::length(c);
        if (len < 1e-300)
            continue;
        const double angle = std::atan2(len, glm::dot(a, b));
        sum += angle * glm::dot(normal, c / len);
    }
    return std::abs(sum) / (2.0 * std::numbers::pi);
}

CpuFormFactors::CpuFormFactors(const PatchMesh& mesh, bool occlusion) : mesh_(mesh), occlusion_(occlusion) {}

scene::Expected<void> CpuFormFactors::compute(std::span<const std::uint32_t> shooters,
                                              std::vector<float>& factors) {
    const std::size_t n = mesh_.patches.size();
    factors.assign(shooters.size() * n, 0.0f);
    for (std::size_t s = 0; s < shooters.size(); ++s) {
        const Patch& shooter = mesh_.patches[shooters[s]];
        const glm::dvec3 point(shooter.center), normal(shooter.normal);
        for (std::size_t j = 0; j < n; ++j) {
            if (j == shooters[s])
                continue;
            const Patch& receiver = mesh_.patches[j];
            // Seen from behind: absorbs nothing (the GPU writes no ID there either).
            if (glm::dot(glm::dvec3(receiver.normal), point - glm::dvec3(receiver.center)) <= 0.0)
                continue;
            std::vector<glm::dvec3> polygon;
            for (int k = 0; k < receiver.cornerCount; ++k)
                polygon.emplace_back(receiver.corners[std::size_t(k)]);
            const double f = pointToPolygonFormFactor(point, normal, polygon);
            if (f <= 0.0)
                continue;
            if (occlusion_) {
                const glm::dvec3 dir = glm::dvec3(receiver.center) - point;
                bool blocked = false;
                for (std::size_t o = 0; o < n && !blocked; ++o)
                    if (o != j && o != shooters[s])
                        blocked = segmentHitsPatch(point, dir, mesh_.patches[o]);
                if (blocked)
                    continue;
            }
            factors[s * n + j] = float(f);
        }
    }
    return {};
}

} // namespace lpv::radiosity
