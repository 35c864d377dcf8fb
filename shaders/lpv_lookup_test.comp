#version 450 core
// Test kernel for LpvVisibilityGLTest and the thin-wall hard case:
// lpv_lookup.glsl's lookup of one cascade (lpvIrradianceRaw, with the
// visibility-aware path when uLpvVisibility is set) at a list of points, so
// that it can be compared with its CPU twin point by point.
#include "sh.glsl"
#include "lpv_lookup.glsl"

layout(local_size_x = 64) in;

// Per case: (position, 0), (unit normal, 0).
layout(std430, binding = 0) readonly buffer Inputs { vec4 inputs[]; };
// Per case: (irradiance times s^-2 as lpvIrradianceRaw returns it, 0).
layout(std430, binding = 1) writeonly buffer Outputs { vec4 outputs[]; };

uniform uint caseCount;
uniform int uCascade;

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= caseCount)
        return;
    outputs[i] = vec4(lpvIrradianceRaw(uCascade, inputs[2u * i].xyz, inputs[2u * i + 1u].xyz), 0.0);
}
