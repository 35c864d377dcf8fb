#version 450 core
// One propagation step, compute scatter (lpv.variant = computeScatter): each
// source cell pushes into its 6 neighbours with integer atomics in fixed point
// (lpv_common.glsl); lpv_resolve.comp then writes the floats and accumulates.
#define LPV_WITH_FACE_BLOCKING
#define LPV_WITH_FIXED_POINT
#define LPV_WITH_DIRECTED
#include "sh.glsl"
#include "lpv_common.glsl"
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(binding = 0) uniform sampler3D uSourceR;
layout(binding = 1) uniform sampler3D uSourceG;
layout(binding = 2) uniform sampler3D uSourceB;
layout(std430, binding = 0) buffer LpvFixedPoint { int lpvSums[]; };

// What q sends into its neighbour q + sigma e_a, added in fixed point.
void pushInto(int a, float sigma, int k, ivec3 q, vec4 r, vec4 g, vec4 b, float scale) {
    ivec3 p = q;
    p[a] += int(sigma);
    if (!lpvInsideCascade(p))
        return;
    vec3 accDc = vec3(0.0), nR = vec3(0.0), nG = vec3(0.0), nB = vec3(0.0);
    lpvSend(a, sigma, r, g, b, lpvBlockingBetween(k, q, a, sigma), lpvDirectedNormal(k, p), accDc, nR, nG, nB);
    vec4 outR = lpvFinishChannel(accDc.r, nR), outG = lpvFinishChannel(accDc.g, nG),
         outB = lpvFinishChannel(accDc.b, nB);
    int base = lpvCellIndex(k, p) * 12;
    for (int j = 0; j < 4; ++j) {
        atomicAdd(lpvSums[base + j], int(round(outR[j] * scale)));
        atomicAdd(lpvSums[base + 4 + j], int(round(outG[j] * scale)));
        atomicAdd(lpvSums[base + 8 + j], int(round(outB[j] * scale)));
    }
}

void main() {
    ivec3 texel = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(texel, ivec3(uGridSize, uGridSize, uGridSize * uCascades))))
        return;
    int k = texel.z / uGridSize;
    ivec3 q = ivec3(texel.xy, texel.z % uGridSize);
    vec4 r = texelFetch(uSourceR, texel, 0), g = texelFetch(uSourceG, texel, 0), b = texelFetch(uSourceB, texel, 0);
    if (r == vec4(0.0) && g == vec4(0.0) && b == vec4(0.0))
        return; // dark cells push nothing: most of a scene's volume early on
    float scale = lpvFixedScale(k);
    pushInto(0, 1.0, k, q, r, g, b, scale);
    pushInto(0, -1.0, k, q, r, g, b, scale);
    pushInto(1, 1.0, k, q, r, g, b, scale);
    pushInto(1, -1.0, k, q, r, g, b, scale);
    pushInto(2, 1.0, k, q, r, g, b, scale);
    pushInto(2, -1.0, k, q, r, g, b, scale);
}
