#version 450 core
// One propagation step, compute gather (lpv.variant = computeGather): each
// destination cell pulls from its 6 neighbours through its 5 other faces
// (docs/lpv.md) and adds the result to the accumulator. No atomics: every
// invocation owns its cell.
//
// The blocking potential of every face comes precomputed per frame
// (lpv_face_blocking.comp: 6 fetches per cell and step, not 24). A shared-
// memory tile of the sources (8x4x4 cells and a border) fetched less but ran
// 1.6x slower on llvmpipe, whose barriers are expensive; see docs/lpv.md.
#include "sh.glsl"
#include "lpv_common.glsl"
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(binding = 0) uniform sampler3D uSourceR;
layout(binding = 1) uniform sampler3D uSourceG;
layout(binding = 2) uniform sampler3D uSourceB;
// Blocking potential on the +x, +y and +z face of every cell (zero: no occlusion).
layout(binding = 4) uniform sampler3D uFaceBlockX;
layout(binding = 5) uniform sampler3D uFaceBlockY;
layout(binding = 6) uniform sampler3D uFaceBlockZ;
uniform bool uOcclusion;
layout(rgba32f, binding = 0) uniform writeonly image3D uDestR;
layout(rgba32f, binding = 1) uniform writeonly image3D uDestG;
layout(rgba32f, binding = 2) uniform writeonly image3D uDestB;
layout(rgba32f, binding = 3) uniform image3D uAccumR;
layout(rgba32f, binding = 4) uniform image3D uAccumG;
layout(rgba32f, binding = 5) uniform image3D uAccumB;

vec4 faceBlocking(int axis, ivec3 texel) {
    if (!uOcclusion)
        return vec4(0.0);
    if (axis == 0)
        return texelFetch(uFaceBlockX, texel, 0);
    if (axis == 1)
        return texelFetch(uFaceBlockY, texel, 0);
    return texelFetch(uFaceBlockZ, texel, 0);
}

// Light from the neighbour q = p - d (d = sigma e_a), if it is inside and not
// dark. The face it crosses is q's +a face for sigma > 0, p's own for sigma < 0.
void gatherFrom(int a, float sigma, int k, ivec3 p, inout vec3 accDc, inout vec3 nR, inout vec3 nG, inout vec3 nB) {
    ivec3 d = ivec3(0);
    d[a] = int(sigma);
    ivec3 q = p - d;
    if (!lpvInsideCascade(q))
        return;
    ivec3 source = ivec3(q.xy, k * uGridSize + q.z);
    vec4 r = texelFetch(uSourceR, source, 0), g = texelFetch(uSourceG, source, 0), b = texelFetch(uSourceB, source, 0);
    if (r == vec4(0.0) && g == vec4(0.0) && b == vec4(0.0))
        return; // dark neighbours send nothing: skip the face math and the GV
    ivec3 faceCell = sigma > 0.0 ? q : p;
    vec4 blocking = faceBlocking(a, ivec3(faceCell.xy, k * uGridSize + faceCell.z));
    lpvSend(a, sigma, r, g, b, blocking, accDc, nR, nG, nB);
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
    vec4 r = lpvFinishChannel(accDc.r, nR), g = lpvFinishChannel(accDc.g, nG), b = lpvFinishChannel(accDc.b, nB);
    imageStore(uDestR, texel, r);
    imageStore(uDestG, texel, g);
    imageStore(uDestB, texel, b);
    imageStore(uAccumR, texel, imageLoad(uAccumR, texel) + r);
    imageStore(uAccumG, texel, imageLoad(uAccumG, texel) + g);
    imageStore(uAccumB, texel, imageLoad(uAccumB, texel) + b);
}
