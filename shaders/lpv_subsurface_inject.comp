#version 450 core
// Subsurface LPV injection (docs/lpv.md, LpvSubsurfaceReference's
// injectSubsurface): an RSM texel whose material is translucent (flux.a =
// 1 + translucency, rsm.frag) is a VPL pointing into the surface, along -normal, with
// no offset and flux * translucency, summed in fixed point into the sums the
// LPV's injection left cleared (lpv_subsurface_resolve.comp reads them).
// The fixed-point scale is the LPV injection's: flux * translucency never
// exceeds the brightest texel's flux that sets it.
#define LPV_WITH_FIXED_POINT
#include "sh.glsl"
#include "lpv_common.glsl"
layout(local_size_x = 8, local_size_y = 8) in;

uniform sampler2DArray uRsmPosition;
uniform sampler2DArray uRsmNormal;
uniform sampler2DArray uRsmFlux; // rgb flux, a = 1 + translucency (rsm.frag)
uniform vec3 uOrigin[6];
uniform float uCellSize[6];

layout(std430, binding = 0) buffer LpvFixedPoint { int lpvSums[]; }; // 12 per cell: channel * 4 + coefficient

void main() {
    ivec3 texel = ivec3(gl_GlobalInvocationID);
    int k = texel.z;
    ivec3 size = textureSize(uRsmPosition, 0);
    if (k >= uCascades || any(greaterThanEqual(texel.xy, size.xy)))
        return;
    vec4 position = texelFetch(uRsmPosition, texel, 0);
    if (position.w <= 0.0)
        return;
    vec4 fluxTexel = texelFetch(uRsmFlux, texel, 0);
    float translucency = clamp(fluxTexel.a - 1.0, 0.0, 1.0);
    if (!(translucency > 0.0))
        return;
    vec3 rawNormal = texelFetch(uRsmNormal, texel, 0).xyz;
    vec3 flux = max(fluxTexel.rgb, vec3(0.0)) * translucency;
    if (!lpvUsableTexel(position.xyz, rawNormal, flux))
        return;
    vec3 u = (position.xyz - uOrigin[k]) / uCellSize[k];
    // Range-checked as floats: converting a far-away coordinate to int is undefined.
    if (any(lessThan(u, vec3(0.0))) || any(greaterThanEqual(u, vec3(uGridSize))))
        return;
    ivec3 cell = min(ivec3(floor(u)), ivec3(uGridSize - 1));
    vec4 lobe = shCosineLobe(-normalize(rawNormal)) * (lpvFixedScale(k) / SH_PI);
    int base = lpvCellIndex(k, cell) * 12;
    for (int c = 0; c < 3; ++c) {
        if (flux[c] == 0.0)
            continue;
        for (int j = 0; j < 4; ++j)
            atomicAdd(lpvSums[base + c * 4 + j], int(round(flux[c] * lobe[j])));
    }
}
