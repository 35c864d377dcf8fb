#pragma once
// Two-band spherical harmonics (4 coefficients per colour channel), the
// representation of light in the LPV. Plain C++ (no GL): the CPU reference
// and the tests use it; shaders/sh.glsl is its GLSL twin, coefficient for
// coefficient, and a GL test checks that they agree.
//
// Conventions (Kaplanyan & Dachsbacher 2010, and the thesis):
//  - coefficient order (Y00, Y1-1, Y10, Y11) as a vec4, real orthonormal basis
//    Y00 = 0.282095, Y1-1 = -0.488603 y, Y10 = 0.488603 z, Y11 = -0.488603 x;
//  - a cell stores the radiant intensity I(w) (W/sr) of the light leaving it
//    in travel direction w, one vec4 per colour channel;
//  - cosineLobe(d) is the projection of the clamped cosine max(0, d.w), so
//    the integral over the sphere of f(w) max(0, d.w) dw = dot(f, cosineLobe(d)).
#include <glm/glm.hpp>

namespace lpv::renderer::sh {

inline constexpr float kY0 = 0.282094792f;  // 1 / (2 sqrt(pi))
inline constexpr float kY1 = 0.488602512f;  // sqrt(3) / (2 sqrt(pi))
inline constexpr float kCos0 = 0.886226925f; // pi * kY0
inline constexpr float kCos1 = 1.023326708f; // (2 pi / 3) * kY1
inline constexpr float kPi = 3.14159265358979f;

// The basis evaluated in direction `w` (unit length).
inline glm::vec4 basis(const glm::vec3& w) { return {kY0, -kY1 * w.y, kY1 * w.z, -kY1 * w.x}; }

// Projection of the clamped cosine lobe max(0, d.w) around unit direction `d`.
inline glm::vec4 cosineLobe(const glm::vec3& d) { return {kCos0, -kCos1 * d.y, kCos1 * d.z, -kCos1 * d.x}; }

// The function `f` evaluated in direction `w`.
inline float evaluate(const glm::vec4& f, const glm::vec3& w) { return glm::dot(f, basis(w)); }

// A virtual point light's intensity Phi/pi * max(0, n.w) as SH (per channel: scale by that channel's flux).
inline glm::vec4 vplIntensity(const glm::vec3& normal, float flux) { return (flux / kPi) * cosineLobe(normal); }

// Irradiance on a surface with unit normal `n` from light whose radiance in
// travel direction w is `radiance` (SH): light arriving at the surface travels
// against its normal, so E = integral L(w) max(0, -n.w) dw.
inline float irradiance(const glm::vec4& radiance, const glm::vec3& n) {
    return glm::max(0.0f, glm::dot(radiance, cosineLobe(-n)));
}

} // namespace lpv::renderer::sh
