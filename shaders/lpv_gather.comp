#version 450 core
// One propagation step, compute gather (lpv.variant = computeGather): each
// destination cell pulls from its 6 neighbours through its 5 other faces
// (docs/lpv.md, lpvGather in lpv_common.glsl) and adds the result to the
// accumulator. No atomics: every invocation owns its cell.
//
// The blocking potential of every face comes precomputed per frame
// (lpv_face_blocking.comp: 6 fetches per cell and step, not 24). A shared-
// memory tile of the sources (8x4x4 cells and a border) fetched less but ran
// 1.6x slower on llvmpipe, whose barriers are expensive (docs/lpv.md).
#define LPV_WITH_FACE_BLOCKING
#define LPV_WITH_SOURCES
#define LPV_SOURCE_CELLS
#include "sh.glsl"
#include "lpv_common.glsl"
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(std430, binding = 3) writeonly buffer LpvDestCells { vec4 destCells[]; }; // 3 per cell
// The accumulator as a storage buffer too; lpv_publish.comp copies it into
// the 3D textures the lookup filters, once after the last step.
layout(std430, binding = 5) buffer LpvAccumCells { vec4 accumCells[]; };

void main() {
    ivec3 texel = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(texel, ivec3(uGridSize, uGridSize, uGridSize * uCascades))))
        return;
    vec4 r, g, b;
    int k = texel.z / uGridSize;
    ivec3 p = ivec3(texel.xy, texel.z % uGridSize);
    lpvGather(k, p, r, g, b);
    int i = lpvCellIndex(k, p) * 3;
    destCells[i] = r;
    destCells[i + 1] = g;
    destCells[i + 2] = b;
    accumCells[i] += r;
    accumCells[i + 1] += g;
    accumCells[i + 2] += b;
}
