#version 450 core
// lpvLookupResolve's second step (LpvLookupResolvePass.cpp): the LPV's
// diffuse lookup (lpv_lookup.glsl's lpvIrradiance, with its cascade blend,
// damping and visibility weights) at full resolution for the pixels
// lpv_lookup_resolve.frag listed (no low-resolution neighbour on their
// surface), written over their texel of the resolved image.
// Variant: LPV_NO_VISIBILITY, as shading's.
#include "sh.glsl"
#include "lpv_lookup.glsl"

layout(local_size_x = 64) in;

struct LpvFallbackEntry {
    float x, y, z;
    uint pixel;
    uint normal;
};
layout(std430, binding = 0) readonly buffer LpvFallbackList {
    uint fallbackCount;
    uint fallbackGroups[3];
    LpvFallbackEntry fallback[];
};
layout(binding = 0, rgba16f) uniform writeonly image2D uLpvResolved;

vec3 fromOctahedral(vec2 p) {
    vec3 n = vec3(p, 1.0 - abs(p.x) - abs(p.y));
    if (n.z < 0.0)
        n.xy = (1.0 - abs(n.yx)) * vec2(n.x >= 0.0 ? 1.0 : -1.0, n.y >= 0.0 ? 1.0 : -1.0);
    return normalize(n);
}

void main() {
    uint i = gl_GlobalInvocationID.x;
    // The last group's spare invocations; past a full list fallbackCount
    // goes on counting, the entries (and the groups) do not.
    if (i >= min(fallbackCount, uint(fallback.length())))
        return;
    LpvFallbackEntry entry = fallback[i];
    vec3 x = vec3(entry.x, entry.y, entry.z);
    vec3 n = fromOctahedral(unpackSnorm2x16(entry.normal));
    vec3 e = uLpvCascadeCount > 0 ? lpvIrradiance(x, n) : vec3(0.0);
    imageStore(uLpvResolved, ivec2(entry.pixel & 0xffffu, entry.pixel >> 16), vec4(e, 1.0));
}
