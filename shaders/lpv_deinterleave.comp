#version 450 core
// The compute gather's interleaved ping-pong volume (cell (x, y, z)'s R, G and
// B coefficients side by side at texels 3x, 3x + 1 and 3x + 2; docs/lpv.md,
// "Memory layout") back to one texture per channel, for the step the LPV
// viewer captures.
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

uniform ivec3 uSize; // N, N, N K: the per-channel volumes

layout(binding = 0) uniform sampler3D uInterleaved;
layout(rgba32f, binding = 0) uniform writeonly image3D uR;
layout(rgba32f, binding = 1) uniform writeonly image3D uG;
layout(rgba32f, binding = 2) uniform writeonly image3D uB;

void main() {
    ivec3 texel = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(texel, uSize)))
        return;
    ivec3 first = ivec3(3 * texel.x, texel.yz);
    imageStore(uR, texel, texelFetch(uInterleaved, first, 0));
    imageStore(uG, texel, texelFetch(uInterleaved, first + ivec3(1, 0, 0), 0));
    imageStore(uB, texel, texelFetch(uInterleaved, first + ivec3(2, 0, 0), 0));
}
