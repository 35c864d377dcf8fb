#version 450 core
// The camera's depth pre-pass (renderer/src/frame/FramePasses.cpp): depth only,
// alpha-mask cut-outs included, so that shading (forward.frag with
// LPV_AFTER_DEPTH_PREPASS) runs its lighting once per visible pixel.
#include "coverage.glsl"

in vec3 vWorldPos;
in vec3 vNormal;
in vec4 vTangent;
in vec2 vUv;

void main() {
#ifndef PREPASS_OPAQUE // opaque materials use the variant that never discards: early depth tests
    if (materialCutOut(vUv))
        discard;
#endif
}
