#version 450 core
// One propagation step, compute gather (lpv.variant = computeGather): each
// destination cell pulls from its 6 neighbours through its 5 other faces
// (docs/lpv.md, lpvGather in lpv_common.glsl) and adds the result to the
// accumulator. No atomics: every invocation owns its cell.
//
// The blocking potential of every face comes precomputed per frame
// (lpv_face_blocking.comp: 6 fetches per cell and step, not 24). A shared-
// memory tile of the sources (8x4x4 cells and a border) fetched less but ran
// 1.6x slower on llvmpipe, whose barriers are expensive (docs/lpv.md).
#if LPV_SH_BANDS == 3
// Three bands (lpv.shBands = 3, issue #47): lpv_transfer3.glsl's gather, the
// twin of lpvref::bands::propagateStep<3>, over the interleaved volumes of 7
// texels per cell (low R, G, B, high R, G, B, last rgb; lpv_resolve.comp
// writes the first, so every step reads them) and the face blocking in two
// textures (bands 0-1 as for two bands, band 2 in uFaceBlockingHigh).
#define LPV_WITH_DIRECTED
#include "sh.glsl"
#include "sh3.glsl"
#include "lpv_common.glsl"
layout(local_size_x = 32, local_size_y = 8, local_size_z = 1) in;

layout(binding = 0) uniform sampler3D uSource;           // 7N x N x NK
layout(binding = 4) uniform sampler3D uFaceBlocking;     // 3N x N x NK: face a of cell x at 3x + a
layout(binding = 5) uniform sampler3D uFaceBlockingHigh; // 6N x N x NK: 6x + 2a (high), 6x + 2a + 1 (last)
uniform bool uOcclusion;
layout(rgba32f, binding = 0) uniform writeonly image3D uDest; // 7N x N x NK
layout(rgba32f, binding = 3) uniform image3D uAccumR;
layout(rgba32f, binding = 4) uniform image3D uAccumG;
layout(rgba32f, binding = 5) uniform image3D uAccumB;
layout(rgba32f, binding = 6) uniform image3D uAccumHigh; // 4N x N x NK: planes high R, G, B, last rgb

int lpvCascade = 0;          // of the destination cell
vec3 lpvDirected = vec3(0.0); // its dilated VPL normal (zero: undirected)

void lpv3Sources(ivec3 q, out Sh9 r, out Sh9 g, out Sh9 b) {
    ivec3 t = ivec3(7 * q.x, q.y, lpvCascade * uGridSize + q.z);
    vec4 last = texelFetch(uSource, t + ivec3(6, 0, 0), 0);
    r = Sh9(texelFetch(uSource, t, 0), texelFetch(uSource, t + ivec3(3, 0, 0), 0), last.x);
    g = Sh9(texelFetch(uSource, t + ivec3(1, 0, 0), 0), texelFetch(uSource, t + ivec3(4, 0, 0), 0), last.y);
    b = Sh9(texelFetch(uSource, t + ivec3(2, 0, 0), 0), texelFetch(uSource, t + ivec3(5, 0, 0), 0), last.z);
}

// The face between q and q + d: q's +a face, or for a negative d the neighbour's.
Sh9 lpv3BlockingBetween(ivec3 q, ivec3 d) {
    int a = d.x != 0 ? 0 : (d.y != 0 ? 1 : 2);
    ivec3 c = q + min(d, ivec3(0));
    ivec3 t = ivec3(c.xy, lpvCascade * uGridSize + c.z);
    return Sh9(texelFetch(uFaceBlocking, ivec3(3 * t.x + a, t.yz), 0),
               texelFetch(uFaceBlockingHigh, ivec3(6 * t.x + 2 * a, t.yz), 0),
               texelFetch(uFaceBlockingHigh, ivec3(6 * t.x + 2 * a + 1, t.yz), 0).x);
}

#define LPV3_GRID uGridSize
#define LPV3_STRENGTH uOcclusionStrength
#define LPV3_TWO_SIDED uTwoSidedOcclusion
#define LPV3_DIRECTED lpvDirected
#include "lpv_transfer3.glsl"

void main() {
    ivec3 texel = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(texel, ivec3(uGridSize, uGridSize, uGridSize * uCascades))))
        return;
    lpvCascade = texel.z / uGridSize;
    ivec3 p = ivec3(texel.xy, texel.z % uGridSize);
    lpvDirected = lpvDirectedNormal(lpvCascade, p);
    Sh9 v[3];
    lpv3Gather(p, uOcclusion, v[0], v[1], v[2]);
    ivec3 first = ivec3(7 * texel.x, texel.yz);
    vec4 last = vec4(v[0].last, v[1].last, v[2].last, 0.0);
    for (int c = 0; c < 3; ++c) {
        imageStore(uDest, first + ivec3(c, 0, 0), v[c].low);
        imageStore(uDest, first + ivec3(3 + c, 0, 0), v[c].high);
    }
    imageStore(uDest, first + ivec3(6, 0, 0), last);
    if (v[0].low == vec4(0.0) && v[1].low == vec4(0.0) && v[2].low == vec4(0.0))
        return; // no light arrived (the DC of any light that did is positive)
    imageStore(uAccumR, texel, imageLoad(uAccumR, texel) + v[0].low);
    imageStore(uAccumG, texel, imageLoad(uAccumG, texel) + v[1].low);
    imageStore(uAccumB, texel, imageLoad(uAccumB, texel) + v[2].low);
    ivec3 plane = ivec3(uGridSize, 0, 0);
    for (int c = 0; c < 3; ++c)
        imageStore(uAccumHigh, texel + c * plane, imageLoad(uAccumHigh, texel + c * plane) + v[c].high);
    imageStore(uAccumHigh, texel + 3 * plane, imageLoad(uAccumHigh, texel + 3 * plane) + last);
}
#else
#define LPV_WITH_FACE_BLOCKING
#define LPV_WITH_DIRECTED
#define LPV_WITH_SOURCES
// The first step (LPV_FIRST_STEP) reads the injected volume, one texture per
// channel; it writes the interleaved volume the later steps read.
#ifndef LPV_FIRST_STEP
#define LPV_INTERLEAVED_SOURCES
#endif
#include "sh.glsl"
#include "lpv_common.glsl"
layout(local_size_x = 32, local_size_y = 8, local_size_z = 1) in;

// Sources (after the first step) and destination interleave a cell's R, G, B
// (3N x N x NK); the accumulator is per channel, for the lookup's filter.
layout(rgba32f, binding = 0) uniform writeonly image3D uDest;
layout(rgba32f, binding = 3) uniform image3D uAccumR;
layout(rgba32f, binding = 4) uniform image3D uAccumG;
layout(rgba32f, binding = 5) uniform image3D uAccumB;

void main() {
    ivec3 texel = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(texel, ivec3(uGridSize, uGridSize, uGridSize * uCascades))))
        return;
    vec4 r, g, b;
    lpvGather(texel.z / uGridSize, ivec3(texel.xy, texel.z % uGridSize), r, g, b);
    ivec3 first = ivec3(3 * texel.x, texel.yz);
    imageStore(uDest, first, r);
    imageStore(uDest, first + ivec3(1, 0, 0), g);
    imageStore(uDest, first + ivec3(2, 0, 0), b);
    if (r == vec4(0.0) && g == vec4(0.0) && b == vec4(0.0))
        return;
    imageStore(uAccumR, texel, imageLoad(uAccumR, texel) + r);
    imageStore(uAccumG, texel, imageLoad(uAccumG, texel) + g);
    imageStore(uAccumB, texel, imageLoad(uAccumB, texel) + b);
}
#endif
