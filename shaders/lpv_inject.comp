#version 450 core
// VPL injection (docs/lpv.md): every RSM texel of tile k is a VPL moved
// lpv.injectionOffset cells along its normal, projected as Phi/pi times a
// clamped cosine lobe into the cell of cascade k it falls in, summed in fixed
// point with integer atomics (lpv_resolve.comp turns the sums into floats).
#define LPV_WITH_FIXED_POINT
#include "sh.glsl"
#include "sh3.glsl"
#include "lpv_common.glsl"
layout(local_size_x = 8, local_size_y = 8) in;

uniform sampler2DArray uRsmPosition;
uniform sampler2DArray uRsmNormal;
uniform sampler2DArray uRsmFlux;
uniform vec3 uOrigin[6];
uniform float uCellSize[6];
uniform float uInjectionOffset; // cells

layout(std430, binding = 0) buffer LpvFixedPoint { int lpvSums[]; }; // 3 B^2 per cell: channel * B^2 + coefficient
// Directed propagation: per cell the VPL normals' sum in fixed point and their
// count (lpv_normals.comp averages them). Scale 2^30 / texels per tile: even
// every texel of a tile in one cell stays below 2^30.
layout(std430, binding = 3) buffer LpvNormalSums { int normalSums[]; }; // 4 per cell: x, y, z, count
uniform bool uDirected;

void main() {
    ivec3 texel = ivec3(gl_GlobalInvocationID);
    int k = texel.z;
    ivec3 size = textureSize(uRsmPosition, 0);
    if (k >= uCascades || any(greaterThanEqual(texel.xy, size.xy)))
        return;
    vec4 position = texelFetch(uRsmPosition, texel, 0);
    if (position.w <= 0.0)
        return;
    vec3 rawNormal = texelFetch(uRsmNormal, texel, 0).xyz;
    vec3 flux = max(texelFetch(uRsmFlux, texel, 0).rgb, vec3(0.0));
    if (!lpvUsableTexel(position.xyz, rawNormal, flux))
        return;
    vec3 n = normalize(rawNormal);
    vec3 p = position.xyz + n * (uInjectionOffset * uCellSize[k]);
    vec3 u = (p - uOrigin[k]) / uCellSize[k];
    // Range-checked as floats: converting a far-away coordinate to int is undefined.
    if (any(lessThan(u, vec3(0.0))) || any(greaterThanEqual(u, vec3(uGridSize))))
        return;
    ivec3 cell = min(ivec3(floor(u)), ivec3(uGridSize - 1));
    float scale = lpvFixedScale(k);
    vec4 lobe = shCosineLobe(n) * (scale / SH_PI);
    if (uDirected) {
        int nb = lpvCellIndex(k, cell) * 4;
        float normalScale = 1073741824.0 / float(uTexelsPerTile);
        for (int j = 0; j < 3; ++j)
            atomicAdd(normalSums[nb + j], int(round(n[j] * normalScale)));
        atomicAdd(normalSums[nb + 3], 1);
    }
#if LPV_SH_BANDS == 3
    Sh9 lobe9 = sh9Scale(sh9CosineLobe(n), scale / SH_PI);
    int base = lpvCellIndex(k, cell) * 27;
    for (int c = 0; c < 3; ++c) {
        if (flux[c] == 0.0)
            continue;
        for (int j = 0; j < 9; ++j)
            atomicAdd(lpvSums[base + c * 9 + j], int(round(flux[c] * lpvCoeff(lobe9, j))));
    }
#else
    int base = lpvCellIndex(k, cell) * 12;
    for (int c = 0; c < 3; ++c) {
        if (flux[c] == 0.0)
            continue;
        for (int j = 0; j < 4; ++j)
            atomicAdd(lpvSums[base + c * 4 + j], int(round(flux[c] * lobe[j])));
    }
#endif
}
