#version 450 core
// Sums the delta form factors of every hemicube pixel per (shooter, patch):
// sums[shooter * patchCount + id - 1] += dFF, in 2^-31 fixed point, since a
// form factor is at most 1 and integer atomics are all OpenGL 4.5 has.
layout(local_size_x = 16, local_size_y = 16) in;
layout(binding = 0) uniform usampler2D uIds;      // 3R x (R * shooters), one row of hemicubes per shooter
layout(binding = 1) uniform sampler2D uDeltaFF;   // 3R x R
layout(std430, binding = 0) buffer Sums { uint sums[]; };
uniform uint uPatchCount;
uniform int uResolution;
uniform int uShooters;
const float kScale = 2147483648.0; // 2^31
void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (p.x >= 3 * uResolution || p.y >= uResolution * uShooters)
        return;
    uint id = texelFetch(uIds, p, 0).r;
    if (id == 0u)
        return;
    int shooter = p.y / uResolution;
    float dff = texelFetch(uDeltaFF, ivec2(p.x, p.y - shooter * uResolution), 0).r;
    atomicAdd(sums[uint(shooter) * uPatchCount + id - 1u], uint(dff * kScale + 0.5));
}
