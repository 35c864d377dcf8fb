// What every pass that rasterises materials reads: coverage (alpha mask,
// colour key, alpha map, blend opacity) and diffuse albedo. MaterialGpu::bind
// sets these uniforms in Coverage, Reflectance and Full modes.
uniform vec3 uDiffuse;              // linear diffuse reflectance
uniform bool uHasBaseColorMap;
uniform sampler2D uBaseColorMap;    // sRGB texture (decoded to linear on sampling), unit 8
uniform bool uHasAlphaMap;
uniform sampler2D uAlphaMap;        // red channel = alpha, unit 9
uniform int uAlphaMode;             // 0 opaque, 1 mask, 2 blend
uniform float uAlphaCutoff;
uniform float uOpacity;
uniform float uTranslucency;        // 0..1, light that passes through (subsurface LPV)

// Alpha of the material at `uv` (1 for opaque materials).
float materialCoverage(vec2 uv) {
    if (uAlphaMode == 0)
        return 1.0;
    float a = uOpacity;
    if (uHasBaseColorMap)
        a *= texture(uBaseColorMap, uv).a;
    if (uHasAlphaMap)
        a *= texture(uAlphaMap, uv).r;
    return a;
}

// True where a masked material has no surface (discard there).
bool materialCutOut(vec2 uv) {
    return uAlphaMode == 1 && materialCoverage(uv) < uAlphaCutoff;
}

// Linear diffuse albedo at `uv`.
vec3 materialAlbedo(vec2 uv) {
    vec3 albedo = uDiffuse;
    if (uHasBaseColorMap)
        albedo *= texture(uBaseColorMap, uv).rgb;
    return albedo;
}
