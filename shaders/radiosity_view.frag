#version 450 core
// Exposure, the ACES fit and sRGB encoding in one step: this view has no
// other passes to share an HDR target with. uFlat draws the patch wireframe.
// The second target keeps the linear radiance (readRadiance, compared with
// the path-traced reference).
in vec3 vRadiance;
uniform float uExposureScale;
uniform vec3 uFlatColor;
uniform bool uFlat;
layout(location = 0) out vec4 outColor;
layout(location = 1) out vec4 outRadiance;
vec3 acesFitted(vec3 x) {
    const float a = 2.51, b = 0.03, c = 2.43, d = 0.59, e = 0.14;
    return clamp((x * (a * x + b)) / (x * (c * x + d) + e), 0.0, 1.0);
}
vec3 toSrgb(vec3 c) {
    return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}
void main() {
    if (uFlat) {
        outColor = vec4(uFlatColor, 1.0);
        outRadiance = vec4(0.0, 0.0, 0.0, 1.0);
        return;
    }
    outRadiance = vec4(max(vRadiance, vec3(0.0)), 1.0);
    outColor = vec4(toSrgb(acesFitted(max(vRadiance, vec3(0.0)) * uExposureScale)), 1.0);
}
