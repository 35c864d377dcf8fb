// Shadow-map sampling for forward shading. ShadowPass::bindForShading sets
// these uniforms; shading calls shadowVisibility() per light.
uniform int uShadowLight;                    // index of the light with the shadow map, -1 = none
uniform sampler2DShadow uShadowMap;
uniform mat4 uShadowViewProj;
uniform float uShadowTexel;     // world-space size of one shadow texel at unit distance (or absolute for ortho)
uniform float uShadowBias;      // in texels
uniform float uShadowSoftness;  // PCF radius in texels
uniform bool uShadowPerspective;

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

// 1 = lit, 0 = in shadow, for light `lightIndex` seen along `toLight` from `worldPos`.
float shadowVisibility(int lightIndex, vec3 worldPos, vec3 n, vec3 toLight, float dist) {
    return lightIndex == uShadowLight ? shadowFactor(worldPos, n, toLight, dist) : 1.0;
}
