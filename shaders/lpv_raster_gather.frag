#version 450 core
// Raster gather: the same gather as lpv_gather.comp, for the cell under this
// fragment of this slice. Targets 0-2 take the step's result, 3-5 are the
// accumulator with additive blending.
#define LPV_WITH_GV
#include "sh.glsl"
#include "lpv_common.glsl"

flat in int gSlice;
layout(binding = 0) uniform sampler3D uSourceR;
layout(binding = 1) uniform sampler3D uSourceG;
layout(binding = 2) uniform sampler3D uSourceB;
layout(location = 0) out vec4 outR;
layout(location = 1) out vec4 outG;
layout(location = 2) out vec4 outB;
layout(location = 3) out vec4 accumR;
layout(location = 4) out vec4 accumG;
layout(location = 5) out vec4 accumB;

void main() {
    int k = gSlice / uGridSize;
    ivec3 p = ivec3(ivec2(gl_FragCoord.xy), gSlice % uGridSize);
    vec4 r = vec4(0.0), g = vec4(0.0), b = vec4(0.0);
    for (int i = 0; i < 6; ++i) {
        ivec3 q = p - LPV_DIRECTIONS[i];
        if (!lpvInsideCascade(q))
            continue;
        ivec3 source = ivec3(q.xy, k * uGridSize + q.z);
        vec4 sr = texelFetch(uSourceR, source, 0), sg = texelFetch(uSourceG, source, 0),
             sb = texelFetch(uSourceB, source, 0);
        if (sr == vec4(0.0) && sg == vec4(0.0) && sb == vec4(0.0))
            continue; // dark neighbours send nothing: skip the face math and the GV
        lpvPropagateThroughFaces(i, sr, sg, sb, lpvBlockingOnFace(k, q, i), r, g, b);
    }
    outR = r;
    outG = g;
    outB = b;
    accumR = r;
    accumG = g;
    accumB = b;
}
