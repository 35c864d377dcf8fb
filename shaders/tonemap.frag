#version 450 core
// HDR -> display: exposure, tonemapping operator, then sRGB encoding.
in vec2 vUv;
out vec4 outColor;

uniform sampler2D uHdr;
uniform float uExposure; // linear scale, 2^EV (with auto exposure: the compensation)
uniform int uOperator;   // 0 aces, 1 reinhard, 2 uncharted2, 3 linear, 4 neutral (DisplayMapping.h's Tonemapper)
uniform int uAutoExposure; // 1: also scale by the metered exposure (exposure_adapt.comp)
layout(std430, binding = 1) readonly buffer Exposure { float logExposure; float meteredExposure; float valid; float lit; };

vec3 acesFitted(vec3 x) {
    // Narkowicz's fit of the ACES reference rendering transform.
    const float a = 2.51, b = 0.03, c = 2.43, d = 0.59, e = 0.14;
    return clamp((x * (a * x + b)) / (x * (c * x + d) + e), 0.0, 1.0);
}

vec3 uncharted2Curve(vec3 x) {
    const float A = 0.15, B = 0.50, C = 0.10, D = 0.20, E = 0.02, F = 0.30;
    return ((x * (A * x + C * B) + D * E) / (x * (A * x + B) + D * F)) - E / F;
}

// Khronos PBR Neutral as its specification states it (DisplayMapping.cpp's pbrNeutral).
vec3 pbrNeutral(vec3 c) {
    const float f90 = 0.04, startCompression = 0.8 - f90, desaturation = 0.15;
    float x = min(c.r, min(c.g, c.b));
    float offset = x < 2.0 * f90 ? x - x * x / (4.0 * f90) : f90;
    c -= offset;
    float peak = max(c.r, max(c.g, c.b));
    if (peak <= startCompression)
        return c;
    const float d = 1.0 - startCompression;
    float newPeak = 1.0 - d * d / (peak + d - startCompression);
    c *= newPeak / peak;
    float g = 1.0 - 1.0 / (desaturation * (peak - newPeak) + 1.0);
    return c + (vec3(newPeak) - c) * g;
}

vec3 linearToSrgb(vec3 c) {
    c = clamp(c, 0.0, 1.0);
    return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}

void main() {
    float scale = uExposure;
    if (uAutoExposure != 0 && valid > 0.5)
        scale *= meteredExposure;
    vec3 hdr = texture(uHdr, vUv).rgb * scale;
    vec3 mapped;
    if (uOperator == 0)
        mapped = acesFitted(hdr);
    else if (uOperator == 1)
        mapped = hdr / (1.0 + hdr);
    else if (uOperator == 2)
        mapped = uncharted2Curve(2.0 * hdr) / uncharted2Curve(vec3(11.2));
    else if (uOperator == 4)
        mapped = pbrNeutral(hdr);
    else
        mapped = hdr;
    outColor = vec4(linearToSrgb(mapped), 1.0);
}
