#version 450 core
// Reflective shadow maps: world-space vertex; rsm.geom projects it into every tile.
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 3) in vec2 inUv;

uniform mat4 uModel;
uniform mat3 uNormalMatrix;

out vec3 gWorldPos;
out vec3 gNormal;
out vec2 gUv;

void main() {
    vec4 world = uModel * vec4(inPosition, 1.0);
    gWorldPos = world.xyz;
    gNormal = uNormalMatrix * inNormal;
    gUv = inUv;
    gl_Position = world;
}
