#version 450 core
// Shadow maps: world-space vertices; shadow.geom projects each triangle into
// every layer (cascade or cube face) of the target in the same pass.
layout(location = 0) in vec3 inPosition;
layout(location = 3) in vec2 inUv;

uniform mat4 uModel;

out vec3 gWorldPos;
out vec2 gUv;

void main() {
    gWorldPos = vec3(uModel * vec4(inPosition, 1.0));
    gUv = inUv;
    gl_Position = vec4(gWorldPos, 1.0);
}
