#version 450 core
// Test kernel for ShGlslAgreementGLTest: every function of sh.glsl on a list of
// inputs, so that the GLSL twin can be compared with Sh.h coefficient for coefficient.
#include "sh.glsl"

layout(local_size_x = 64) in;

// Per case: (unit direction, flux), then an SH vector to evaluate.
layout(std430, binding = 0) readonly buffer Inputs { vec4 inputs[]; };
// Per case: basis, cosine lobe, VPL intensity, (evaluate, irradiance, 0, 0).
layout(std430, binding = 1) writeonly buffer Outputs { vec4 outputs[]; };

uniform uint caseCount;

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= caseCount)
        return;
    vec3 w = inputs[2u * i].xyz;
    float flux = inputs[2u * i].w;
    vec4 f = inputs[2u * i + 1u];
    outputs[4u * i + 0u] = shBasis(w);
    outputs[4u * i + 1u] = shCosineLobe(w);
    outputs[4u * i + 2u] = shVplIntensity(w, flux);
    outputs[4u * i + 3u] = vec4(shEvaluate(f, w), shIrradiance(f, w), 0.0, 0.0);
}
