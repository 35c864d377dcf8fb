#version 450 core
// Baked radiosity shown directly: per-vertex radiance, smoothed on the CPU (radiosity/VertexRadiosity.h).
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aRadiance;
uniform mat4 uViewProj;
out vec3 vRadiance;
void main() {
    vRadiance = aRadiance;
    gl_Position = uViewProj * vec4(aPosition, 1.0);
}
