#version 450 core
// Fixed-point sums (injection, or one compute-scatter step) to floats: the
// result goes to the volume the next step reads and into the accumulator
// (set on injection, added on propagation). The sums are cleared for reuse.
#define LPV_WITH_FIXED_POINT
#include "sh.glsl"
#include "lpv_common.glsl"
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(std430, binding = 0) buffer LpvFixedPoint { int lpvSums[]; };
layout(rgba32f, binding = 0) uniform writeonly image3D uDestR;
layout(rgba32f, binding = 1) uniform writeonly image3D uDestG;
layout(rgba32f, binding = 2) uniform writeonly image3D uDestB;
layout(rgba32f, binding = 3) uniform image3D uAccumR;
layout(rgba32f, binding = 4) uniform image3D uAccumG;
layout(rgba32f, binding = 5) uniform image3D uAccumB;
uniform bool uAccumulate; // false: accumulator = result (injection)

void main() {
    ivec3 texel = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(texel, ivec3(uGridSize, uGridSize, uGridSize * uCascades))))
        return;
    int k = texel.z / uGridSize;
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
}
