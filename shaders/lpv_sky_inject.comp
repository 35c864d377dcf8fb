#version 450 core
// Sky light injection (docs/lpv.md, LpvReference's injectSky): per cascade
// and column of cells, the highest surface in a top-down depth map; the first
// cell above it receives a VPL facing down, flux pi * sky radiance * s^2.
// Added to the injected volume (ping-pong 0) and the accumulator after the
// RSM's VPLs are resolved; one invocation per column, so no atomics.
#define LPV_WITH_FIXED_POINT
#include "sh.glsl"
#include "sh3.glsl"
#include "lpv_common.glsl"
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

#if LPV_SH_BANDS == 3
// Three bands: the injected volume interleaved (7 texels per cell, as
// lpv_resolve.comp writes it) and band 2 of the accumulator (4 planes along x).
layout(rgba32f, binding = 0) uniform image3D uVolume;
layout(rgba32f, binding = 6) uniform image3D uAccumHigh;
#else
layout(rgba32f, binding = 0) uniform image3D uVolumeR;
layout(rgba32f, binding = 1) uniform image3D uVolumeG;
layout(rgba32f, binding = 2) uniform image3D uVolumeB;
#endif
layout(rgba32f, binding = 3) uniform image3D uAccumR;
layout(rgba32f, binding = 4) uniform image3D uAccumG;
layout(rgba32f, binding = 5) uniform image3D uAccumB;
uniform sampler2DArray uSkyDepth; // orthographic from above: depth 0 at uSkyTop, 1 at uSkyBottom (1: nothing)
uniform vec2 uSkyMin;        // world x, z of texel (0, 0)'s corner
uniform float uSkyTexel;     // world size of a texel
uniform int uSkySize;        // texels per side
uniform float uSkyTop;
uniform float uSkyBottom;
uniform vec3 uSkyRadiance;
uniform vec3 uOrigin[6];
uniform float uCellSize[6];

const float NO_SURFACE = -3.0e38;

int firstTexel(float w, float lo) { return int(ceil((w - lo) / uSkyTexel - 0.5)); }

// The highest surface over the texels whose centres lie in the column.
float columnTop(float x0, float z0, float x1, float z1) {
    int i0 = firstTexel(x0, uSkyMin.x), i1 = firstTexel(x1, uSkyMin.x) - 1;
    int j0 = firstTexel(z0, uSkyMin.y), j1 = firstTexel(z1, uSkyMin.y) - 1;
    if (i1 < i0 || j1 < j0) {
        i0 = i1 = int(floor((0.5 * (x0 + x1) - uSkyMin.x) / uSkyTexel));
        j0 = j1 = int(floor((0.5 * (z0 + z1) - uSkyMin.y) / uSkyTexel));
    }
    float top = NO_SURFACE;
    for (int j = max(j0, 0); j <= min(j1, uSkySize - 1); ++j)
        for (int i = max(i0, 0); i <= min(i1, uSkySize - 1); ++i) {
            float d = texelFetch(uSkyDepth, ivec3(i, j, 0), 0).r;
            if (d < 1.0)
                top = max(top, uSkyTop - d * (uSkyTop - uSkyBottom));
        }
    return top;
}

void main() {
    ivec3 id = ivec3(gl_GlobalInvocationID);
    int k = id.z;
    if (id.x >= uGridSize || id.y >= uGridSize || k >= uCascades)
        return;
    float s = uCellSize[k];
    vec3 o = uOrigin[k];
    float x0 = o.x + float(id.x) * s, z0 = o.z + float(id.y) * s;
    float top = columnTop(x0, z0, x0 + s, z0 + s);
    float above = top <= NO_SURFACE ? 0.0 : floor((top - o.y) / s) + 1.0;
    int y = int(clamp(above, 0.0, float(uGridSize))); // clamped as a float: no undefined conversion
    if (y >= uGridSize)
        return; // covered above the cascade's top
    ivec3 texel = ivec3(id.x, y, k * uGridSize + id.y);
#if LPV_SH_BANDS == 3
    // cosineLobe(-y) of three bands: band 2 has only Y20 and Y22.
    Sh9 lobe9 = sh9Scale(sh9CosineLobe(vec3(0.0, -1.0, 0.0)), s * s);
    ivec3 first = ivec3(7 * texel.x, texel.yz), plane = ivec3(uGridSize, 0, 0);
    for (int c = 0; c < 3; ++c) {
        imageStore(uVolume, first + ivec3(c, 0, 0), imageLoad(uVolume, first + ivec3(c, 0, 0)) + uSkyRadiance[c] * lobe9.low);
        imageStore(uVolume, first + ivec3(3 + c, 0, 0),
                   imageLoad(uVolume, first + ivec3(3 + c, 0, 0)) + uSkyRadiance[c] * lobe9.high);
        imageStore(uAccumHigh, texel + c * plane, imageLoad(uAccumHigh, texel + c * plane) + uSkyRadiance[c] * lobe9.high);
    }
    vec4 last = vec4(uSkyRadiance, 0.0) * lobe9.last;
    imageStore(uVolume, first + ivec3(6, 0, 0), imageLoad(uVolume, first + ivec3(6, 0, 0)) + last);
    imageStore(uAccumHigh, texel + 3 * plane, imageLoad(uAccumHigh, texel + 3 * plane) + last);
    imageStore(uAccumR, texel, imageLoad(uAccumR, texel) + uSkyRadiance.r * lobe9.low);
    imageStore(uAccumG, texel, imageLoad(uAccumG, texel) + uSkyRadiance.g * lobe9.low);
    imageStore(uAccumB, texel, imageLoad(uAccumB, texel) + uSkyRadiance.b * lobe9.low);
    // No scale slot: three bands run the compute gather only.
#else
    vec4 lobe = shCosineLobe(vec3(0.0, -1.0, 0.0)) * (s * s);
    vec4 r = imageLoad(uVolumeR, texel) + uSkyRadiance.r * lobe;
    vec4 g = imageLoad(uVolumeG, texel) + uSkyRadiance.g * lobe;
    vec4 b = imageLoad(uVolumeB, texel) + uSkyRadiance.b * lobe;
    imageStore(uVolumeR, texel, r);
    imageStore(uVolumeG, texel, g);
    imageStore(uVolumeB, texel, b);
    imageStore(uAccumR, texel, imageLoad(uAccumR, texel) + uSkyRadiance.r * lobe);
    imageStore(uAccumG, texel, imageLoad(uAccumG, texel) + uSkyRadiance.g * lobe);
    imageStore(uAccumB, texel, imageLoad(uAccumB, texel) + uSkyRadiance.b * lobe);
    // The compute scatter's fixed-point scale must cover the brighter cell.
    vec4 largest = max(max(abs(r), abs(g)), abs(b));
    lpvRecordMax(k, 0, max(max(largest.x, largest.y), max(largest.z, largest.w)));
#endif
}
