#version 450 core
// The two GV sources (RSM, camera) merged by maximum: per cell the SH with the
// larger DC coefficient wins, so a surface both see is not counted twice.
// The sums are cleared for the next frame.
#include "sh.glsl"
#include "sh3.glsl"
#include "lpv_common.glsl"
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

const float GV_FIXED_SCALE = 65536.0;
layout(std430, binding = 2) buffer GvFixedPoint { int gvSums[]; };
layout(rgba32f, binding = 0) uniform writeonly image3D uGvOut;
#if LPV_SH_BANDS == 3
// Band 2 of the GV: 2(N+1) x (N+1) x (N+1)K, a GV cell's (Y2-2..Y21) and (Y22, 0, 0, 0) side by side.
layout(rgba32f, binding = 1) uniform writeonly image3D uGvHighOut;
#endif

void main() {
    int m = uGridSize + 1;
    ivec3 texel = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(texel, ivec3(m, m, m * uCascades))))
        return;
    int k = texel.z / m;
    int cell = gvCellIndex(k, ivec3(texel.xy, texel.z % m));
    int other = uCascades * m * m * m;
#if LPV_SH_BANDS == 3
    float a9[9], b9[9];
    for (int j = 0; j < 9; ++j) {
        a9[j] = float(gvSums[cell * 9 + j]) / GV_FIXED_SCALE;
        b9[j] = float(gvSums[(other + cell) * 9 + j]) / GV_FIXED_SCALE;
        gvSums[cell * 9 + j] = 0;
        gvSums[(other + cell) * 9 + j] = 0;
    }
    Sh9 larger = b9[0] > a9[0] ? lpvSh9(b9) : lpvSh9(a9);
    imageStore(uGvOut, texel, larger.low);
    imageStore(uGvHighOut, ivec3(2 * texel.x, texel.yz), larger.high);
    imageStore(uGvHighOut, ivec3(2 * texel.x + 1, texel.yz), vec4(larger.last, 0.0, 0.0, 0.0));
    return;
#endif
    vec4 a, b;
    for (int j = 0; j < 4; ++j) {
        a[j] = float(gvSums[cell * 4 + j]) / GV_FIXED_SCALE;
        b[j] = float(gvSums[(other + cell) * 4 + j]) / GV_FIXED_SCALE;
        gvSums[cell * 4 + j] = 0;
        gvSums[(other + cell) * 4 + j] = 0;
    }
    imageStore(uGvOut, texel, b.x > a.x ? b : a);
}
