#version 450 core
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec4 inTangent;
layout(location = 3) in vec2 inUv;

uniform mat4 uModel;
uniform mat3 uNormalMatrix;
uniform mat4 uViewProj;

out vec3 vWorldPos;
out vec3 vNormal;
out vec2 vUv;

void main() {
    vec4 world = uModel * vec4(inPosition, 1.0);
    vWorldPos = world.xyz;
    vNormal = uNormalMatrix * inNormal;
    vUv = inUv;
    gl_Position = uViewProj * world;
}
