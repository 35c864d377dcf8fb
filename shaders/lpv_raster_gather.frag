#version 450 core
// Raster gather: the same gather as lpv_gather.comp (lpvGather), for the cell under this
// fragment of this slice. Targets 0-2 take the step's result, 3-5 are the
// accumulator with additive blending.
#define LPV_WITH_FACE_BLOCKING
#define LPV_WITH_DIRECTED
#define LPV_WITH_SOURCES
#include "sh.glsl"
#include "lpv_common.glsl"

flat in int gSlice;
layout(location = 0) out vec4 outR;
layout(location = 1) out vec4 outG;
layout(location = 2) out vec4 outB;
layout(location = 3) out vec4 accumR;
layout(location = 4) out vec4 accumG;
layout(location = 5) out vec4 accumB;

void main() {
    vec4 r, g, b;
    lpvGather(gSlice / uGridSize, ivec3(ivec2(gl_FragCoord.xy), gSlice % uGridSize), r, g, b);
    outR = r;
    outG = g;
    outB = b;
    accumR = r;
    accumG = g;
    accumB = b;
}
