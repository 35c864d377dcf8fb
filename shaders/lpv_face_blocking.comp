#version 450 core
// Once per frame, after the geometry volume: the blocking potential on the
// +x, +y and +z face of every LPV cell (the average of the 4 GV cells around
// the face centre, docs/lpv.md), so the compute gather reads 6 values per
// cell and step instead of 24.
#define LPV_WITH_GV
#include "sh.glsl"
#include "sh3.glsl"
#include "lpv_common.glsl"
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

// 3N x N x NK: the +x, +y, +z faces of cell (x, y, z) at texels 3x, 3x + 1, 3x + 2.
layout(rgba32f, binding = 0) uniform writeonly image3D uFaceBlocking;
#if LPV_SH_BANDS == 3
// Band 2 (lpv_gv_merge.comp's uGvHighOut) in, and out on the faces: 6N x N x NK,
// cell (x, y, z)'s face a at texels 6x + 2a (Y2-2..Y21) and 6x + 2a + 1 (Y22).
layout(binding = 5) uniform sampler3D uGvHigh;
layout(rgba32f, binding = 1) uniform writeonly image3D uFaceBlockingHigh;

// lpvBlockingOnFace's average of the 4 GV cells around the face, for band 2.
void storeHighOnFace(int k, ivec3 q, int a, ivec3 texel) {
    ivec3 g = q;
    g[a] += 1;
    ivec3 e1 = ivec3(0), e2 = ivec3(0);
    e1[(a + 1) % 3] = 1;
    e2[(a + 2) % 3] = 1;
    int base = k * (uGridSize + 1);
    vec4 high = vec4(0.0), last = vec4(0.0);
    ivec3 corners[4] = ivec3[4](g, g + e1, g + e2, g + e1 + e2);
    for (int i = 0; i < 4; ++i) {
        ivec3 t = ivec3(2 * corners[i].x, corners[i].y, base + corners[i].z);
        high += texelFetch(uGvHigh, t, 0);
        last += texelFetch(uGvHigh, t + ivec3(1, 0, 0), 0);
    }
    imageStore(uFaceBlockingHigh, ivec3(6 * texel.x + 2 * a, texel.yz), uOcclusion ? 0.25 * high : vec4(0.0));
    imageStore(uFaceBlockingHigh, ivec3(6 * texel.x + 2 * a + 1, texel.yz), uOcclusion ? 0.25 * last : vec4(0.0));
}
#endif

void main() {
    ivec3 texel = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(texel, ivec3(uGridSize, uGridSize, uGridSize * uCascades))))
        return;
    int k = texel.z / uGridSize;
    ivec3 q = ivec3(texel.xy, texel.z % uGridSize);
    // Direction 2a travels along +a: the face between q and q + e_a.
    const ivec3 first = ivec3(3 * texel.x, texel.yz);
    imageStore(uFaceBlocking, first, lpvBlockingOnFace(k, q, 0));
    imageStore(uFaceBlocking, first + ivec3(1, 0, 0), lpvBlockingOnFace(k, q, 2));
    imageStore(uFaceBlocking, first + ivec3(2, 0, 0), lpvBlockingOnFace(k, q, 4));
#if LPV_SH_BANDS == 3
    for (int a = 0; a < 3; ++a)
        storeHighOnFace(k, q, a, texel);
#endif
}
