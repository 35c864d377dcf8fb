#version 450 core
// lpvLookup (renderer/src/passes/lpv/LpvLookupPass.cpp): the LPV's diffuse
// lookup, lpv_lookup.glsl's lpvIrradiance as shading calls it, at 1/2 or 1/4
// of the view's resolution, with what shading's upsampling
// (lpv_lookup_upsample.glsl) weighs its neighbours by. Variants: LOOKUP_OPAQUE
// never discards; LPV_NO_VISIBILITY leaves out the
// visibility-aware lookup when the frame has no moments, as shading does.
// The pass drew the depth first: test it before the lookup runs.
layout(early_fragment_tests) in;
in vec3 vWorldPos;
in vec3 vNormal;
in vec4 vTangent;
in vec2 vUv;

layout(location = 0) out vec4 outIrradiance; // rgb lpvIrradiance; a the distance from the camera x uLpvLowDistanceScale
layout(location = 1) out vec4 outNormal;     // the vertex normal seen from the camera's side, n * 0.5 + 0.5

#include "coverage.glsl"
#include "sh.glsl"
#include "lpv_lookup.glsl"

uniform vec3 uCameraPos;
uniform float uLpvLowDistanceScale; // 1 / the camera's far plane: distances fit a half float at any scale

void main() {
#ifndef LOOKUP_OPAQUE
    if (materialCutOut(vUv))
        discard;
#endif
    // The interpolated normal on the side the surface is seen from, by
    // material.glsl's rule (the geometric normal turned to the viewer
    // decides). Without the normal map: at this resolution it would be a
    // sample of its finest detail, and the upsampling compares smooth normals.
    vec3 toViewer = uCameraPos - vWorldPos;
    vec3 ng = cross(dFdx(vWorldPos), dFdy(vWorldPos));
    if (dot(ng, toViewer) < 0.0)
        ng = -ng;
    vec3 n = normalize(vNormal);
    if (dot(n, ng) < 0.0)
        n = -n;
    vec3 e = uLpvCascadeCount > 0 ? lpvIrradiance(vWorldPos, n) : vec3(0.0);
    outIrradiance = vec4(e, length(toViewer) * uLpvLowDistanceScale);
    outNormal = vec4(n * 0.5 + 0.5, 1.0);
}
