#version 450 core
// The subsurface injection's fixed-point sums to floats: into the subsurface
// volume the first step reads and the subsurface accumulator (both V_0), in
// the packed layout of lpv_subsurface.glsl. The sums are cleared for the
// LPV's next use; no scale is recorded (the LPV's scatter slots stay as they are).
#define LPV_WITH_FIXED_POINT
#include "sh.glsl"
#include "lpv_common.glsl"
#include "lpv_subsurface.glsl"
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(std430, binding = 0) buffer LpvFixedPoint { int lpvSums[]; };
layout(rgba32f, binding = 0) uniform writeonly image3D uVolume;
layout(rgba32f, binding = 1) uniform writeonly image3D uAccum;

void main() {
    ivec3 texel = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(texel, ivec3(uGridSize, uGridSize, uGridSize * uCascades))))
        return;
    int k = texel.z / uGridSize;
    ivec3 cell = ivec3(texel.xy, texel.z % uGridSize);
    float scale = lpvFixedScale(k);
    float inverse = scale > 0.0 ? 1.0 / scale : 0.0;
    int base = lpvCellIndex(k, cell) * 12;
    for (int c = 0; c < 3; ++c) {
        vec4 v;
        for (int j = 0; j < 4; ++j) {
            v[j] = float(lpvSums[base + c * 4 + j]) * inverse;
            lpvSums[base + c * 4 + j] = 0;
        }
        imageStore(uVolume, sssTexel(c, k, cell), v);
        imageStore(uAccum, sssTexel(c, k, cell), v);
    }
}
