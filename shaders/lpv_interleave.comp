#version 450 core
// Between the per-channel volumes (injection, the other variants, the LPV
// viewer) and the compute gather's interleaved ping-pong volumes, where cell
// (x, y, z)'s R, G and B coefficients sit side by side at texels 3x, 3x + 1
// and 3x + 2 (docs/lpv.md, "Performance notes"). Once per frame before the
// gather's first step (pack), and only for the viewer's capture after it
// (UNPACK).
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

uniform ivec3 uSize; // N, N, N K: the per-channel volumes

#ifdef UNPACK
layout(binding = 0) uniform sampler3D uInterleaved;
layout(rgba32f, binding = 0) uniform writeonly image3D uR;
layout(rgba32f, binding = 1) uniform writeonly image3D uG;
layout(rgba32f, binding = 2) uniform writeonly image3D uB;
#else
layout(binding = 0) uniform sampler3D uR;
layout(binding = 1) uniform sampler3D uG;
layout(binding = 2) uniform sampler3D uB;
layout(rgba32f, binding = 0) uniform writeonly image3D uInterleaved;
#endif

void main() {
    ivec3 texel = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(texel, uSize)))
        return;
    ivec3 first = ivec3(3 * texel.x, texel.yz);
#ifdef UNPACK
    imageStore(uR, texel, texelFetch(uInterleaved, first, 0));
    imageStore(uG, texel, texelFetch(uInterleaved, first + ivec3(1, 0, 0), 0));
    imageStore(uB, texel, texelFetch(uInterleaved, first + ivec3(2, 0, 0), 0));
#else
    imageStore(uInterleaved, first, texelFetch(uR, texel, 0));
    imageStore(uInterleaved, first + ivec3(1, 0, 0), texelFetch(uG, texel, 0));
    imageStore(uInterleaved, first + ivec3(2, 0, 0), texelFetch(uB, texel, 0));
#endif
}
