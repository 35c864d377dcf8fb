#version 450 core
// The brightest texel of every RSM tile (largest colour channel of its flux):
// the fixed-point scale of the injection follows it (lpv_common.glsl).
#define LPV_WITH_FIXED_POINT
#include "sh.glsl"
#include "lpv_common.glsl"
layout(local_size_x = 8, local_size_y = 8) in;

uniform sampler2DArray uRsmPosition;
uniform sampler2DArray uRsmFlux;

shared uint groupMax;

void main() {
    if (gl_LocalInvocationIndex == 0u)
        groupMax = 0u;
    barrier();
    ivec3 texel = ivec3(gl_GlobalInvocationID);
    ivec3 size = textureSize(uRsmFlux, 0);
    if (all(lessThan(texel.xy, size.xy)) && texelFetch(uRsmPosition, texel, 0).w > 0.0) {
        vec3 flux = texelFetch(uRsmFlux, texel, 0).rgb;
        float brightest = max(max(flux.r, flux.g), max(flux.b, 0.0));
        if (isnan(brightest) || isinf(brightest))
            brightest = 0.0; // the injection skips such texels too
        // Non-negative floats order like their bit patterns.
        atomicMax(groupMax, floatBitsToUint(brightest));
    }
    barrier();
    if (gl_LocalInvocationIndex == 0u)
        atomicMax(lpvScaleData[texel.z], groupMax);
}
