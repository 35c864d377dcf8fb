#version 450 core
// Depth-only pass from the light's point of view.
layout(location = 0) in vec3 inPosition;

uniform mat4 uLightViewProj;
uniform mat4 uModel;

void main() {
    gl_Position = uLightViewProj * uModel * vec4(inPosition, 1.0);
}
