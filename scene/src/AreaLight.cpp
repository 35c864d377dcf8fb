#include "lpv/scene/AreaLight.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace lpv::scene {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

glm::vec3 safeNormalize(const glm::vec3& v, const glm::vec3& fallback) {
    const float len = glm::length(v);
    return len > 1e-20f && std::isfinite(len) ? v / len : fallback;
}

// A disc's polygon has the disc's area: circumradius r * sqrt(2 pi / (N sin(2 pi / N))).
float discPolygonRadius(float radius) {
    const double n = kAreaLightDiscSides;
    return float(double(radius) * std::sqrt(2.0 * std::numbers::pi / (n * std::sin(2.0 * std::numbers::pi / n))));
}

// Sutherland-Hodgman against the plane (x - p) . n >= 0.
template <class V, class T>
std::vector<V> clipToHemisphere(const V& p, const V& n, std::span<const V> polygon) {
    std::vector<V> out;
    const std::size_t count = polygon.size();
    for (std::size_t i = 0; i < count; ++i) {
        const V& a = polygon[i];
        const V& b = polygon[(i + 1) % count];
        const T da = glm::dot(a - p, n), db = glm::dot(b - p, n);
        if (da >= T(0))
            out.push_back(a);
        if ((da >= T(0)) != (db >= T(0)))
            out.push_back(a + (b - a) * (da / (da - db)));
    }
    return out;
}

// Lambert's sum over the edges of a polygon above the horizon; atan2 keeps
// small angles exact where acos(dot) would not.
template <class V, class T>
T lambertSum(const V& p, const V& n, const std::vector<V>& clipped) {
    T sum = T(0);
    const std::size_t count = clipped.size();
    for (std::size_t i = 0; i < count; ++i) {
        const V a = clipped[i] - p, b = clipped[(i + 1) % count] - p;
        const T la = glm::length(a), lb = glm::length(b);
        if (la <= T(0) || lb <= T(0))
            continue; // p on a vertex: that edge subtends nothing
        const V ua = a / la, ub = b / lb;
        const V c = glm::cross(ua, ub);
        const T s = glm::length(c);
        if (s <= T(0))
            continue; // p on the edge's line
        sum += std::atan2(s, glm::dot(ua, ub)) * glm::dot(c / s, n);
    }
    return std::abs(sum) * T(0.5);
}

} // namespace

AreaLightFrame areaLightFrame(const Light& light) {
    AreaLightFrame f;
    f.center = light.position;
    f.normal = safeNormalize(light.direction, {0.0f, -1.0f, 0.0f});
    glm::vec3 t = light.tangent - f.normal * glm::dot(light.tangent, f.normal);
    const glm::vec3 helper = std::abs(f.normal.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    t = safeNormalize(t, glm::normalize(glm::cross(helper, f.normal)));
    const glm::vec3 b = glm::cross(f.normal, t);
    if (light.shape == AreaShape::Disc) {
        f.halfU = t * light.radius;
        f.halfV = b * light.radius;
    } else {
        f.halfU = t * (0.5f * light.size.x);
        f.halfV = b * (0.5f * light.size.y);
    }
    return f;
}

float areaLightArea(const Light& light) {
    return light.shape == AreaShape::Disc ? kPi * light.radius * light.radius : light.size.x * light.size.y;
}

glm::vec3 areaLightRadiance(const Light& light) {
    if (light.unit == AreaUnit::Radiance)
        return light.color * light.intensity;
    const float sides = light.twoSided ? 2.0f : 1.0f;
    const float area = areaLightArea(light);
    return area > 0.0f ? light.color * (light.intensity / (kPi * area * sides)) : glm::vec3(0.0f);
}

std::vector<glm::vec3> areaLightPolygon(const Light& light) {
    const AreaLightFrame f = areaLightFrame(light);
    if (light.shape == AreaShape::Rectangle)
        return {f.center - f.halfU - f.halfV, f.center + f.halfU - f.halfV, f.center + f.halfU + f.halfV,
                f.center - f.halfU + f.halfV};
    std::vector<glm::vec3> out;
    const float scale = discPolygonRadius(1.0f);
    for (int i = 0; i < kAreaLightDiscSides; ++i) {
        const float a = 2.0f * kPi * float(i) / float(kAreaLightDiscSides);
        out.push_back(f.center + scale * (std::cos(a) * f.halfU + std::sin(a) * f.halfV));
    }
    return out;
}

double polygonCosineSolidAngle(const glm::dvec3& p, const glm::dvec3& n, std::span<const glm::dvec3> polygon) {
    const std::vector<glm::dvec3> clipped = clipToHemisphere<glm::dvec3, double>(p, n, polygon);
    return clipped.size() < 3 ? 0.0 : lambertSum<glm::dvec3, double>(p, n, clipped);
}

float areaLightIrradianceFactor(const Light& light, const glm::vec3& p, const glm::vec3& n) {
    const AreaLightFrame f = areaLightFrame(light);
    const glm::vec3 toPoint = p - f.center;
    const float height = glm::dot(toPoint, f.normal);
    if (!(height > 0.0f) && !(light.twoSided && height < 0.0f))
        return 0.0f; // behind a one-sided light, or in its plane
    const float distance = glm::length(toPoint);
    const float extent = glm::length(f.halfU) + glm::length(f.halfV);
    if (extent < 1e-3f * distance) {
        // A point of the light's area: A cos(light) cos(surface) / d^2.
        const glm::vec3 l = -toPoint / distance;
        return areaLightArea(light) * std::abs(height) / distance * std::max(glm::dot(n, l), 0.0f) /
               (distance * distance);
    }
    const std::vector<glm::vec3> polygon = areaLightPolygon(light);
    const std::vector<glm::vec3> clipped = clipToHemisphere<glm::vec3, float>(p, n, polygon);
    return clipped.size() < 3 ? 0.0f : lambertSum<glm::vec3, float>(p, n, clipped);
}

bool hasAreaLight(std::span<const Light> lights) {
    return std::any_of(lights.begin(), lights.end(), [](const Light& l) { return l.type == LightType::Area; });
}

bool liesOnAnAreaLight(std::span<const Light> lights, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c,
                       float worldMagnitude) {
    for (const Light& light : lights) {
        if (light.type != LightType::Area)
            continue;
        const AreaLightFrame f = areaLightFrame(light);
        const float u = glm::length(f.halfU), v = glm::length(f.halfV);
        if (!(u > 0.0f) || !(v > 0.0f))
            continue;
        // A thousandth of the light off its plane and outline still counts, plus
        // the float rounding of positions that far from the origin (8 mm at
        // 100 km): lengths that scale (issue #41), no millimetre floor, which
        // was 7% of the Cornell lamp in centimetres.
        const float magnitude =
            std::max({std::abs(f.center.x), std::abs(f.center.y), std::abs(f.center.z), worldMagnitude});
        const float slack = 1e-3f * (u + v) + 4.0f * std::numeric_limits<float>::epsilon() * magnitude;
        bool inside = true;
        for (const glm::vec3& p : {a, b, c}) {
            const glm::vec3 d = p - f.center;
            const float along = glm::dot(d, f.normal);
            const float x = glm::dot(d, f.halfU) / u, y = glm::dot(d, f.halfV) / v;
            const bool withinOutline = light.shape == AreaShape::Disc
                                           ? std::sqrt(x * x + y * y) <= u * discPolygonRadius(1.0f) + slack
                                           : std::abs(x) <= u + slack && std::abs(y) <= v + slack;
            if (!(std::abs(along) <= slack) || !withinOutline) {
                inside = false;
                break;
            }
        }
        if (inside)
            return true;
    }
    return false;
}

} // namespace lpv::scene
