#version 450 core
// After the geometry volume, when lpv.visibilityLookup is on: per LPV cell
// and axis the first two moments of the distance (in cells) to the nearest
// surface toward +a and -a, read from the GV on the cell's own face (0.5
// cells) and the next (1.5), the rest at the far distance (docs/lpv.md,
// "Visibility-aware lookup"; lpvref::buildMoments is the CPU twin).
#include "sh.glsl"
#include "lpv_common.glsl"
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(binding = 3) uniform sampler3D uGv; // (N + 1)^3 per cascade, stacked along z
// 3N x N x NK: cell (x, y, z)'s axis a at texel (3x + a, y, z) holds (E[d], E[d^2]) toward +a, then toward -a.
layout(rgba32f, binding = 0) uniform writeonly image3D uMoments;
uniform float uMaxDistance;    // cells: what a direction without a surface records
uniform float uClosedCoverage; // coverage at which a face counts as closed for sight

// GV cell g of cascade k; outside 0..N nothing blocks (as propagation reads it).
vec4 gvCell(int k, ivec3 g) {
    if (any(lessThan(g, ivec3(0))) || any(greaterThan(g, ivec3(uGridSize))))
        return vec4(0.0);
    return texelFetch(uGv, ivec3(g.xy, k * (uGridSize + 1) + g.z), 0);
}

// The opacity for sight along axis a of the face of axis a whose lower
// corner is GV cell g (the average of its 4 corner GV cells, as a trilinear
// sample at the face centre): surfaces stop sight from either side; what the
// linear band lost (both faces of a wall) counts with half its coverage.
float faceOpacity(int k, ivec3 g, int a) {
    ivec3 e1 = ivec3(0), e2 = ivec3(0);
    e1[(a + 1) % 3] = 1;
    e2[(a + 2) % 3] = 1;
    vec4 b = 0.25 * (gvCell(k, g) + gvCell(k, g + e1) + gvCell(k, g + e2) + gvCell(k, g + e1 + e2));
    float coverage = b.x / SH_COS0;
    vec3 l = vec3(-b.w, -b.y, b.z) / SH_COS1;
    float projected = abs(l[a]) + 0.5 * max(coverage - length(l), 0.0);
    return clamp(projected / uClosedCoverage, 0.0, 1.0);
}

// (E[d], E[d^2]) from cell c along sigma e_a: faces at 0.5 and 1.5 cells.
vec2 moments(int k, ivec3 c, int a, int sigma) {
    float transmitted = 1.0, mean = 0.0, meanSquare = 0.0;
    for (int j = 0; j < 2; ++j) {
        // The face's GV plane along a: c + 1 + j ahead, c - j behind.
        ivec3 g = c;
        g[a] = sigma > 0 ? c[a] + 1 + j : c[a] - j;
        float t = 0.5 + float(j);
        float hit = transmitted * faceOpacity(k, g, a);
        mean += hit * t;
        meanSquare += hit * t * t;
        transmitted -= hit;
    }
    return vec2(mean + transmitted * uMaxDistance, meanSquare + transmitted * uMaxDistance * uMaxDistance);
}

void main() {
    ivec3 texel = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(texel, ivec3(uGridSize, uGridSize, uGridSize * uCascades))))
        return;
    int k = texel.z / uGridSize;
    ivec3 c = ivec3(texel.xy, texel.z % uGridSize);
    for (int a = 0; a < 3; ++a)
        imageStore(uMoments, ivec3(3 * texel.x + a, texel.yz), vec4(moments(k, c, a, 1), moments(k, c, a, -1)));
}
