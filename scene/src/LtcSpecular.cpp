#include "lpv/scene/LtcSpecular.h"

#include "lpv/scene/AreaLight.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numbers>

namespace lpv::scene {
namespace {

// Written by tools/ltc-fit (its header says how); cells row by row.
constexpr float kLtcGgxTable[] = {
#include "LtcGgxTable.inc"
};
static_assert(std::size(kLtcGgxTable) == std::size_t(kLtcTableSize) * kLtcTableSize * kLtcCellFloats,
              "LtcGgxTable.inc was generated for another kLtcTableSize");

constexpr double kPi = std::numbers::pi;

float tableCoordinate(float x) {
    return std::isnan(x) ? 0.0f : std::clamp(x, 0.0f, 1.0f);
}

// The texel coordinate GL_LINEAR filters at, from the uv the shader passes:
// uv * N - 0.5 = coordinate * (N - 1), in the same float steps.
float texelCoordinate(float coordinate) {
    constexpr float n = float(kLtcTableSize);
    const float uv = (coordinate * (n - 1.0f) + 0.5f) / n;
    return uv * n - 0.5f;
}

LtcCell cellAt(int t, int r) {
    const float* c = kLtcGgxTable + (std::size_t(t) * kLtcTableSize + std::size_t(r)) * kLtcCellFloats;
    return {c[0], c[1], c[2], c[3], c[4], c[5]};
}

glm::dvec3 anyPerpendicular(const glm::vec3& n) {
    const glm::vec3 helper = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    return glm::normalize(glm::dvec3(glm::cross(helper, n)));
}

// The LTC's density toward the unit direction w (both in the shading frame):
// cos+(M^-1 w / |M^-1 w|) / pi * |det M^-1| / |M^-1 w|^3, invariant to M's scale.
double ltcDensity(const glm::dmat3& inverse, const glm::dvec3& w) {
    const glm::dvec3 o = inverse * w;
    const double len = glm::length(o);
    if (!(len > 0.0))
        return 0.0;
    return std::max(o.z / len, 0.0) / kPi * std::abs(glm::determinant(inverse)) / (len * len * len);
}

} // namespace

std::span<const float> ltcGgxTable() {
    return kLtcGgxTable;
}

LtcTextureData ltcGgxTextureData() {
    LtcTextureData data;
    const std::size_t cells = std::size_t(kLtcTableSize) * kLtcTableSize;
    data.inverseMatrix.reserve(cells * 4);
    data.scale.reserve(cells * 2);
    for (std::size_t i = 0; i < cells; ++i) {
        const float* c = kLtcGgxTable + i * kLtcCellFloats;
        data.inverseMatrix.insert(data.inverseMatrix.end(), c, c + 4);
        data.scale.insert(data.scale.end(), c + 4, c + 6);
    }
    return data;
}

glm::mat3 ltcInverseMatrix(const LtcCell& c) {
    return glm::mat3(glm::vec3(c.m00, 0.0f, c.m20), glm::vec3(0.0f, 1.0f, 0.0f),
                     glm::vec3(c.m02, 0.0f, c.m22));
}

LtcCell ltcGgxLookup(float roughness, float cosTheta) {
    const float s = texelCoordinate(tableCoordinate(roughness));
    const float t = texelCoordinate(std::sqrt(1.0f - tableCoordinate(cosTheta)));
    const float s0 = std::floor(s), t0 = std::floor(t);
    const float fs = s - s0, ft = t - t0;
    const auto edge = [](float i) { return std::clamp(int(i), 0, kLtcTableSize - 1); };
    const int r0 = edge(s0), r1 = edge(s0 + 1.0f), t0i = edge(t0), t1i = edge(t0 + 1.0f);
    const LtcCell a = cellAt(t0i, r0), b = cellAt(t0i, r1), c = cellAt(t1i, r0), d = cellAt(t1i, r1);
    const auto mix = [&](float LtcCell::*field) {
        const float top = a.*field + (b.*field - a.*field) * fs;
        const float bottom = c.*field + (d.*field - c.*field) * fs;
        return top + (bottom - top) * ft;
    };
    LtcCell out;
    for (float LtcCell::*field :
         {&LtcCell::m00, &LtcCell::m02, &LtcCell::m20, &LtcCell::m22, &LtcCell::magnitude, &LtcCell::fresnel})
        out.*field = mix(field);
    return out;
}

glm::vec2 areaLightSpecularFactor(const Light& light, const glm::vec3& p, const glm::vec3& n,
                                  const glm::vec3& v, float roughness) {
    const AreaLightFrame f = areaLightFrame(light);
    const glm::vec3 toPoint = p - f.center;
    const float height = glm::dot(toPoint, f.normal);
    if (!(height > 0.0f) && !(light.twoSided && height < 0.0f))
        return glm::vec2(0.0f); // behind a one-sided light, or in its plane

    const float nv = glm::dot(n, v);
    const LtcCell cell = ltcGgxLookup(roughness, nv);
    // The frame of the fit: v in the x-z plane on the +x side.
    const glm::dvec3 dn(n);
    glm::dvec3 t1 = glm::dvec3(v) - dn * double(nv);
    const double t1Length = glm::length(t1);
    t1 = t1Length > 1e-6 ? t1 / t1Length : anyPerpendicular(n);
    const glm::dvec3 t2 = glm::cross(dn, t1);
    // World to the frame (its axes as the rows), then the cell's M^-1.
    const glm::dmat3 toFrame = glm::transpose(glm::dmat3(t1, t2, dn));
    const glm::dmat3 inverse = glm::dmat3(ltcInverseMatrix(cell));

    double integral = 0.0;
    const float distance = glm::length(toPoint);
    const float extent = glm::length(f.halfU) + glm::length(f.halfV);
    if (extent < 1e-3f * distance) {
        // A point of the light's area: the density toward it times A cos(light) / d^2.
        const glm::dvec3 l = toFrame * glm::dvec3(-toPoint / distance);
        const double solidAngle =
            double(areaLightArea(light)) * std::abs(height) / distance / (double(distance) * distance);
        integral = ltcDensity(inverse, l) * solidAngle;
    } else {
        std::vector<glm::dvec3> polygon;
        for (const glm::vec3& corner : areaLightPolygon(light))
            polygon.push_back(inverse * (toFrame * glm::dvec3(corner - p)));
        // Lambert's formula normalises the vertex directions, so the
        // transformed vertices need no normalising; it is pi for a full hemisphere.
        integral = polygonCosineSolidAngle(glm::dvec3(0.0), glm::dvec3(0.0, 0.0, 1.0), polygon) / kPi;
    }
    return glm::vec2(float(cell.magnitude * integral), float(cell.fresnel * integral));
}

} // namespace lpv::scene
