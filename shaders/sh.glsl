// Two-band spherical harmonics: the GLSL twin of
// renderer/include/lpv/renderer/lpv/Sh.h (same order, same constants; a GL
// test checks that they agree). Coefficients (Y00, Y1-1, Y10, Y11) in a vec4.
const float SH_Y0 = 0.282094792;
const float SH_Y1 = 0.488602512;
const float SH_COS0 = 0.886226925;
const float SH_COS1 = 1.023326708;
const float SH_PI = 3.14159265358979;

vec4 shBasis(vec3 w) { return vec4(SH_Y0, -SH_Y1 * w.y, SH_Y1 * w.z, -SH_Y1 * w.x); }

vec4 shCosineLobe(vec3 d) { return vec4(SH_COS0, -SH_COS1 * d.y, SH_COS1 * d.z, -SH_COS1 * d.x); }

float shEvaluate(vec4 f, vec3 w) { return dot(f, shBasis(w)); }

vec4 shVplIntensity(vec3 normal, float flux) { return (flux / SH_PI) * shCosineLobe(normal); }

float shIrradiance(vec4 radiance, vec3 n) { return max(0.0, dot(radiance, shCosineLobe(-n))); }
