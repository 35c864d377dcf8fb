#version 450 core
// Sun cascades: depth comes from the fixed function; alpha-masked
// materials (leaves, fences) cut holes so they cast masked shadows.
// SHADOW_OPAQUE: the variant for opaque materials, with nothing to cut.
#include "coverage.glsl"

in vec3 vWorldPos;
in vec2 vUv;

void main() {
#ifndef SHADOW_OPAQUE
    // Opaque draws use the SHADOW_OPAQUE variant, which never discards: a
    // shader that can discard defers the depth test, and on llvmpipe that
    // made the sun's cascades about 3x slower (docs/renderer.md).
    if (materialCutOut(vUv))
        discard;
#endif
}
