#version 450 core
// What the sun sees in one RSM tile texel: the surface's world position, its
// normal (turned toward the sun) and the flux it reflects, i.e. one virtual
// point light for the LPV injection.
//
// Flux per texel. A texel covers the area A (uTexelArea) on a plane facing the
// sun. On a surface tilted by theta from that plane the same texel covers
// A / cos(theta), and the irradiance there is E * cos(theta), E being the
// sun's irradiance on a plane facing it. The diffuse power leaving the patch
// is therefore albedo * E * cos(theta) * A / cos(theta) = albedo * E * A:
// independent of the tilt. Summed over a tile it gives albedo * E * (the area
// the surface shadows), the total power the surface reflects. The cosine is
// not lost: a tilted surface covers fewer texels. (Tested by RsmGLTest.)
#include "coverage.glsl"

in vec3 vWorldPos;
in vec3 vNormal;
in vec2 vUv;
flat in float vTexelArea;

uniform vec3 uSunIrradiance;  // light colour * intensity, W/m^2 on a plane facing the sun

layout(location = 0) out vec4 outPosition; // xyz world position, w = 1 where a surface was seen
layout(location = 1) out vec4 outNormal;   // xyz world normal facing the sun, w = 1
layout(location = 2) out vec4 outFlux;     // rgb reflected flux of the texel (W), a = 1 + translucency

void main() {
    if (materialCutOut(vUv))
        discard;
    // The side the sun sees is the side it lights: single-sided geometry seen
    // from behind (the outside of a wall, a leaf's underside) reflects from
    // the face turned to the sun.
    vec3 n = normalize(gl_FrontFacing ? vNormal : -vNormal);
    // Blended surfaces (glass, thin cloth) intercept only the light they cover.
    float intercepted = uAlphaMode == 2 ? materialCoverage(vUv) : 1.0;
    outPosition = vec4(vWorldPos, 1.0);
    outNormal = vec4(n, 1.0);
    // a: 1 + the material's translucency for the subsurface LPV, so that a
    // surface still reads as w != 0 (the debug views' "a surface was seen").
    outFlux = vec4(materialAlbedo(vUv) * uSunIrradiance * (vTexelArea * intercepted), 1.0 + clamp(uTranslucency, 0.0, 1.0));
}
