#version 450 core
// The two GV sources (RSM, camera) merged by maximum: per cell the SH with the
// larger DC coefficient wins, so a surface both see is not counted twice.
// The sums are cleared for the next frame.
#include "sh.glsl"
#include "lpv_common.glsl"
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

const float GV_FIXED_SCALE = 65536.0;
layout(std430, binding = 2) buffer GvFixedPoint { int gvSums[]; };
layout(rgba32f, binding = 0) uniform writeonly image3D uGvOut;

void main() {
    int m = uGridSize + 1;
    ivec3 texel = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(texel, ivec3(m, m, m * uCascades))))
        return;
    int k = texel.z / m;
    int cell = gvCellIndex(k, ivec3(texel.xy, texel.z % m));
    int other = uCascades * m * m * m;
    vec4 a, b;
    for (int j = 0; j < 4; ++j) {
        a[j] = float(gvSums[cell * 4 + j]) / GV_FIXED_SCALE;
        b[j] = float(gvSums[(other + cell) * 4 + j]) / GV_FIXED_SCALE;
        gvSums[cell * 4 + j] = 0;
        gvSums[(other + cell) * 4 + j] = 0;
    }
    imageStore(uGvOut, texel, b.x > a.x ? b : a);
}
