#version 450 core
// What a spot or point light sees in one texel of its reflective shadow map
// (LocalRsmPass): world position, normal turned toward the light, and the
// flux the surface reflects, i.e. one VPL for the LPV injection.
//
// Flux per texel. The light's radiant intensity toward the texel is
// I(w) = colour * intensity * spot(w) * window(d) (W/sr; forward.frag's
// attenuation without the 1 / d^2). A texel of a perspective view whose image
// plane lies at distance 1 covers a = (2 tan(fov/2) / size)^2 there; seen from
// the light at angle theta off the view axis it subtends the solid angle
// dOmega = a cos(theta) / (1 / cos(theta))^2 = a cos^3(theta). All the flux
// the light sends into dOmega, I dOmega, lands on the surface in that texel
// whatever its distance and tilt (the 1 / d^2 and the n.l of the irradiance
// cancel against the area d^2 dOmega / n.l the texel covers), and a diffuse
// surface reflects the fraction albedo of it:
//     Phi = albedo * I(w) * a * cos^3(theta).
// An area light is rendered as a point at its centre (six cube faces) whose
// intensity is that of a Lambertian emitter seen from afar: I(w) = L A
// max(w . normal, 0) (|w . normal| when two-sided), uRadiantIntensity = L A.
#include "coverage.glsl"

in vec3 vWorldPos;
in vec3 vNormal;
in vec2 vUv;
flat in float vTexelArea; // rsm.geom passes uTexelArea: here a, the texel's area on the image plane at distance 1

uniform vec3 uLightPosition;
uniform vec3 uFaceAxis;      // this view's axis
uniform vec3 uSpotDirection; // unit; unused for a point light
uniform bool uSpot;
uniform vec2 uCosCone;       // cos(outer), cos(inner)
uniform float uRange;        // 0 = unlimited
uniform vec3 uRadiantIntensity; // colour * intensity, W/sr (an area light: radiance * area)
uniform bool uArea;             // an area light: uSpotDirection is its front normal
uniform bool uTwoSided;

layout(location = 0) out vec4 outPosition;
layout(location = 1) out vec4 outNormal;
layout(location = 2) out vec4 outFlux;

void main() {
    if (materialCutOut(vUv))
        discard;
    vec3 n = normalize(gl_FrontFacing ? vNormal : -vNormal);
    vec3 toTexel = vWorldPos - uLightPosition;
    float d = length(toTexel);
    vec3 w = toTexel / max(d, 1e-6);
    float cosTheta = max(dot(w, uFaceAxis), 0.0);
    float falloff = 1.0;
    if (uRange > 0.0) {
        float r = d / uRange;
        falloff *= clamp(1.0 - r * r * r * r, 0.0, 1.0);
    }
    if (uSpot)
        falloff *= smoothstep(uCosCone.x, uCosCone.y, dot(w, uSpotDirection));
    if (uArea)
        falloff *= uTwoSided ? abs(dot(w, uSpotDirection)) : max(dot(w, uSpotDirection), 0.0);
    float intercepted = uAlphaMode == 2 ? materialCoverage(vUv) : 1.0;
    float solidAngle = vTexelArea * cosTheta * cosTheta * cosTheta;
    outPosition = vec4(vWorldPos, 1.0);
    outNormal = vec4(n, 1.0);
    outFlux = vec4(materialAlbedo(vUv) * uRadiantIntensity * (falloff * solidAngle * intercepted), 1.0);
}
