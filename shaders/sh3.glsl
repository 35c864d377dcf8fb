// Three-band spherical harmonics (issue #47, lpv.shBands = 3): the GLSL twin
// of renderer/include/lpv/renderer/lpv/ShBands.h with B = 3 (same order, same
// constants; Sh3GlslAgreementGLTest checks that they agree). Include sh.glsl
// first: band 0-1 are its functions. Nine coefficients as (Y00, Y1-1, Y10,
// Y11) in `low`, (Y2-2, Y2-1, Y20, Y21) in `high` and Y22 in `last`, the
// layout of three textures per colour channel (RGBA, RGBA, R).
const float SH_Y2 = 1.092548431;  // sqrt(15 / 4pi)
const float SH_Y20 = 0.315391565; // sqrt(5 / 16pi)
const float SH_Y22 = 0.546274215; // sqrt(15 / 16pi)
// The clamped cosine's band factors (the irradiance convolution): pi, 2pi/3, pi/4.
const vec4 SH_A_LOW = vec4(SH_PI, 2.0 * SH_PI / 3.0, 2.0 * SH_PI / 3.0, 2.0 * SH_PI / 3.0);
const float SH_A2 = SH_PI / 4.0;

struct Sh9 {
    vec4 low;
    vec4 high;
    float last;
};

Sh9 sh9Basis(vec3 w) {
    return Sh9(shBasis(w),
               vec4(SH_Y2 * w.x * w.y, -SH_Y2 * w.y * w.z, SH_Y20 * (3.0 * w.z * w.z - 1.0), -SH_Y2 * w.x * w.z),
               SH_Y22 * (w.x * w.x - w.y * w.y));
}

Sh9 sh9Scale(Sh9 f, float s) { return Sh9(f.low * s, f.high * s, f.last * s); }

float sh9Dot(Sh9 a, Sh9 b) { return dot(a.low, b.low) + dot(a.high, b.high) + a.last * b.last; }

// The projection of max(0, d.w): A_l Y_lm(d).
Sh9 sh9CosineLobe(vec3 d) {
    Sh9 y = sh9Basis(d);
    return Sh9(y.low * SH_A_LOW, y.high * SH_A2, y.last * SH_A2);
}

float sh9Evaluate(Sh9 f, vec3 w) { return sh9Dot(f, sh9Basis(w)); }

Sh9 sh9VplIntensity(vec3 normal, float flux) { return sh9Scale(sh9CosineLobe(normal), flux / SH_PI); }

float sh9Irradiance(Sh9 radiance, vec3 n) { return max(0.0, sh9Dot(radiance, sh9CosineLobe(-n))); }
