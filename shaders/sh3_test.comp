#version 450 core
// Test kernel for Sh3GlslAgreementGLTest: every function of sh3.glsl on a list
// of inputs, to compare the GLSL twin with ShBands.h coefficient for coefficient.
#include "sh.glsl"
#include "sh3.glsl"

layout(local_size_x = 64) in;

// Per case: (unit direction, flux), then nine coefficients as low, high, (last, 0, 0, 0).
layout(std430, binding = 0) readonly buffer Inputs { vec4 inputs[]; };
// Per case: basis, cosine lobe and VPL intensity as (low, high, (last, a, b, 0)) each,
// a and b: evaluate and irradiance of the input in the basis's third vec4, 0 elsewhere.
layout(std430, binding = 1) writeonly buffer Outputs { vec4 outputs[]; };

uniform uint caseCount;

void write(uint at, Sh9 f, float a, float b) {
    outputs[at] = f.low;
    outputs[at + 1u] = f.high;
    outputs[at + 2u] = vec4(f.last, a, b, 0.0);
}

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= caseCount)
        return;
    vec3 w = inputs[4u * i].xyz;
    float flux = inputs[4u * i].w;
    Sh9 f = Sh9(inputs[4u * i + 1u], inputs[4u * i + 2u], inputs[4u * i + 3u].x);
    write(9u * i, sh9Basis(w), sh9Evaluate(f, w), sh9Irradiance(f, w));
    write(9u * i + 3u, sh9CosineLobe(w), 0.0, 0.0);
    write(9u * i + 6u, sh9VplIntensity(w, flux), 0.0, 0.0);
}
