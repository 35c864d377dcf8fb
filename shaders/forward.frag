#version 450 core
// Direct light: Lambert diffuse + Blinn-Phong specular, one shadow map for
// the first shadow-casting light, emissive. Output is linear HDR radiance.
in vec3 vWorldPos;
in vec3 vNormal;
in vec2 vUv;

// Colour plus the camera G-buffer (normal, albedo) in one pass; depth is the
// shared depth attachment.
layout(location = 0) out vec4 outColor;
layout(location = 1) out vec4 outNormal; // world normal, xyz in -1..1
layout(location = 2) out vec4 outAlbedo; // diffuse reflectance, linear

#include "common.glsl"
#include "shadow_sampling.glsl"

uniform int uLightCount;
uniform int uLightType[MAX_LIGHTS];
uniform vec3 uLightRadiantColor[MAX_LIGHTS]; // colour * intensity
uniform vec3 uLightPosition[MAX_LIGHTS];
uniform vec3 uLightDirection[MAX_LIGHTS];    // direction the light travels
uniform float uLightRange[MAX_LIGHTS];
uniform vec2 uLightCosCone[MAX_LIGHTS];      // cos(outer), cos(inner)

uniform vec3 uCameraPos;
uniform vec3 uDiffuse;
uniform vec3 uSpecular;
uniform float uShininess;
uniform vec3 uEmissive;
uniform bool uTwoSided;

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
        float visibility = shadowVisibility(i, vWorldPos, n, l, dist);
        vec3 h = normalize(l + v);
        // Normalised Blinn-Phong so the specular lobe conserves energy as shininess grows.
        float spec = (uShininess + 8.0) / (8.0 * PI) * pow(max(dot(n, h), 0.0), uShininess);
        radiance += (uDiffuse / PI + uSpecular * spec) * irradianceColor * ndotl * visibility;
    }
    outColor = vec4(radiance, 1.0);
    outNormal = vec4(n, 1.0);
    outAlbedo = vec4(uDiffuse, 1.0);
}
