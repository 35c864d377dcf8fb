#pragma once
// Spherical harmonics of two or three bands (B = 2: 4 coefficients per
// colour channel, B = 3: 9), for the higher-order LPV of issue #47
// (lpv.shBands). Plain C++ (no GL). With B = 2 every function equals its
// twin in Sh.h, coefficient for coefficient; B = 3 adds band 2.
//
// Conventions (docs/lpv.md, "Three bands"): the real orthonormal basis with
// the Condon-Shortley phase, as Sh.h's band 1 (Sloan, "Stupid spherical
// harmonics tricks", 2008), in the order
//   Y00,
//   Y1-1 = -k1 y, Y10 = k1 z, Y11 = -k1 x,                    k1 = sqrt(3 / 4pi)
//   Y2-2 = k2 xy, Y2-1 = -k2 yz, Y20 = k20 (3z^2 - 1), Y21 = -k2 xz,
//   Y22 = k22 (x^2 - y^2),                                     k2 = sqrt(15 / 4pi),
//                                                              k20 = sqrt(5 / 16pi), k22 = sqrt(15 / 16pi).
// The clamped cosine max(0, d.w) projects to A_l Y_lm(d) with
// A_0 = pi, A_1 = 2pi/3, A_2 = pi/4 (its zonal coefficients times
// sqrt(4pi / (2l + 1))), so the integral of f(w) max(0, d.w) over the sphere
// is dot(f, cosineLobe(d)) for any f of up to B bands.
#include "lpv/renderer/lpv/Sh.h"

#include <glm/glm.hpp>

#include <array>

namespace lpv::renderer::sh {

inline constexpr float kY2 = 1.092548431f;  // sqrt(15 / 4pi)
inline constexpr float kY20 = 0.315391565f; // sqrt(5 / 16pi)
inline constexpr float kY22 = 0.546274215f; // sqrt(15 / 16pi)
// The clamped cosine's band factors A_l (the irradiance convolution).
inline constexpr float kA0 = kPi;
inline constexpr float kA1 = 2.0f * kPi / 3.0f;
inline constexpr float kA2 = kPi / 4.0f;

template <int B>
struct Coeffs {
    static_assert(B == 2 || B == 3, "two or three bands");
    static constexpr int kCount = B * B;
    std::array<float, std::size_t(B * B)> c{};

    float& operator[](int i) { return c[std::size_t(i)]; }
    float operator[](int i) const { return c[std::size_t(i)]; }
    Coeffs& operator+=(const Coeffs& o) {
        for (int i = 0; i < kCount; ++i)
            c[std::size_t(i)] += o.c[std::size_t(i)];
        return *this;
    }
    friend Coeffs operator*(float s, Coeffs f) {
        for (float& v : f.c)
            v *= s;
        return f;
    }
    friend bool operator==(const Coeffs&, const Coeffs&) = default;
};

template <int B>
float dot(const Coeffs<B>& a, const Coeffs<B>& b) {
    float s = 0.0f;
    for (int i = 0; i < Coeffs<B>::kCount; ++i)
        s += a[i] * b[i];
    return s;
}

// The basis in unit direction `w`.
template <int B>
Coeffs<B> basisOf(const glm::vec3& w) {
    Coeffs<B> y;
    y[0] = kY0;
    y[1] = -kY1 * w.y;
    y[2] = kY1 * w.z;
    y[3] = -kY1 * w.x;
    if constexpr (B == 3) {
        y[4] = kY2 * w.x * w.y;
        y[5] = -kY2 * w.y * w.z;
        y[6] = kY20 * (3.0f * w.z * w.z - 1.0f);
        y[7] = -kY2 * w.x * w.z;
        y[8] = kY22 * (w.x * w.x - w.y * w.y);
    }
    return y;
}

// The projection of max(0, d.w): A_l Y_lm(d) (band 2: pi/4 Y2m(d)).
template <int B>
Coeffs<B> cosineLobeOf(const glm::vec3& d) {
    Coeffs<B> f = basisOf<B>(d);
    f[0] *= kA0;
    for (int i = 1; i < 4; ++i)
        f[i] *= kA1;
    for (int i = 4; i < Coeffs<B>::kCount; ++i)
        f[i] *= kA2;
    return f;
}

template <int B>
float evaluateAt(const Coeffs<B>& f, const glm::vec3& w) {
    return dot(f, basisOf<B>(w));
}

// A VPL's intensity Phi/pi max(0, n.w) (per channel: that channel's flux).
template <int B>
Coeffs<B> vplIntensityOf(const glm::vec3& normal, float flux) {
    return (flux / kPi) * cosineLobeOf<B>(normal);
}

// Irradiance on a surface of unit normal `n` from light whose radiance in
// travel direction w is `radiance`: E = integral L(w) max(0, -n.w) dw.
template <int B>
float irradianceOf(const Coeffs<B>& radiance, const glm::vec3& n) {
    return glm::max(0.0f, dot(radiance, cosineLobeOf<B>(-n)));
}

// Sh.h's vec4 as two-band coefficients and back.
inline Coeffs<2> fromVec4(const glm::vec4& v) { return {{v.x, v.y, v.z, v.w}}; }
inline glm::vec4 toVec4(const Coeffs<2>& f) { return {f[0], f[1], f[2], f[3]}; }

} // namespace lpv::renderer::sh
