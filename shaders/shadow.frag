#version 450 core
// Sun cascades: depth comes from the fixed function; alpha-masked
// materials (leaves, fences) cut holes so they cast masked shadows.
#include "coverage.glsl"

in vec3 vWorldPos;
in vec2 vUv;

void main() {
    if (materialCutOut(vUv))
        discard;
}
