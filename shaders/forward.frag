#version 450 core
// Direct light: Lambert diffuse + Blinn-Phong specular, one shadow map for
// the first shadow-casting light, emissive. Output is linear HDR radiance.
in vec3 vWorldPos;
in vec3 vNormal;
in vec2 vUv;

out vec4 outColor;

#include "common.glsl"

uniform int uLightCount;
uniform int uLightType[MAX_LIGHTS];
uniform vec3 uLightRadiantColor[MAX_LIGHTS]; // colour * intensity
uniform vec3 uLightPosition[MAX_LIGHTS];
uniform vec3 uLightDirection[MAX_LIGHTS];    // direction the light travels
uniform float uLightRange[MAX_LIGHTS];
uniform vec2 uLightCosCone[MAX_LIGHTS];      // cos(outer), cos(inner)
uniform int uShadowLight;                    // index of the light with the shadow map, -1 = none

uniform sampler2DShadow uShadowMap;
uniform mat4 uShadowViewProj;
uniform float uShadowTexel;     // world-space size of one shadow texel at unit distance (or absolute for ortho)
uniform float uShadowBias;      // in texels
uniform float uShadowSoftness;  // PCF radius in texels
uniform bool uShadowPerspective;

uniform vec3 uCameraPos;
uniform vec3 uDiffuse;
uniform vec3 uSpecular;
uniform float uShininess;
uniform vec3 uEmissive;
uniform bool uTwoSided;

float shadowFactor(vec3 worldPos, vec3 n, vec3 toLight, float dist) {
    // Offset along the normal by the bias in world units of one texel at this
    // distance, growing at grazing angles where one texel spans more depth.
    float texelWorld = uShadowPerspective ? uShadowTexel * dist : uShadowTexel;
    float cosTheta = clamp(dot(n, toLight), 0.0, 1.0);
    float grazing = sqrt(1.0 - cosTheta * cosTheta);
    vec3 p = worldPos + n * (uShadowBias * texelWorld * (1.0 + 2.0 * grazing));
    vec4 clip = uShadowViewProj * vec4(p, 1.0);
    if (clip.w <= 0.0)
        return 1.0;
    vec3 ndc = clip.xyz / clip.w;
    vec3 uvz = ndc * 0.5 + 0.5;
    if (any(lessThan(uvz.xy, vec2(0.0))) || any(greaterThan(uvz.xy, vec2(1.0))) || uvz.z > 1.0)
        return 1.0;
    vec2 texel = 1.0 / vec2(textureSize(uShadowMap, 0));
    float radius = max(uShadowSoftness, 0.0);
    int taps = radius > 0.0 ? 2 : 0;
    float sum = 0.0;
    float count = 0.0;
    for (int y = -taps; y <= taps; ++y)
        for (int x = -taps; x <= taps; ++x) {
            vec2 offset = vec2(x, y) * texel * (radius / 2.0);
            sum += texture(uShadowMap, vec3(uvz.xy + offset, uvz.z));
            count += 1.0;
        }
    return sum / count;
}

void main() {
    vec3 n = normalize(vNormal);
    vec3 v = normalize(uCameraPos - vWorldPos);
    if (uTwoSided && dot(n, v) < 0.0)
        n = -n;

    vec3 radiance = uEmissive;
    for (int i = 0; i < uLightCount && i < MAX_LIGHTS; ++i) {
        vec3 l;
        vec3 irradianceColor;
        float dist = 1.0;
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
        float visibility = (i == uShadowLight) ? shadowFactor(vWorldPos, n, l, dist) : 1.0;
        vec3 h = normalize(l + v);
        // Normalised Blinn-Phong so the specular lobe conserves energy as shininess grows.
        float spec = (uShininess + 8.0) / (8.0 * PI) * pow(max(dot(n, h), 0.0), uShininess);
        radiance += (uDiffuse / PI + uSpecular * spec) * irradianceColor * ndotl * visibility;
    }
    outColor = vec4(radiance, 1.0);
}
