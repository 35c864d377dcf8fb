#version 450 core
// Reflective shadow maps: world-space vertex; rsm.geom projects it into every
// tile (rsm.tileDraws = geometryShader).
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 3) in vec2 inUv;

uniform mat4 uModel;
uniform mat3 uNormalMatrix;

#ifdef RSM_NO_GEOMETRY_SHADER
// rsm.tileDraws = perTile: one tile per draw, projected here (no rsm.geom).
uniform mat4 uViewProj;
uniform float uTileTexelArea;
out vec3 vWorldPos;
out vec3 vNormal;
out vec2 vUv;
flat out float vTexelArea;

void main() {
    vec4 world = uModel * vec4(inPosition, 1.0);
    vWorldPos = world.xyz;
    vNormal = uNormalMatrix * inNormal;
    vUv = inUv;
    vTexelArea = uTileTexelArea;
    gl_Position = uViewProj * world;
}
#else
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
#endif
