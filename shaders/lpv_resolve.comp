#version 450 core
// Fixed-point sums (injection, or one compute-scatter step) to floats: the
// result goes to the volume the next step reads and into the accumulator
// (set on injection, added on propagation). The sums are cleared for reuse,
// and the result's largest coefficient is recorded for the next scatter step.
#define LPV_WITH_FIXED_POINT
#include "sh.glsl"
#include "sh3.glsl"
#include "lpv_common.glsl"
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(std430, binding = 0) buffer LpvFixedPoint { int lpvSums[]; };
#if LPV_SH_BANDS == 3
// Three bands (injection only: the compute gather): the interleaved volume the
// first step reads, 7N x N x NK (low R, G, B, high R, G, B, last rgb side by
// side), and band 2 of the accumulator, 4N x N x NK (planes high R, G, B,
// last rgb along x, so the lookup filters each plane alone).
layout(rgba32f, binding = 0) uniform writeonly image3D uDest;
layout(rgba32f, binding = 6) uniform image3D uAccumHigh;
#else
layout(rgba32f, binding = 0) uniform writeonly image3D uDestR;
layout(rgba32f, binding = 1) uniform writeonly image3D uDestG;
layout(rgba32f, binding = 2) uniform writeonly image3D uDestB;
#endif
layout(rgba32f, binding = 3) uniform image3D uAccumR;
layout(rgba32f, binding = 4) uniform image3D uAccumG;
layout(rgba32f, binding = 5) uniform image3D uAccumB;
uniform bool uAccumulate; // false: accumulator = result (injection)
uniform int uRecordSlot;  // where the largest |coefficient| of the result goes (next scatter's scale)

// A work group's 4 slices span at most two cascades (N >= 8): reduce the
// largest coefficient in shared memory first, one global atomic per cascade.
shared uint groupMax[2];

#if LPV_SH_BANDS == 3
// Resolves one cell; returns its largest |coefficient|.
float resolveCell(ivec3 texel, int k) {
    ivec3 cell = ivec3(texel.xy, texel.z % uGridSize);
    float scale = lpvFixedScale(k);
    float inverse = scale > 0.0 ? 1.0 / scale : 0.0;
    int base = lpvCellIndex(k, cell) * 27;
    Sh9 v[3];
    float largest = 0.0;
    for (int c = 0; c < 3; ++c) {
        float f[9];
        for (int j = 0; j < 9; ++j) {
            f[j] = float(lpvSums[base + c * 9 + j]) * inverse;
            lpvSums[base + c * 9 + j] = 0;
            largest = max(largest, abs(f[j]));
        }
        v[c] = lpvSh9(f);
    }
    ivec3 first = ivec3(7 * texel.x, texel.yz);
    for (int c = 0; c < 3; ++c) {
        imageStore(uDest, first + ivec3(c, 0, 0), v[c].low);
        imageStore(uDest, first + ivec3(3 + c, 0, 0), v[c].high);
    }
    vec4 last = vec4(v[0].last, v[1].last, v[2].last, 0.0);
    imageStore(uDest, first + ivec3(6, 0, 0), last);
    ivec3 plane = ivec3(uGridSize, 0, 0);
    if (uAccumulate) {
        v[0].low += imageLoad(uAccumR, texel);
        v[1].low += imageLoad(uAccumG, texel);
        v[2].low += imageLoad(uAccumB, texel);
        for (int c = 0; c < 3; ++c)
            v[c].high += imageLoad(uAccumHigh, texel + c * plane);
        last += imageLoad(uAccumHigh, texel + 3 * plane);
    }
    imageStore(uAccumR, texel, v[0].low);
    imageStore(uAccumG, texel, v[1].low);
    imageStore(uAccumB, texel, v[2].low);
    for (int c = 0; c < 3; ++c)
        imageStore(uAccumHigh, texel + c * plane, v[c].high);
    imageStore(uAccumHigh, texel + 3 * plane, last);
    return largest;
}
#else
// Resolves one cell; returns its largest |coefficient|.
float resolveCell(ivec3 texel, int k) {
    ivec3 cell = ivec3(texel.xy, texel.z % uGridSize);
    float scale = lpvFixedScale(k);
    float inverse = scale > 0.0 ? 1.0 / scale : 0.0;
    int base = lpvCellIndex(k, cell) * 12;
    vec4 v[3];
    for (int c = 0; c < 3; ++c) {
        for (int j = 0; j < 4; ++j) {
            v[c][j] = float(lpvSums[base + c * 4 + j]) * inverse;
            lpvSums[base + c * 4 + j] = 0;
        }
    }
    vec4 largest = max(max(abs(v[0]), abs(v[1])), abs(v[2]));
    imageStore(uDestR, texel, v[0]);
    imageStore(uDestG, texel, v[1]);
    imageStore(uDestB, texel, v[2]);
    if (uAccumulate) {
        v[0] += imageLoad(uAccumR, texel);
        v[1] += imageLoad(uAccumG, texel);
        v[2] += imageLoad(uAccumB, texel);
    }
    imageStore(uAccumR, texel, v[0]);
    imageStore(uAccumG, texel, v[1]);
    imageStore(uAccumB, texel, v[2]);
    return max(max(largest.x, largest.y), max(largest.z, largest.w));
}
#endif

void main() {
    if (gl_LocalInvocationIndex == 0u) {
        groupMax[0] = 0u;
        groupMax[1] = 0u;
    }
    barrier();
    ivec3 texel = ivec3(gl_GlobalInvocationID);
    int firstCascade = int(gl_WorkGroupID.z * gl_WorkGroupSize.z) / uGridSize;
    int k = texel.z / uGridSize;
    bool inside = all(lessThan(texel, ivec3(uGridSize, uGridSize, uGridSize * uCascades)));
    if (inside)
        atomicMax(groupMax[k - firstCascade], floatBitsToUint(resolveCell(texel, k)));
    barrier();
    if (gl_LocalInvocationIndex < 2u && firstCascade + int(gl_LocalInvocationIndex) < uCascades)
        lpvRecordMax(firstCascade + int(gl_LocalInvocationIndex), uRecordSlot,
                     uintBitsToFloat(groupMax[gl_LocalInvocationIndex]));
}

