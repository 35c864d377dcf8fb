#version 450 core
// Test kernel for LpvGlossyGLTest: lpv_glossy.glsl's march on a list of rays,
// so that the GLSL twin can be compared with LpvGlossy.cpp ray by ray.
#include "sh.glsl"
#include "lpv_lookup.glsl"
#include "lpv_glossy.glsl"

layout(local_size_x = 64) in;

// Per case: (origin, glossiness), (unit direction, n.v), (f0, 0).
layout(std430, binding = 0) readonly buffer Inputs { vec4 inputs[]; };
// Per case: (incoming radiance, chosen cascade of the first sample), (reflectance, 0).
layout(std430, binding = 1) writeonly buffer Outputs { vec4 outputs[]; };

uniform uint caseCount;

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= caseCount)
        return;
    vec3 x = inputs[3u * i].xyz;
    float glossiness = inputs[3u * i].w;
    vec3 r = inputs[3u * i + 1u].xyz;
    float nDotV = inputs[3u * i + 1u].w;
    vec3 f0 = inputs[3u * i + 2u].xyz;
    float t0 = uLpvCellSize[0];
    int first = lpvGlossyCascade(x + r * t0, 2.0 * t0 * (1.0 - glossiness));
    outputs[2u * i] = vec4(lpvGlossyIncoming(x, r, glossiness), float(first));
    outputs[2u * i + 1u] = vec4(lpvGlossyReflectance(f0, glossiness, nDotV), 0.0);
}
