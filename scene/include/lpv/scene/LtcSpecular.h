#pragma once
// The GGX specular lobe of area lights by Linearly Transformed Cosines (Heitz,
// Dupuy, Hill, Neubelt 2016). An LTC is a clamped cosine whose directions were
// transformed by a 3x3 matrix M; its integral over a polygon is Lambert's
// formula (AreaLight.h) applied to the polygon transformed by M^-1. A table,
// fitted offline by tools/ltc-fit (README there), gives per (roughness,
// n.v) the M^-1 whose LTC best matches the normalised lobe D * V * cos(theta_l)
// of shaders/brdf.glsl, and the lobe's integrals, so that the specular
// radiance from an area light of radiance L is, with Schlick's Fresnel F0,
//     L * (F0 * x + (1 - F0) * y),   (x, y) = areaLightSpecularFactor(...),
//     x = magnitude * I, y = fresnel * I, I = the LTC's integral over the light.
// This is the CPU reference its shader twin is tested against.
#include "lpv/scene/Light.h"

#include <glm/glm.hpp>

#include <span>
#include <vector>

namespace lpv::scene {

// The table has kLtcTableSize x kLtcTableSize cells of kLtcCellFloats floats.
//
// Axes (chosen as in the paper): column r holds roughness = r / (N - 1), the
// material's perceptual roughness, so alpha = max(roughness^2, 1e-3) as in
// brdf.glsl: the lobe's shape changes about evenly along it, where an alpha
// axis would spend half the columns on nearly diffuse lobes. Row t holds
// sqrt(1 - n.v) = t / (N - 1): nearly even in the view angle (d theta /
// d coordinate between sqrt(2) and 2), where the lobe changes fastest near
// grazing, yet one sqrt away from n.v in the shader, with no acos.
// (n.v is at least 1e-4, brdf.glsl's clamp, in the last row.)
//
// Cell (t, r) starts at float (t * N + r) * 6; its floats are
//   [0..3] m00, m02, m20, m22: M^-1 = [[m00, 0, m02], [0, 1, 0], [m20, 0, m22]]
//          (row, column; scaled so the middle entry is 1, which changes
//          nothing, the integral being invariant to M's scale) in the frame
//          x = t1 = normalize(v - n (n.v)), y = t2 = cross(n, t1), z = n;
//          in GLSL, mat3(vec3(m00, 0, m20), vec3(0, 1, 0), vec3(m02, 0, m22));
//   [4]    magnitude = integral over the sphere of D V cos(theta_l) (the
//          lobe's directional albedo without Fresnel);
//   [5]    fresnel = integral of D V cos(theta_l) (1 - v.h)^5.
// Uploaded as two N x N textures with the width along roughness and rows by
// t: RGBA32F (m00, m02, m20, m22) and RG32F (magnitude, fresnel), GL_LINEAR,
// GL_CLAMP_TO_EDGE, sampled at
//     uv = (vec2(roughness, sqrt(1 - n.v)) * (N - 1) + 0.5) / N
// so that the table's first and last entries sit on texel centres.
inline constexpr int kLtcTableSize = 64;
inline constexpr int kLtcCellFloats = 6;

// All kLtcTableSize^2 * kLtcCellFloats floats, cells row by row as above.
std::span<const float> ltcGgxTable();

// The table split into the two textures' texel data, rows by t: 4 floats per
// texel (m00, m02, m20, m22), then 2 per texel (magnitude, fresnel).
struct LtcTextureData {
    std::vector<float> inverseMatrix;
    std::vector<float> scale;
};
LtcTextureData ltcGgxTextureData();

struct LtcCell {
    float m00 = 1.0f, m02 = 0.0f, m20 = 0.0f, m22 = 1.0f;
    float magnitude = 0.0f;
    float fresnel = 0.0f;
};

// M^-1 of a cell as a glm (column-major) matrix.
glm::mat3 ltcInverseMatrix(const LtcCell& cell);

// The table at (roughness, cosTheta = n.v), both clamped to [0, 1] (NaN reads
// as 0), filtered bilinearly as a GL_LINEAR, clamp-to-edge sample at the uv
// above would be (the GPU rounds its weights to 8 bits; this does not).
LtcCell ltcGgxLookup(float roughness, float cosTheta);

// The LTC integral of an area light's polygon (areaLightPolygon) at p with
// unit normal n, unit view direction v (toward the viewer) and roughness,
// scaled by the lobe's magnitude and Fresnel integral: (x, y) above.
// 0 behind a one-sided light, or in its plane (as areaLightIrradianceFactor).
// n.v <= 0, which interpolated and mapped normals give, reads the table's
// grazing row, as brdf.glsl clamps n.v to 1e-4; with v along n the frame's
// tangent is arbitrary, the lobe being symmetric about n there. A light
// smaller than 1e-3 of its distance is treated as a point (the LTC's density
// toward it times its solid angle), as the float shader must.
glm::vec2 areaLightSpecularFactor(const Light& light, const glm::vec3& p, const glm::vec3& n,
                                  const glm::vec3& v, float roughness);

} // namespace lpv::scene
