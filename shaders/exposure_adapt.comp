#version 450 core
// Auto exposure, step 2 of 2: the log-average luminance of the lit pixels
// from the tiles of exposure_reduce.comp, the exposure that maps it to the key
// value (Reinhard et al. 2002), lowered where the highlight percentile of the
// histogram would pass the tonemapper's white, and its adaptation: the
// metered log exposure moves toward the target by uBlend = 1 - exp(-dt / tau)
// per frame (1 = immediately). The result stays on the GPU for tonemap.frag:
// no read-back. AutoExposure.cpp has the CPU twin.
layout(local_size_x = 256) in;

uniform int uTileCount;
uniform float uKey;              // output.exposureKey
uniform float uHighlightPercent; // output.exposureHighlights
uniform float uHighlightInput;   // the tonemapper's white (DisplayMapping.h's whiteInput)
uniform float uBlend; // 1 on the first frame, after a reset, or with no adaptation time

layout(std430, binding = 0) readonly buffer Tiles { vec2 tiles[]; };
// logExposure: ln of the metered exposure; exposure = exp(logExposure);
// valid: 1 once a frame with lit pixels was metered; lit: that frame's lit pixel count.
layout(std430, binding = 1) buffer Exposure { float logExposure; float exposure; float valid; float lit; };
layout(std430, binding = 2) readonly buffer Histogram { uint histogram[256]; };

// AutoExposure.h's kMeterBins, kMeterBinsPerEv, kMeterMinLog2.
const int kBins = 256;
const float kBinsPerEv = 4.0, kMinLog2 = -24.0;

shared vec2 partial[256];

// ln of the value below which the brightest channel of uHighlightPercent of the lit pixels lies,
// interpolated inside its bin (AutoExposure.cpp's highlightPercentile).
float percentileLog(float total) {
    float wanted = total * clamp(uHighlightPercent, 0.0, 100.0) / 100.0;
    float below = 0.0;
    for (int b = 0; b < kBins; ++b) {
        float n = float(histogram[b]);
        if (n > 0.0 && below + n >= wanted) {
            float within = clamp((wanted - below) / n, 0.0, 1.0);
            return (kMinLog2 + (float(b) + within) / kBinsPerEv) * log(2.0);
        }
        below += n;
    }
    return kMinLog2 * log(2.0); // not reached: the last non-empty bin holds the 100th percentile
}

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
    float target = log(uKey) - sum.x / sum.y;
    target = min(target, log(uHighlightInput) - percentileLog(sum.y));
    // Clamped to +-16 EV, the range of output.exposure.
    target = clamp(target, -16.0 * log(2.0), 16.0 * log(2.0));
    logExposure = valid > 0.5 ? mix(logExposure, target, uBlend) : target;
    exposure = exp(logExposure);
    valid = 1.0;
}
