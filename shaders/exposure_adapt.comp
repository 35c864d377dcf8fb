#version 450 core
// Auto exposure, step 2 of 2: the log-average luminance of the lit pixels
// from the tiles of exposure_reduce.comp, the exposure that maps it to the key
// value (Reinhard et al. 2002), and its adaptation: the metered log exposure
// moves toward the target by uBlend = 1 - exp(-dt / tau) per frame (1 =
// immediately). The result stays on the GPU for tonemap.frag: no read-back.
layout(local_size_x = 256) in;

uniform int uTileCount;
uniform float uKey;   // output.exposureKey
uniform float uBlend; // 1 on the first frame, after a reset, or with no adaptation time

layout(std430, binding = 0) readonly buffer Tiles { vec2 tiles[]; };
// logExposure: ln of the metered exposure; exposure = exp(logExposure);
// valid: 1 once a frame with lit pixels was metered; lit: that frame's lit pixel count.
layout(std430, binding = 1) buffer Exposure { float logExposure; float exposure; float valid; float lit; };

shared vec2 partial[256];

void main() {
    uint i = gl_LocalInvocationIndex;
    vec2 acc = vec2(0.0);
    for (int t = int(i); t < uTileCount; t += 256)
        acc += tiles[t];
    partial[i] = acc;
    barrier();
    for (uint s = 128u; s > 0u; s >>= 1) {
        if (i < s)
            partial[i] += partial[i + s];
        barrier();
    }
    if (i != 0u)
        return;
    vec2 sum = partial[0];
    lit = sum.y;
    if (sum.y < 1.0)
        return; // nothing lit: keep the last exposure (1 before any)
    // Clamped to +-16 EV, the range of output.exposure.
    float target = clamp(log(uKey) - sum.x / sum.y, -16.0 * log(2.0), 16.0 * log(2.0));
    logExposure = valid > 0.5 ? mix(logExposure, target, uBlend) : target;
    exposure = exp(logExposure);
    valid = 1.0;
}
