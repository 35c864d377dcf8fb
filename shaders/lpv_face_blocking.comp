#version 450 core
// Once per frame, after the geometry volume: the blocking potential on the
// +x, +y and +z face of every LPV cell (the average of the 4 GV cells around
// the face centre, docs/lpv.md), so the compute gather reads 6 values per
// cell and step instead of 24.
#define LPV_WITH_GV
#include "sh.glsl"
#include "lpv_common.glsl"
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(rgba32f, binding = 0) uniform writeonly image3D uFaceBlockX;
layout(rgba32f, binding = 1) uniform writeonly image3D uFaceBlockY;
layout(rgba32f, binding = 2) uniform writeonly image3D uFaceBlockZ;

void main() {
    ivec3 texel = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(texel, ivec3(uGridSize, uGridSize, uGridSize * uCascades))))
        return;
    int k = texel.z / uGridSize;
    ivec3 q = ivec3(texel.xy, texel.z % uGridSize);
    // Direction 2a travels along +a: the face between q and q + e_a.
    imageStore(uFaceBlockX, texel, lpvBlockingOnFace(k, q, 0));
    imageStore(uFaceBlockY, texel, lpvBlockingOnFace(k, q, 2));
    imageStore(uFaceBlockZ, texel, lpvBlockingOnFace(k, q, 4));
}
