#version 450 core
// Patch-ID rendering into one hemicube face (renderer/src/passes/radiosity/GpuHemicube.cpp).
layout(location = 0) in vec3 aPosition;
layout(location = 1) in uint aPatchId;
uniform mat4 uViewProj;
flat out uint vPatchId;
void main() {
    vPatchId = aPatchId;
    gl_Position = uViewProj * vec4(aPosition, 1.0);
}
