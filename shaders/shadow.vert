#version 450 core
// Shadow maps: world-space vertices; shadow.geom projects each triangle into
// every layer (cascade or cube face) of the target in the same pass. With
// SHADOW_NO_GEOMETRY_SHADER (shadow.cascadeDraws = perCascade) each cascade
// is drawn on its own, projected here, into the one layer attached.
layout(location = 0) in vec3 inPosition;
layout(location = 3) in vec2 inUv;

uniform mat4 uModel;

#ifdef SHADOW_NO_GEOMETRY_SHADER
uniform mat4 uViewProj;
out vec3 vWorldPos;
out vec2 vUv;

void main() {
    vWorldPos = vec3(uModel * vec4(inPosition, 1.0));
    vUv = inUv;
    gl_Position = uViewProj * vec4(vWorldPos, 1.0);
}
#else
out vec3 gWorldPos;
out vec2 gUv;

void main() {
    gWorldPos = vec3(uModel * vec4(inPosition, 1.0));
    gUv = inUv;
    gl_Position = vec4(gWorldPos, 1.0);
}
#endif
