#version 450 core
// One shadow pass for all layers of a layered depth target: invocation i
// projects the triangle with layer i's matrix into layer uFirstLayer + i
// (the sun's cascades, or the six faces of a point light's cube map).
// Triangles wholly outside a layer's volume are dropped there.
// SHADOW_LAYERS (1..8) is defined by ShadowPass per layer count: on
// llvmpipe an idle invocation costs as much as a busy one.
#ifndef SHADOW_LAYERS
#define SHADOW_LAYERS 1
#endif
layout(triangles, invocations = SHADOW_LAYERS) in;
layout(triangle_strip, max_vertices = 3) out;

uniform int uLayerCount;               // 1..8
uniform int uFirstLayer;
uniform mat4 uLayerViewProj[8];

in vec3 gWorldPos[];
in vec2 gUv[];
out vec3 vWorldPos;
out vec2 vUv;

void main() {
    if (gl_InvocationID >= uLayerCount)
        return;
    mat4 m = uLayerViewProj[gl_InvocationID];
    vec4 clip[3];
    for (int i = 0; i < 3; ++i)
        clip[i] = m * vec4(gWorldPos[i], 1.0);
    for (int axis = 0; axis < 3; ++axis) {
        if (clip[0][axis] > clip[0].w && clip[1][axis] > clip[1].w && clip[2][axis] > clip[2].w)
            return;
        if (clip[0][axis] < -clip[0].w && clip[1][axis] < -clip[1].w && clip[2][axis] < -clip[2].w)
            return;
    }
    for (int i = 0; i < 3; ++i) {
        gl_Position = clip[i];
        gl_Layer = uFirstLayer + gl_InvocationID;
        vWorldPos = gWorldPos[i];
        vUv = gUv[i];
        EmitVertex();
    }
    EndPrimitive();
}
