#version 450 core
// Auto exposure, step 1 of 2: the sum of log luminance and the count of lit
// pixels of each 64x64 tile of the HDR image (each of the 16x16 invocations
// reads a 4x4 block), and the histogram of the log2 brightest channel of the
// whole frame for the highlight percentile (a pixel clips where its
// brightest channel passes the tonemapper's white, whatever its luminance). Pixels without light (luminance <=
// kMinLuminance: an unlit background, a black wall) do not count, so a mostly
// dark frame is metered on what it shows. AutoExposure.h has the CPU twin.
layout(local_size_x = 16, local_size_y = 16) in;

uniform sampler2D uHdr;

layout(std430, binding = 0) writeonly buffer Tiles { vec2 tiles[]; }; // (sum of ln L, count) per tile
layout(std430, binding = 2) buffer Histogram { uint histogram[256]; }; // cleared before the dispatch

const float kMinLuminance = 1e-5;
// AutoExposure.h's kMeterBins, kMeterBinsPerEv, kMeterMinLog2.
const int kBins = 256;
const float kBinsPerEv = 4.0, kMinLog2 = -24.0;

shared vec2 partial[256];
shared uint bins[256];

int meterBin(float v) { return clamp(int(floor((log2(v) - kMinLog2) * kBinsPerEv)), 0, kBins - 1); }

void main() {
    uint i = gl_LocalInvocationIndex;
    bins[i] = 0u;
    barrier();
    ivec2 size = textureSize(uHdr, 0);
    ivec2 base = ivec2(gl_WorkGroupID.xy) * 64 + ivec2(gl_LocalInvocationID.xy) * 4;
    vec2 acc = vec2(0.0);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) {
            ivec2 p = base + ivec2(x, y);
            if (p.x >= size.x || p.y >= size.y)
                continue;
            vec3 c = texelFetch(uHdr, p, 0).rgb;
            float l = dot(c, vec3(0.2126, 0.7152, 0.0722));
            if (l > kMinLuminance && !isinf(l)) { // NaN fails the comparison
                acc += vec2(log(l), 1.0);
                atomicAdd(bins[meterBin(max(c.r, max(c.g, c.b)))], 1u);
            }
        }
    partial[i] = acc;
    barrier();
    // A tile's histogram joins the frame's with one atomic per non-empty bin.
    if (bins[i] != 0u)
        atomicAdd(histogram[i], bins[i]);
    for (uint s = 128u; s > 0u; s >>= 1) {
        if (i < s)
            partial[i] += partial[i + s];
        barrier();
    }
    if (i == 0u)
        tiles[gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x] = partial[0];
}
