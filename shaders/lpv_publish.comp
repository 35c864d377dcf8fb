#version 450 core
// After the compute gather's last step: its accumulator (a storage buffer,
// 3 vec4 per cell) into the 3D textures the lookup samples with trilinear
// filtering.
#include "sh.glsl"
#include "lpv_common.glsl"
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(std430, binding = 5) readonly buffer LpvAccumCells { vec4 accumCells[]; };
layout(rgba32f, binding = 3) uniform writeonly image3D uAccumR;
layout(rgba32f, binding = 4) uniform writeonly image3D uAccumG;
layout(rgba32f, binding = 5) uniform writeonly image3D uAccumB;

void main() {
    ivec3 texel = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(texel, ivec3(uGridSize, uGridSize, uGridSize * uCascades))))
        return;
    int i = lpvCellIndex(texel.z / uGridSize, ivec3(texel.xy, texel.z % uGridSize)) * 3;
    imageStore(uAccumR, texel, accumCells[i]);
    imageStore(uAccumG, texel, accumCells[i + 1]);
    imageStore(uAccumB, texel, accumCells[i + 2]);
}
