#version 450 core
// Multi-bounce LPV (docs/lpv.md, "Local lights, emissive surfaces and
// bounces"; CPU twin lpvref::bounceVpls in LpvBounce.h).
//
// BOUNCE_INJECT: per cell, the geometry volume at the cell centre (the mean
// of its 8 corner GV cells) is an oriented surfel, net normal n and coverage
// c = min(|net oriented area| / s^2, 1). It receives max(0, A . cosineLobe(-n))
// (irradiance times the cell face) from the accumulator A of the bounce just
// propagated and re-emits albedo * c times that as a VPL facing n in the same
// cell. The VPLs become the next bounce's V_0: the step volume and the
// accumulator are both set to them, one invocation per cell (no atomics).
// Their largest |coefficient| is recorded for the compute scatter's scale.
//
// Otherwise (BOUNCE_ADD): the running total of earlier bounces and the
// accumulator: uFinal false adds the accumulator into the total, true adds
// the total into the accumulator (which the forward pass then reads).
#define LPV_WITH_FIXED_POINT
#include "sh.glsl"
#include "lpv_common.glsl"
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(rgba32f, binding = 0) uniform image3D uVolumeR; // BOUNCE_INJECT: V_0 of the bounce; else the total
layout(rgba32f, binding = 1) uniform image3D uVolumeG;
layout(rgba32f, binding = 2) uniform image3D uVolumeB;
layout(rgba32f, binding = 3) uniform image3D uAccumR;
layout(rgba32f, binding = 4) uniform image3D uAccumG;
layout(rgba32f, binding = 5) uniform image3D uAccumB;

#ifdef BOUNCE_INJECT
layout(binding = 3) uniform sampler3D uGv; // (N + 1)^3 per cascade, stacked along z
uniform float uAlbedo;
uniform int uRecordSlot;

vec4 gvAt(int k, ivec3 g) { return texelFetch(uGv, ivec3(g.xy, k * (uGridSize + 1) + g.z), 0); }
#else
uniform bool uFinal;
#endif

void main() {
    ivec3 texel = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(texel, ivec3(uGridSize, uGridSize, uGridSize * uCascades))))
        return;
#ifdef BOUNCE_INJECT
    int k = texel.z / uGridSize;
    ivec3 p = ivec3(texel.xy, texel.z % uGridSize);
    vec4 b = vec4(0.0);
    for (int corner = 0; corner < 8; ++corner)
        b += gvAt(k, p + ivec3(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1));
    b *= 0.125;
    vec3 oriented = vec3(-b.w, -b.y, b.z) / SH_COS1;
    float len = length(oriented);
    vec4 r = vec4(0.0), g = vec4(0.0), bl = vec4(0.0);
    if (len > 1e-6) {
        vec3 n = oriented / len;
        float reflected = uAlbedo * min(len, 1.0);
        vec4 receive = shCosineLobe(-n), emit = shCosineLobe(n) / SH_PI;
        r = reflected * max(0.0, dot(imageLoad(uAccumR, texel), receive)) * emit;
        g = reflected * max(0.0, dot(imageLoad(uAccumG, texel), receive)) * emit;
        bl = reflected * max(0.0, dot(imageLoad(uAccumB, texel), receive)) * emit;
    }
    imageStore(uVolumeR, texel, r);
    imageStore(uVolumeG, texel, g);
    imageStore(uVolumeB, texel, bl);
    imageStore(uAccumR, texel, r);
    imageStore(uAccumG, texel, g);
    imageStore(uAccumB, texel, bl);
    vec4 largest = max(max(abs(r), abs(g)), abs(bl));
    float m = max(max(largest.x, largest.y), max(largest.z, largest.w));
    if (m > 0.0)
        lpvRecordMax(k, uRecordSlot, m);
#else
    vec4 tr = imageLoad(uVolumeR, texel), tg = imageLoad(uVolumeG, texel), tb = imageLoad(uVolumeB, texel);
    vec4 ar = imageLoad(uAccumR, texel), ag = imageLoad(uAccumG, texel), ab = imageLoad(uAccumB, texel);
    if (uFinal) {
        imageStore(uAccumR, texel, ar + tr);
        imageStore(uAccumG, texel, ag + tg);
        imageStore(uAccumB, texel, ab + tb);
    } else {
        imageStore(uVolumeR, texel, tr + ar);
        imageStore(uVolumeG, texel, tg + ag);
        imageStore(uVolumeB, texel, tb + ab);
    }
#endif
}
