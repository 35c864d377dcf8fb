#version 450 core
// Variants (ShadingPass::variant): LPV_AREA_LIGHTS compiles the area-light
// code in; LPV_NO_LOCAL_SHADOWS, LPV_NO_VISIBILITY, LPV_NO_GLOSSY and
// LPV_NO_SUBSURFACE_LOOKUP leave out what a frame does not run. On llvmpipe
// code that is compiled in but never taken still slows every pixel.
// LPV_SCREEN_INDIRECT (a pass declared an image of the indirect light,
// frame/IndirectLight.h; gi.method = radiosity draws a baked solution's)
// takes the indirect light from that image at this pixel
// (screen_indirect.glsl) instead of the LPV, whose lookups it leaves out.
// LPV_LOOKUP_RESOLVED (lpv.lookupResolution = half|quarter, opaque and
// masked surfaces) takes the LPV's diffuse light from the lpvLookupResolve
// pass's image of the view at this pixel (lpv_lookup_resolved.glsl): no
// diffuse LPV lookup is compiled in.
// Direct light: Blinn-Phong or glTF metallic-roughness (material.glsl,
// brdf.glsl) with normal maps, shadows per light (shadow_sampling.glsl),
// emissive. Output is linear HDR radiance; blended materials output it
// premultiplied by their coverage.
#ifdef LPV_AFTER_DEPTH_PREPASS
// The depth pre-pass left the nearest surface's depth: test it before
// shading. Without this, the discard below would defer the test until after
// the lighting, and every hidden fragment would be lit for nothing.
layout(early_fragment_tests) in;
#endif
in vec3 vWorldPos;
in vec3 vNormal;
in vec4 vTangent;
in vec2 vUv;

// Colour plus the camera G-buffer (normal, albedo) in one pass; depth is the
// shared depth attachment. Blended draws leave the G-buffer alone (colour mask).
layout(location = 0) out vec4 outColor;
layout(location = 1) out vec4 outNormal; // shading normal (after normal mapping), world, xyz in -1..1
layout(location = 2) out vec4 outAlbedo; // diffuse reflectance, linear; a = coverage

#include "common.glsl"
#include "coverage.glsl"
#include "brdf.glsl"
#include "material.glsl"
#include "shadow_sampling.glsl"
#ifdef LPV_AREA_LIGHTS
#include "area_light.glsl"
#endif
#ifdef LPV_SCREEN_INDIRECT
#include "screen_indirect.glsl"
#else
#include "sh.glsl"
#include "lpv_lookup.glsl"
#include "lpv_subsurface_lookup.glsl"
#include "lpv_glossy.glsl"
#ifdef LPV_LOOKUP_RESOLVED
// lpv.lookupResolution = half|quarter: the reduced-resolution lookup, resolved to this pixel.
#include "lpv_lookup_resolved.glsl"
#define LPV_DIFFUSE_IRRADIANCE(x, n) lpvIrradianceResolved()
#else
#define LPV_DIFFUSE_IRRADIANCE(x, n) lpvIrradiance(x, n)
#endif
#endif

uniform int uLightCount;
uniform int uLightType[MAX_LIGHTS];
uniform vec3 uLightRadiantColor[MAX_LIGHTS]; // colour * intensity; an area light's radiance
uniform vec3 uLightPosition[MAX_LIGHTS];     // an area light's centre
uniform vec3 uLightDirection[MAX_LIGHTS];    // direction the light travels; an area light's front normal
uniform float uLightRange[MAX_LIGHTS];
uniform vec2 uLightCosCone[MAX_LIGHTS];      // cos(outer), cos(inner)
uniform vec3 uLightHalfU[MAX_LIGHTS];        // area lights: half the width along the tangent (a disc: radius)
uniform vec3 uLightHalfV[MAX_LIGHTS];        // area lights: half the height
uniform int uLightAreaShape[MAX_LIGHTS];     // area lights: 0 rectangle, 1 disc
uniform int uLightTwoSided[MAX_LIGHTS];      // area lights: 1 = emits from both sides

uniform vec3 uCameraPos;
// output.view: 0 final image; 1 the LPV's indirect irradiance (W/m^2, no
// albedo, the quantity the path-traced reference's indirect channel holds);
// 2 direct light and emission only. Blended surfaces add nothing to 1.
uniform int uOutputView;
uniform int uShadowCascadeTint; // 1: tint by sun shadow cascade (ForwardRenderer::setShadowCascadeTint)

void main() {
    if (materialCutOut(vUv))
        discard;
    vec3 v = normalize(uCameraPos - vWorldPos);
    Surface s = materialSurface(vNormal, vTangent, vUv, vWorldPos, v);
    vec3 n = s.normal;

    vec3 radiance = s.emissive;
    for (int i = 0; i < uLightCount && i < MAX_LIGHTS; ++i) {
        vec3 l;
        vec3 irradianceColor;
        float dist = 1.0;
#ifdef LPV_AREA_LIGHTS
        if (uLightType[i] == LIGHT_AREA) {
            // Exact diffuse irradiance of the polygon and the specular lobe by LTC (area_light.glsl).
            vec3 lightNormal = normalize(uLightDirection[i]);
            bool twoSided = uLightTwoSided[i] != 0;
            vec3 polygon[AREA_DISC_SIDES];
            int count;
            float factor = areaLightFactor(uLightPosition[i], lightNormal, uLightHalfU[i], uLightHalfV[i],
                                           uLightAreaShape[i], twoSided, vWorldPos, n, l, polygon, count);
            if (factor <= 0.0)
                continue;
            float visibility =
                areaShadowVisibility(i, vWorldPos, n, uLightPosition[i], lightNormal, uLightHalfU[i], uLightHalfV[i],
                                     uLightAreaShape[i], twoSided);
            radiance += areaLightReflectance(s, l, v, factor, polygon, count, uLightPosition[i], lightNormal,
                                             uLightHalfU[i], uLightHalfV[i], uLightAreaShape[i], vWorldPos) *
                        uLightRadiantColor[i] * visibility;
            continue;
        }
#else
        if (uLightType[i] == LIGHT_AREA)
            continue; // this variant shades scenes without area lights
#endif
        if (uLightType[i] == LIGHT_DIRECTIONAL) {
            l = -normalize(uLightDirection[i]);
            irradianceColor = uLightRadiantColor[i];
        } else {
            vec3 d = uLightPosition[i] - vWorldPos;
            dist = length(d);
            l = d / max(dist, 1e-6);
            float atten = 1.0 / max(dist * dist, 1e-8);
            if (uLightRange[i] > 0.0) {
                // Smooth window so the light reaches zero at its range (glTF convention).
                float r = dist / uLightRange[i];
                atten *= clamp(1.0 - r * r * r * r, 0.0, 1.0);
            }
            if (uLightType[i] == LIGHT_SPOT) {
                float cosAngle = dot(-l, normalize(uLightDirection[i]));
                atten *= smoothstep(uLightCosCone[i].x, uLightCosCone[i].y, cosAngle);
            }
            irradianceColor = uLightRadiantColor[i] * atten;
        }
        float ndotl = max(dot(n, l), 0.0);
        if (ndotl <= 0.0)
            continue;
        float visibility = shadowVisibility(i, vWorldPos, n, l, dist);
        radiance += surfaceBrdf(s, l, v) * irradianceColor * ndotl * visibility;
    }
    if (uOutputView == 1) {
#ifdef LPV_SCREEN_INDIRECT
        vec3 e = PI * indirectIncident() * s.occlusion;
#else
        vec3 e = uLpvCascadeCount > 0 ? LPV_DIFFUSE_IRRADIANCE(vWorldPos, n) * s.occlusion : vec3(0.0);
#endif
        outColor = uAlphaMode == 2 ? vec4(0.0) : vec4(e, 1.0);
        outNormal = vec4(n, 1.0);
        outAlbedo = vec4(s.albedo, 1.0);
        return;
    }
#ifdef LPV_SCREEN_INDIRECT
    // Indirect diffuse light from the image: Lambert's albedo / pi times the
    // irradiance E, and the image holds E / pi.
    if (uOutputView == 0) {
        vec3 diffuseAlbedo = uShadingModel == 1 ? s.albedo * (1.0 - s.metallic) : s.albedo;
        radiance += diffuseAlbedo * indirectIncident() * s.occlusion;
    }
#else
    // Indirect diffuse light from the LPV; metals have no diffuse part.
    if (uLpvCascadeCount > 0 && uOutputView == 0) {
        vec3 diffuseAlbedo = uShadingModel == 1 ? s.albedo * (1.0 - s.metallic) : s.albedo;
        radiance += diffuseAlbedo / PI * LPV_DIFFUSE_IRRADIANCE(vWorldPos, n) * s.occlusion;
        // Subsurface LPV: light that crossed a translucent material leaves through its other side.
#ifndef LPV_NO_SUBSURFACE_LOOKUP
        if (uTranslucency > 0.0)
            radiance += diffuseAlbedo / PI * lpvSubsurfaceIrradiance(vWorldPos, n) * uTranslucency;
#endif
    }
#endif
#if !defined(LPV_NO_GLOSSY) && !defined(LPV_SCREEN_INDIRECT)
    // Glossy reflections: the LPV ray-marched along the reflection vector (lpv_glossy.glsl).
    if (uOutputView == 0 && lpvGlossyRuns(uGlossiness)) {
        vec3 f0 = uShadingModel == 1 ? mix(vec3(0.04), s.albedo, s.metallic) : max(s.specular, vec3(0.04));
        radiance += lpvGlossyReflection(vWorldPos, n, v, f0, uGlossiness) * s.occlusion;
    }
#endif
    if (uShadowCascadeTint != 0 && uSunShadowLight >= 0) {
        const vec3 tints[6] = vec3[6](vec3(1.0, 0.35, 0.35), vec3(0.35, 0.86, 0.35), vec3(0.35, 0.6, 1.0),
                                      vec3(1.0, 0.82, 0.24), vec3(0.86, 0.35, 1.0), vec3(0.31, 0.9, 0.9));
        int k = sunCascadeIndex(vWorldPos);
        if (k >= 0) // the tint keeps the surface's brightness, so shadows still read
            radiance = mix(radiance, tints[k % 6] * max(dot(radiance, vec3(0.2126, 0.7152, 0.0722)), 0.05), 0.6);
    }
    float coverage = uAlphaMode == 2 ? clamp(materialCoverage(vUv), 0.0, 1.0) : 1.0;
    outColor = vec4(radiance * coverage, coverage);
    outNormal = vec4(n, 1.0);
    outAlbedo = vec4(s.albedo, 1.0);
}
