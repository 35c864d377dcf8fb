#version 450 core
// lpvLookupResolve (renderer/src/passes/lpv/LpvLookupResolvePass.cpp): the
// reduced-resolution lookup upsampled (lpv_lookup_upsample.glsl) into an
// image of the view, once per visible opaque or masked pixel, with the depth
// of the camera's pre-pass (or the pass's own) tested before the shader.
// A pixel whose low-resolution neighbours all lie on other surfaces goes on
// a list (position, normal, pixel) that lpv_lookup_fallback.comp looks up at
// full resolution: a branch here would run the lookup under an execution mask
// at every pixel on llvmpipe. The list holds uLpvFallbackCapacity pixels (an
// eighth of the view; measured: under 1% of Sibenik's and Sponza's pixels at
// quarter); past it a pixel keeps the plain bilinear mean of its neighbours.
// Variant: RESOLVE_OPAQUE never discards.
layout(early_fragment_tests) in;
in vec3 vWorldPos;
in vec3 vNormal;
in vec4 vTangent;
in vec2 vUv;

layout(location = 0) out vec4 outIrradiance; // rgb E (replaced where listed), a 1

#include "coverage.glsl"
#include "lpv_lookup_upsample.glsl"

uniform vec3 uCameraPos;
uniform uint uLpvFallbackCapacity; // entries the list has room for

// The pixels the fallback looks up: count, then the compute groups that cover
// them (glDispatchComputeIndirect's x, y, z), then the entries.
struct LpvFallbackEntry {
    float x, y, z; // the position
    uint pixel;    // x | y << 16
    uint normal;   // packSnorm2x16 of the octahedral normal
};
layout(std430, binding = 0) buffer LpvFallbackList {
    uint fallbackCount;
    uint fallbackGroups[3];
    LpvFallbackEntry fallback[];
};
const uint LPV_FALLBACK_GROUP = 64u; // lpv_lookup_fallback.comp's local size

vec2 octahedral(vec3 n) {
    n /= abs(n.x) + abs(n.y) + abs(n.z);
    vec2 p = n.xy;
    if (n.z < 0.0)
        p = (1.0 - abs(n.yx)) * vec2(n.x >= 0.0 ? 1.0 : -1.0, n.y >= 0.0 ? 1.0 : -1.0);
    return p;
}

void main() {
#ifndef RESOLVE_OPAQUE
    if (materialCutOut(vUv))
        discard;
#endif
    vec3 nv = lpvViewerSideNormal(vWorldPos, vNormal, uCameraPos);
    vec3 e;
    if (!lpvIrradianceUpsampled(vWorldPos, nv, uCameraPos, e)) {
        uint i = atomicAdd(fallbackCount, 1u);
        if (i < uLpvFallbackCapacity) {
            if (i % LPV_FALLBACK_GROUP == 0u)
                atomicAdd(fallbackGroups[0], 1u);
            uvec2 pixel = uvec2(gl_FragCoord.xy);
            fallback[i] = LpvFallbackEntry(vWorldPos.x, vWorldPos.y, vWorldPos.z, pixel.x | (pixel.y << 16),
                                           packSnorm2x16(octahedral(nv)));
        }
    }
    outIrradiance = vec4(e, 1.0);
}
