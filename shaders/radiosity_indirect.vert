#version 450 core
// The radiosityIndirect pass (RadiosityIndirectPass.cpp): a baked solution's
// patches with the incident light smoothed to their corners on the CPU
// (radiosity/VertexRadiosity.h).
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aIncident;
layout(location = 2) in vec3 aNormal;
uniform mat4 uViewProj;
out vec3 vWorldPos;
out vec3 vIncident;
flat out vec3 vNormal;
void main() {
    vWorldPos = aPosition;
    vIncident = aIncident;
    vNormal = aNormal;
    gl_Position = uViewProj * vec4(aPosition, 1.0);
}
