#version 450 core
// One propagation step, compute gather (lpv.variant = computeGather): each
// destination cell pulls from its 6 neighbours through its 5 other faces
// (docs/lpv.md) and adds the result to the accumulator. No atomics: every
// invocation owns its cell.
#define LPV_WITH_GV
#include "sh.glsl"
#include "lpv_common.glsl"
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

uniform sampler3D uSourceR;
uniform sampler3D uSourceG;
uniform sampler3D uSourceB;
layout(rgba32f, binding = 0) uniform writeonly image3D uDestR;
layout(rgba32f, binding = 1) uniform writeonly image3D uDestG;
layout(rgba32f, binding = 2) uniform writeonly image3D uDestB;
layout(rgba32f, binding = 3) uniform image3D uAccumR;
layout(rgba32f, binding = 4) uniform image3D uAccumG;
layout(rgba32f, binding = 5) uniform image3D uAccumB;

void main() {
    ivec3 texel = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(texel, ivec3(uGridSize, uGridSize, uGridSize * uCascades))))
        return;
    int k = texel.z / uGridSize;
    ivec3 p = ivec3(texel.xy, texel.z % uGridSize);
    vec4 r = vec4(0.0), g = vec4(0.0), b = vec4(0.0);
    for (int i = 0; i < 6; ++i) {
        ivec3 q = p - LPV_DIRECTIONS[i];
        if (!lpvInsideCascade(q))
            continue;
        ivec3 source = ivec3(q.xy, k * uGridSize + q.z);
        lpvPropagateThroughFaces(i, texelFetch(uSourceR, source, 0), texelFetch(uSourceG, source, 0),
                                 texelFetch(uSourceB, source, 0), lpvBlockingOnFace(k, q, i), r, g, b);
    }
    imageStore(uDestR, texel, r);
    imageStore(uDestG, texel, g);
    imageStore(uDestB, texel, b);
    imageStore(uAccumR, texel, imageLoad(uAccumR, texel) + r);
    imageStore(uAccumG, texel, imageLoad(uAccumG, texel) + g);
    imageStore(uAccumB, texel, imageLoad(uAccumB, texel) + b);
}
