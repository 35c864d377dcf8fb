#version 450 core
// Once per frame, after the geometry volume: the blocking potential on the
// +x, +y and +z face of every LPV cell (the average of the 4 GV cells around
// the face centre, docs/lpv.md), so the compute gather reads 6 values per
// cell and step instead of 24.
#define LPV_WITH_GV
#include "sh.glsl"
#include "lpv_common.glsl"
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

// 3N x N x NK: the +x, +y, +z faces of cell (x, y, z) at texels 3x, 3x + 1, 3x + 2.
layout(rgba32f, binding = 0) uniform writeonly image3D uFaceBlocking;

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
}
