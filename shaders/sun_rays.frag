#version 450 core
// Sun rays, pass 2: a radial blur of the occlusion image towards the sun's
// screen position (Mitchell, GPU Gems 3 ch. 13), added to the HDR image.
in vec2 vUv;
out vec4 outColor;

uniform sampler2D uOcclusion;
uniform vec2 uSunUv;        // the sun's position on screen (may lie outside 0..1)
uniform int uSamples;
uniform float uDensity;     // fraction of the way to the sun the samples cover
uniform float uDecay;       // weight falloff per sample
uniform vec3 uRayColor;     // sun colour x strength, per unit of accumulated occlusion

void main() {
    vec2 step = (vUv - uSunUv) * (uDensity / float(uSamples));
    vec2 uv = vUv;
    float weight = 1.0;
    float sum = 0.0;
    for (int i = 0; i < uSamples; ++i) {
        uv -= step;
        sum += texture(uOcclusion, uv).r * weight;
        weight *= uDecay;
    }
    outColor = vec4(uRayColor * (sum / float(uSamples)), 0.0);
}
