// Shared by the LPV passes (docs/lpv.md is the maths, LpvReference.h its CPU
// twin). Cascades are stacked along z in one 3D texture per colour channel:
// cell (x, y, z) of cascade k is texel (x, y, k * N + z). The geometry volume
// stacks (N + 1)^3 blocks the same way.
// Needs sh.glsl included before it (includes are one level deep).

uniform int uGridSize;   // N, cells per axis of one cascade
uniform int uCascades;   // K

const float LPV_FRONT_FACE_SOLID_ANGLE = 0.4006696846;
const float LPV_SIDE_FACE_SOLID_ANGLE = 0.4234313544;

// The 6 directions of travel d, in the order of LpvReference's face table.
const ivec3 LPV_DIRECTIONS[6] = ivec3[6](ivec3(1, 0, 0), ivec3(-1, 0, 0), ivec3(0, 1, 0), ivec3(0, -1, 0),
                                         ivec3(0, 0, 1), ivec3(0, 0, -1));

// Outward normal of face f (0 = the face opposite the source, 1..4 the side
// faces) of the destination cell, for direction of travel i.
vec3 lpvFaceNormal(int i, int f) {
    vec3 d = vec3(LPV_DIRECTIONS[i]);
    if (f == 0)
        return d;
    int a = i / 2;
    int side = (f <= 2) ? (a + 1) % 3 : (a + 2) % 3;
    vec3 n = vec3(0.0);
    n[side] = (f % 2 == 1) ? 1.0 : -1.0;
    return n;
}

bool lpvInsideCascade(ivec3 c) { return all(greaterThanEqual(c, ivec3(0))) && all(lessThan(c, ivec3(uGridSize))); }

// Cell index in the fixed-point buffers (cascades stacked like the textures).
int lpvCellIndex(int k, ivec3 c) { return ((k * uGridSize + c.z) * uGridSize + c.y) * uGridSize + c.x; }
int gvCellIndex(int k, ivec3 g) {
    int m = uGridSize + 1;
    return ((k * m + g.z) * m + g.y) * m + g.x;
}

// What a source cell with intensity (r, g, b) sends into the neighbour it
// touches along direction i, through that neighbour's 5 other faces;
// `blocking` is the GV interpolated on the shared face (zero = no occlusion).
void lpvPropagateThroughFaces(int i, vec4 r, vec4 g, vec4 b, vec4 blocking, inout vec4 outR, inout vec4 outG,
                              inout vec4 outB) {
    vec3 d = vec3(LPV_DIRECTIONS[i]);
    for (int f = 0; f < 5; ++f) {
        vec3 n = lpvFaceNormal(i, f);
        vec3 dir = normalize(d + 0.5 * n);
        float omega = f == 0 ? LPV_FRONT_FACE_SOLID_ANGLE : LPV_SIDE_FACE_SOLID_ANGLE;
        float transmittance = 1.0 - clamp(shEvaluate(blocking, -dir), 0.0, 1.0);
        vec4 basis = shBasis(dir);
        vec4 lobe = shCosineLobe(n) * (omega / SH_PI * transmittance);
        outR += max(0.0, dot(r, basis)) * lobe;
        outG += max(0.0, dot(g, basis)) * lobe;
        outB += max(0.0, dot(b, basis)) * lobe;
    }
}

#ifdef LPV_WITH_GV
// The GV stacked like the LPV, (N + 1)^3 per cascade.
uniform sampler3D uGv;
uniform bool uOcclusion;

// The blocking potential on the face between source q and q + d (direction i):
// GV coordinate q + 0.5 + 0.5 d, i.e. the average of 4 GV cells.
vec4 lpvBlockingOnFace(int k, ivec3 q, int i) {
    if (!uOcclusion)
        return vec4(0.0);
    int a = i / 2;
    ivec3 g = q;
    if (LPV_DIRECTIONS[i][a] > 0)
        g[a] += 1;
    ivec3 e1 = ivec3(0), e2 = ivec3(0);
    e1[(a + 1) % 3] = 1;
    e2[(a + 2) % 3] = 1;
    int base = k * (uGridSize + 1);
    vec4 sum = texelFetch(uGv, ivec3(g.xy, base + g.z), 0) + texelFetch(uGv, ivec3((g + e1).xy, base + (g + e1).z), 0) +
               texelFetch(uGv, ivec3((g + e2).xy, base + (g + e2).z), 0) +
               texelFetch(uGv, ivec3((g + e1 + e2).xy, base + (g + e1 + e2).z), 0);
    return 0.25 * sum;
}
#endif

#ifdef LPV_WITH_FIXED_POINT
// Fixed point for the integer atomics (docs/lpv.md). Injection: per cascade
// the scale 2^29 / bound, bound = 0.85 * the brightest texel's flux * texels
// per tile. Compute scatter: 2^29 / (8 * the largest |coefficient| of the
// volume being propagated), recorded by the resolve that wrote it: one step
// sends at most 7.15 times that into a cell (docs/lpv.md), so the sums never
// overflow, and the scale follows the light as it spreads and fades.
// Buffer: [k] brightest texel flux, [K + slot * K + k] largest |coefficient|
// of the volume in that slot (float bits; non-negative floats order like uints).
layout(std430, binding = 1) buffer LpvScales { uint lpvScaleData[]; };
uniform int uTexelsPerTile;
uniform int uScaleSlot; // -1: injection; 0 or 1: the propagated volume's slot

float lpvFixedScale(int k) {
    float bound = uScaleSlot < 0 ? 0.85 * uintBitsToFloat(lpvScaleData[k]) * float(uTexelsPerTile)
                                 : 8.0 * uintBitsToFloat(lpvScaleData[uCascades * (1 + uScaleSlot) + k]);
    return bound > 0.0 ? 536870912.0 / bound : 0.0;
}

// Records the largest |coefficient| of a resolved cell into slot `slot`.
void lpvRecordMax(int k, int slot, float value) {
    atomicMax(lpvScaleData[uCascades * (1 + slot) + k], floatBitsToUint(value));
}
#endif
