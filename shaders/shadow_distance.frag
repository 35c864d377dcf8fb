#version 450 core
// Point and spot maps: store the distance to the light divided by the map's
// far distance, so soft-shadow filtering works in linear distances.
#include "coverage.glsl"

in vec3 vWorldPos;
in vec2 vUv;

uniform vec3 uLightPos;
uniform float uFar;

void main() {
    if (materialCutOut(vUv))
        discard;
    gl_FragDepth = distance(vWorldPos, uLightPos) / uFar;
}
