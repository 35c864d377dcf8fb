#version 450 core
// One RSM tile per invocation: every triangle is projected into each tile
// (one layer of the array targets per LPV cascade), so all tiles render in a
// single pass. RsmPass defines RSM_TILES (the tile count) after #version and
// builds one program per count: llvmpipe runs every declared invocation, so
// idle ones would cost as much as working ones.
#ifndef RSM_TILES
#define RSM_TILES 6
#endif
layout(triangles, invocations = RSM_TILES) in;
layout(triangle_strip, max_vertices = 3) out;

const int kMaxTiles = 6; // kMaxRsmCascades in renderer/src/passes/lpv/RsmCascades.h
uniform mat4 uTileViewProj[kMaxTiles];
uniform float uTexelArea[kMaxTiles]; // world area of one texel across the sun's rays

in vec3 gWorldPos[];
in vec3 gNormal[];
in vec2 gUv[];

out vec3 vWorldPos;
out vec3 vNormal;
out vec2 vUv;
flat out float vTexelArea;

void main() {
    int tile = gl_InvocationID;
    vec4 clip[3];
    for (int i = 0; i < 3; ++i)
        clip[i] = uTileViewProj[tile] * gl_in[i].gl_Position;
    // Skip triangles wholly outside one side of this tile's box (the
    // rasteriser would clip them anyway, but not before setting them up).
    for (int axis = 0; axis < 3; ++axis) {
        if (clip[0][axis] > clip[0].w && clip[1][axis] > clip[1].w && clip[2][axis] > clip[2].w)
            return;
        if (clip[0][axis] < -clip[0].w && clip[1][axis] < -clip[1].w && clip[2][axis] < -clip[2].w)
            return;
    }
    for (int i = 0; i < 3; ++i) {
        gl_Position = clip[i];
        gl_Layer = tile;
        vWorldPos = gWorldPos[i];
        vNormal = gNormal[i];
        vUv = gUv[i];
        vTexelArea = uTexelArea[tile];
        EmitVertex();
    }
    EndPrimitive();
}
