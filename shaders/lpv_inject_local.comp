#version 450 core
// VPLs of spot and point lights (LocalRsmPass's targets, one layer per face;
// docs/lpv.md, "Local lights, emissive surfaces and bounces"). A face is not
// tied to a cascade as the sun's tiles are, so every texel is injected into
// every cascade that holds it, the same way lpv_inject.comp injects (moved
// lpv.injectionOffset cells along its normal, Phi / pi times a cosine lobe),
// into the same fixed-point sums before the one resolve.
//
// LOCAL_FLUX_MAX: the brightest texel of all faces raises every cascade's
// injection bound (lpv_common.glsl), so the sums cannot overflow; the bound's
// texel count (uTexelsPerTile) then counts the sun's tile and all local texels.
#define LPV_WITH_FIXED_POINT
#include "sh.glsl"
#include "sh3.glsl"
#include "lpv_common.glsl"
layout(local_size_x = 8, local_size_y = 8) in;

uniform sampler2DArray uLocalPosition;
uniform sampler2DArray uLocalFlux;
#ifndef LOCAL_FLUX_MAX
uniform sampler2DArray uLocalNormal;
uniform vec3 uOrigin[6];
uniform float uCellSize[6];
uniform float uInjectionOffset; // cells
layout(std430, binding = 0) buffer LpvFixedPoint { int lpvSums[]; };
// Directed propagation: these VPLs' normals join the sun's in the same sums
// (lpv_inject.comp), so light does not flow back onto the surfaces a spot,
// point or area light lit either.
layout(std430, binding = 3) buffer LpvNormalSums { int normalSums[]; }; // 4 per cell: x, y, z, count
uniform bool uDirected;
#else
shared uint groupMax;
#endif

void main() {
    ivec3 texel = ivec3(gl_GlobalInvocationID);
    ivec3 size = textureSize(uLocalPosition, 0);
#ifdef LOCAL_FLUX_MAX
    if (gl_LocalInvocationIndex == 0u)
        groupMax = 0u;
    barrier();
    if (all(lessThan(texel.xy, size.xy)) && texelFetch(uLocalPosition, texel, 0).w > 0.0) {
        vec3 flux = texelFetch(uLocalFlux, texel, 0).rgb;
        float brightest = max(max(flux.r, flux.g), max(flux.b, 0.0));
        if (isnan(brightest) || isinf(brightest))
            brightest = 0.0;
        atomicMax(groupMax, floatBitsToUint(brightest));
    }
    barrier();
    if (gl_LocalInvocationIndex == 0u)
        for (int k = 0; k < uCascades; ++k)
            atomicMax(lpvScaleData[k], groupMax);
#else
    if (any(greaterThanEqual(texel.xy, size.xy)))
        return;
    vec4 position = texelFetch(uLocalPosition, texel, 0);
    if (position.w <= 0.0)
        return;
    vec3 rawNormal = texelFetch(uLocalNormal, texel, 0).xyz;
    vec3 flux = max(texelFetch(uLocalFlux, texel, 0).rgb, vec3(0.0));
    if (!lpvUsableTexel(position.xyz, rawNormal, flux) || all(equal(flux, vec3(0.0))))
        return;
    vec3 n = normalize(rawNormal);
    for (int k = 0; k < uCascades; ++k) {
        vec3 p = position.xyz + n * (uInjectionOffset * uCellSize[k]);
        vec3 u = (p - uOrigin[k]) / uCellSize[k];
        if (any(lessThan(u, vec3(0.0))) || any(greaterThanEqual(u, vec3(uGridSize))))
            continue;
        ivec3 cell = min(ivec3(floor(u)), ivec3(uGridSize - 1));
        vec4 lobe = shCosineLobe(n) * (lpvFixedScale(k) / SH_PI);
        if (uDirected) {
            int nb = lpvCellIndex(k, cell) * 4;
            float normalScale = 1073741824.0 / float(uTexelsPerTile);
            for (int j = 0; j < 3; ++j)
                atomicAdd(normalSums[nb + j], int(round(n[j] * normalScale)));
            atomicAdd(normalSums[nb + 3], 1);
        }
#if LPV_SH_BANDS == 3
        Sh9 lobe9 = sh9Scale(sh9CosineLobe(n), lpvFixedScale(k) / SH_PI);
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
#endif
}
