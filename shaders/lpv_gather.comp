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
