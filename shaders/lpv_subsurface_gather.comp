#version 450 core
// One subsurface propagation step (docs/lpv.md, LpvSubsurfaceReference's
// propagateSubsurface): the LPV's compute gather (lpvSend) without occlusion
// (the translucent material's own surfaces would block the light inside it)
// and without directed propagation, times (1 - attenuation), added to the
// subsurface accumulator. Packed volumes (lpv_subsurface.glsl).
#include "sh.glsl"
#include "lpv_common.glsl"
#include "lpv_subsurface.glsl"
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(binding = 0) uniform sampler3D uSource;
layout(rgba32f, binding = 0) uniform writeonly image3D uDest;
layout(rgba32f, binding = 1) uniform image3D uAccum;
uniform float uKeep; // 1 - effects.subsurfaceAttenuation

void gatherFrom(int a, float sigma, int k, ivec3 p, inout vec3 accDc, inout vec3 nR, inout vec3 nG, inout vec3 nB) {
    ivec3 q = p;
    q[a] -= int(sigma);
    if (!lpvInsideCascade(q))
        return;
    vec4 r = texelFetch(uSource, sssTexel(0, k, q), 0);
    vec4 g = texelFetch(uSource, sssTexel(1, k, q), 0);
    vec4 b = texelFetch(uSource, sssTexel(2, k, q), 0);
    if (r == vec4(0.0) && g == vec4(0.0) && b == vec4(0.0))
        return;
    lpvSend(a, sigma, r, g, b, vec4(0.0), vec3(0.0), accDc, nR, nG, nB);
}

void main() {
    ivec3 texel = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(texel, ivec3(uGridSize, uGridSize, uGridSize * uCascades))))
        return;
    int k = texel.z / uGridSize;
    ivec3 p = ivec3(texel.xy, texel.z % uGridSize);
    vec3 accDc = vec3(0.0), nR = vec3(0.0), nG = vec3(0.0), nB = vec3(0.0);
    // Literal directions, so that the compiler folds every axis index.
    gatherFrom(0, 1.0, k, p, accDc, nR, nG, nB);
    gatherFrom(0, -1.0, k, p, accDc, nR, nG, nB);
    gatherFrom(1, 1.0, k, p, accDc, nR, nG, nB);
    gatherFrom(1, -1.0, k, p, accDc, nR, nG, nB);
    gatherFrom(2, 1.0, k, p, accDc, nR, nG, nB);
    gatherFrom(2, -1.0, k, p, accDc, nR, nG, nB);
    vec4 v[3] = vec4[3](lpvFinishChannel(accDc.r, nR) * uKeep, lpvFinishChannel(accDc.g, nG) * uKeep,
                        lpvFinishChannel(accDc.b, nB) * uKeep);
    // The destination was cleared before the step: cells that receive nothing write nothing.
    if (v[0] == vec4(0.0) && v[1] == vec4(0.0) && v[2] == vec4(0.0))
        return;
    for (int c = 0; c < 3; ++c) {
        ivec3 t = sssTexel(c, k, p);
        imageStore(uDest, t, v[c]);
        imageStore(uAccum, t, imageLoad(uAccum, t) + v[c]);
    }
}
