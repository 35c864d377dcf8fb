#version 450 core
// Directed propagation (docs/lpv.md): the normals volume. Without
// NORMALS_DILATE: the fixed-point sums of lpv_inject.comp become each cell's
// average VPL normal (w = 1 where the cell has VPLs) and are cleared for the
// next frame. With NORMALS_DILATE: one dilation, a cell without normals takes
// the average of its 6 neighbours that have one (LpvReference's dilateNormals).
#include "sh.glsl"
#include "lpv_common.glsl"
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(rgba32f, binding = 0) uniform writeonly image3D uNormalsOut;

#ifdef NORMALS_DILATE
layout(binding = 0) uniform sampler3D uNormalsIn;

vec4 normalAt(int k, ivec3 c) { return texelFetch(uNormalsIn, ivec3(c.xy, k * uGridSize + c.z), 0); }
#else
layout(std430, binding = 3) buffer LpvNormalSums { int normalSums[]; };
uniform int uTexelsPerTile;
#endif

void main() {
    ivec3 texel = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(texel, ivec3(uGridSize, uGridSize, uGridSize * uCascades))))
        return;
    int k = texel.z / uGridSize;
    ivec3 cell = ivec3(texel.xy, texel.z % uGridSize);
#ifdef NORMALS_DILATE
    vec4 own = normalAt(k, cell);
    if (own.w > 0.0) {
        imageStore(uNormalsOut, texel, own);
        return;
    }
    vec3 sum = vec3(0.0);
    float count = 0.0;
    for (int i = 0; i < 6; ++i) {
        ivec3 q = cell + LPV_DIRECTIONS[i];
        if (!lpvInsideCascade(q))
            continue;
        vec4 v = normalAt(k, q);
        if (v.w > 0.0) {
            sum += v.xyz;
            count += 1.0;
        }
    }
    imageStore(uNormalsOut, texel, count > 0.0 ? vec4(sum / count, 1.0) : vec4(0.0));
#else
    int base = lpvCellIndex(k, cell) * 4;
    int count = normalSums[base + 3];
    float normalScale = 1073741824.0 / float(uTexelsPerTile);
    vec3 sum = vec3(normalSums[base], normalSums[base + 1], normalSums[base + 2]) / normalScale;
    imageStore(uNormalsOut, texel, count > 0 ? vec4(sum / float(count), 1.0) : vec4(0.0));
    for (int j = 0; j < 4; ++j)
        normalSums[base + j] = 0;
#endif
}
