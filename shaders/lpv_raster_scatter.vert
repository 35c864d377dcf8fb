#version 450 core
// Raster scatter (lpv.variant = rasterScatter): one point per (source cell,
// direction); it carries what the source sends into that neighbour and lands
// on the neighbour's texel, where additive blending sums the 6 arrivals.
#define LPV_WITH_GV
#define LPV_WITH_DIRECTED
#include "sh.glsl"
#include "lpv_common.glsl"

layout(binding = 0) uniform sampler3D uSourceR;
layout(binding = 1) uniform sampler3D uSourceG;
layout(binding = 2) uniform sampler3D uSourceB;
out int vSlice;
flat out vec4 vR;
flat out vec4 vG;
flat out vec4 vB;

void main() {
    int i = gl_VertexID % 6;
    int cellIndex = gl_VertexID / 6;
    int n = uGridSize;
    ivec3 texel = ivec3(cellIndex % n, (cellIndex / n) % n, cellIndex / (n * n));
    int k = texel.z / n;
    ivec3 q = ivec3(texel.xy, texel.z % n);
    ivec3 p = q + LPV_DIRECTIONS[i];
    vR = vec4(0.0);
    vG = vec4(0.0);
    vB = vec4(0.0);
    vSlice = -1;
    gl_Position = vec4(2.0, 2.0, 0.0, 1.0);
    if (!lpvInsideCascade(p))
        return;
    vec4 r = texelFetch(uSourceR, texel, 0), g = texelFetch(uSourceG, texel, 0), b = texelFetch(uSourceB, texel, 0);
    if (r == vec4(0.0) && g == vec4(0.0) && b == vec4(0.0))
        return;
    lpvPropagateThroughFaces(i, r, g, b, uOcclusionStrength * lpvBlockingOnFace(k, q, i), lpvDirectedNormal(k, p), vR, vG, vB);
    vSlice = k * n + p.z;
    gl_Position = vec4((vec2(p.xy) + 0.5) / float(n) * 2.0 - 1.0, 0.0, 1.0);
}
