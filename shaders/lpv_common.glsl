// Shared by the LPV passes (docs/lpv.md is the maths, LpvReference.h its CPU
// twin). Cascades are stacked along z in one 3D texture per colour channel:
// cell (x, y, z) of cascade k is texel (x, y, k * N + z). The geometry volume
// stacks (N + 1)^3 blocks the same way.
// Needs sh.glsl included before it (includes are one level deep).

uniform int uGridSize;   // N, cells per axis of one cascade
uniform int uCascades;   // K

// lpv.shBands (issue #47): 2 unless a kernel's variant defines 3. Three bands
// need sh3.glsl included before this file; their layouts (docs/lpv.md,
// "Memory layout"): a cell's 9 coefficients per channel as Sh9 (low, high,
// last), the fixed-point sums 27 per cell (channel * 9 + coefficient).
#ifndef LPV_SH_BANDS
#define LPV_SH_BANDS 2
#endif
const int LPV_COEFFS = LPV_SH_BANDS * LPV_SH_BANDS; // per colour channel
#if LPV_SH_BANDS == 3
// Coefficient j (0..8) of a three-band SH vector.
float lpvCoeff(Sh9 f, int j) { return j < 4 ? f.low[j] : j < 8 ? f.high[j - 4] : f.last; }
Sh9 lpvSh9(float c[9]) { return Sh9(vec4(c[0], c[1], c[2], c[3]), vec4(c[4], c[5], c[6], c[7]), c[8]); }
#endif

// The 6 directions of travel d, in the order of LpvReference's face table.
const ivec3 LPV_DIRECTIONS[6] = ivec3[6](ivec3(1, 0, 0), ivec3(-1, 0, 0), ivec3(0, 1, 0), ivec3(0, -1, 0),
                                         ivec3(0, 0, 1), ivec3(0, 0, -1));

// Generated from the face table (docs/lpv.md): for direction i and face f
// (index 5 i + f), the SH basis in the face's direction dir_f and the
// re-emission lobe cosineLobe(n_f) * omega_f / pi. LpvGLTest checks the whole
// propagation against the CPU reference, which builds the table itself.
const vec4 LPV_FACE_BASIS[30] = vec4[30](
    vec4(0.282094792, -0, 0, -0.488602512),
    vec4(0.282094792, -0.218509686, 0, -0.437019372),
    vec4(0.282094792, 0.218509686, 0, -0.437019372),
    vec4(0.282094792, -0, 0.218509686, -0.437019372),
    vec4(0.282094792, -0, -0.218509686, -0.437019372),
    vec4(0.282094792, -0, 0, 0.488602512),
    vec4(0.282094792, -0.218509686, 0, 0.437019372),
    vec4(0.282094792, 0.218509686, 0, 0.437019372),
    vec4(0.282094792, -0, 0.218509686, 0.437019372),
    vec4(0.282094792, -0, -0.218509686, 0.437019372),
    vec4(0.282094792, -0.488602512, 0, -0),
    vec4(0.282094792, -0.437019372, 0.218509686, -0),
    vec4(0.282094792, -0.437019372, -0.218509686, -0),
    vec4(0.282094792, -0.437019372, 0, -0.218509686),
    vec4(0.282094792, -0.437019372, 0, 0.218509686),
    vec4(0.282094792, 0.488602512, 0, -0),
    vec4(0.282094792, 0.437019372, 0.218509686, -0),
    vec4(0.282094792, 0.437019372, -0.218509686, -0),
    vec4(0.282094792, 0.437019372, 0, -0.218509686),
    vec4(0.282094792, 0.437019372, 0, 0.218509686),
    vec4(0.282094792, -0, 0.488602512, -0),
    vec4(0.282094792, -0, 0.437019372, -0.218509686),
    vec4(0.282094792, -0, 0.437019372, 0.218509686),
    vec4(0.282094792, -0.218509686, 0.437019372, -0),
    vec4(0.282094792, 0.218509686, 0.437019372, -0),
    vec4(0.282094792, -0, -0.488602512, -0),
    vec4(0.282094792, -0, -0.437019372, -0.218509686),
    vec4(0.282094792, -0, -0.437019372, 0.218509686),
    vec4(0.282094792, -0.218509686, -0.437019372, -0),
    vec4(0.282094792, 0.218509686, -0.437019372, -0));
const vec4 LPV_FACE_LOBE[30] = vec4[30](
    vec4(0.113026831, -0, 0, -0.130512143),
    vec4(0.11944778, -0.137926416, 0, -0),
    vec4(0.11944778, 0.137926416, 0, -0),
    vec4(0.11944778, -0, 0.137926416, -0),
    vec4(0.11944778, -0, -0.137926416, -0),
    vec4(0.113026831, -0, 0, 0.130512143),
    vec4(0.11944778, -0.137926416, 0, -0),
    vec4(0.11944778, 0.137926416, 0, -0),
    vec4(0.11944778, -0, 0.137926416, -0),
    vec4(0.11944778, -0, -0.137926416, -0),
    vec4(0.113026831, -0.130512143, 0, -0),
    vec4(0.11944778, -0, 0.137926416, -0),
    vec4(0.11944778, -0, -0.137926416, -0),
    vec4(0.11944778, -0, 0, -0.137926416),
    vec4(0.11944778, -0, 0, 0.137926416),
    vec4(0.113026831, 0.130512143, 0, -0),
    vec4(0.11944778, -0, 0.137926416, -0),
    vec4(0.11944778, -0, -0.137926416, -0),
    vec4(0.11944778, -0, 0, -0.137926416),
    vec4(0.11944778, -0, 0, 0.137926416),
    vec4(0.113026831, -0, 0.130512143, -0),
    vec4(0.11944778, -0, 0, -0.137926416),
    vec4(0.11944778, -0, 0, 0.137926416),
    vec4(0.11944778, -0.137926416, 0, -0),
    vec4(0.11944778, 0.137926416, 0, -0),
    vec4(0.113026831, -0, -0.130512143, -0),
    vec4(0.11944778, -0, 0, -0.137926416),
    vec4(0.11944778, -0, 0, 0.137926416),
    vec4(0.11944778, -0.137926416, 0, -0),
    vec4(0.11944778, 0.137926416, 0, -0));

// A usable RSM texel: finite position and flux, a normal that has a direction.
// (Degenerate texels are skipped, so one bad texel cannot poison the volume.)
bool lpvUsableTexel(vec3 position, vec3 normal, vec3 flux) {
    bool finite = !any(isnan(position)) && !any(isinf(position)) && !any(isnan(flux)) && !any(isinf(flux)) &&
                  !any(isnan(normal)) && !any(isinf(normal));
    return finite && dot(normal, normal) > 1e-12;
}

bool lpvInsideCascade(ivec3 c) { return all(greaterThanEqual(c, ivec3(0))) && all(lessThan(c, ivec3(uGridSize))); }

// Cell index in the fixed-point buffers (cascades stacked like the textures).
int lpvCellIndex(int k, ivec3 c) { return ((k * uGridSize + c.z) * uGridSize + c.y) * uGridSize + c.x; }
int gvCellIndex(int k, ivec3 g) {
    int m = uGridSize + 1;
    return ((k * m + g.z) * m + g.y) * m + g.x;
}

// The propagation of one direction written out for speed (compute gather,
// raster gather, compute scatter). An SH vector c is used in the form
// f(w) = dc + dot(v, w), dc = Y00 c.x, v = Y1 (-c.w, -c.y, c.z); with the
// travel direction d = sigma e_a and the side axes b, c, the 5 face
// directions are sigma e_a and (sigma e_a +- 0.5 e_b) / sqrt(1.25), ... so each
// evaluation is two multiply-adds, and the re-emitted lobes cosineLobe(n_f)
// are accumulated as (DC, normal) pairs, converted back once at the end
// (lpvFinish). The same maths as the face table, about 3x fewer operations;
// LpvGLTest holds it to the CPU reference. Call with literal a and sigma: the
// compiler then folds every index.
const float LPV_FRONT_WEIGHT = 0.4006696846 / SH_PI; // omega_front / pi
const float LPV_SIDE_WEIGHT = 0.4234313544 / SH_PI;  // omega_side / pi
const float LPV_SIDE_MAIN = 0.894427191;             // 1 / sqrt(1.25)
const float LPV_SIDE_OFF = 0.447213595;              // 0.5 / sqrt(1.25)

vec3 lpvVectorPart(vec4 c) { return SH_Y1 * vec3(-c.w, -c.y, c.z); }

// lpv.twoSidedOcclusion: a surfel blocks light that reaches it from either
// side, not only light that hits its front (docs/lpv.md, Propagation).
uniform bool uTwoSidedOcclusion;

// One channel: what the source (dc, v) sends through the 5 faces with transmittances t.
void lpvSendChannel(int a, float sigma, float dc, vec3 v, float t0, vec4 tSide, inout float accDc, inout vec3 accN) {
    int b = (a + 1) % 3, c = (a + 2) % 3;
    float front = max(0.0, dc + sigma * v[a]) * t0 * LPV_FRONT_WEIGHT;
    float side = dc + sigma * LPV_SIDE_MAIN * v[a];
    vec4 sides = max(vec4(0.0), vec4(side) + LPV_SIDE_OFF * vec4(v[b], -v[b], v[c], -v[c])) * tSide * LPV_SIDE_WEIGHT;
    accDc += front + sides.x + sides.y + sides.z + sides.w;
    accN[a] += sigma * front;
    accN[b] += sides.x - sides.y;
    accN[c] += sides.z - sides.w;
}

// The source cell's (r, g, b) sent along sigma e_a into the neighbour, through
// the blocking potential on the face between them (zero: no occlusion).
// `directed` is the destination cell's dilated VPL normal for directed
// propagation (zero: undirected): each re-emitted lobe n_f is weighted by
// min(1, 1 + n_f . directed), folded into the faces' transmittances.
void lpvSend(int a, float sigma, vec4 r, vec4 g, vec4 b, vec4 blocking, vec3 directed, inout vec3 accDc,
             inout vec3 accNR, inout vec3 accNG, inout vec3 accNB) {
    int ib = (a + 1) % 3, ic = (a + 2) % 3;
    // Transmittance 1 - clamp(B(-w)) per face; two-sided: 1 - clamp(max(B(-w), B(w))).
    float bDc = SH_Y0 * blocking.x;
    vec3 bV = lpvVectorPart(blocking);
    float front = sigma * bV[a];
    float t0 = 1.0 - clamp(uTwoSidedOcclusion ? bDc + abs(front) : bDc - front, 0.0, 1.0);
    float along = sigma * LPV_SIDE_MAIN * bV[a];
    vec4 across = LPV_SIDE_OFF * vec4(bV[ib], -bV[ib], bV[ic], -bV[ic]);
    vec4 sideBlocked = vec4(bDc - along) - across;
    if (uTwoSidedOcclusion)
        sideBlocked = max(sideBlocked, vec4(bDc + along) + across);
    vec4 tSide = vec4(1.0) - clamp(sideBlocked, 0.0, 1.0);
    // Face normals: sigma e_a (front), +-e_b, +-e_c (sides).
    t0 *= min(1.0, 1.0 + sigma * directed[a]);
    tSide *= min(vec4(1.0), vec4(1.0) + vec4(directed[ib], -directed[ib], directed[ic], -directed[ic]));
    lpvSendChannel(a, sigma, SH_Y0 * r.x, lpvVectorPart(r), t0, tSide, accDc.r, accNR);
    lpvSendChannel(a, sigma, SH_Y0 * g.x, lpvVectorPart(g), t0, tSide, accDc.g, accNG);
    lpvSendChannel(a, sigma, SH_Y0 * b.x, lpvVectorPart(b), t0, tSide, accDc.b, accNB);
}

// Accumulated (DC, normal) pairs back to SH: the sum of flux/pi * cosineLobe(n).
vec4 lpvFinishChannel(float accDc, vec3 accN) {
    return vec4(SH_COS0 * accDc, -SH_COS1 * accN.y, SH_COS1 * accN.z, -SH_COS1 * accN.x);
}

// The same from the face table, for a direction known only at run time (the
// raster scatter's vertex shader, one point per direction).
void lpvPropagateThroughFaces(int i, vec4 r, vec4 g, vec4 b, vec4 blocking, vec3 directed, inout vec4 outR,
                              inout vec4 outG, inout vec4 outB) {
    for (int f = 0; f < 5; ++f) {
        vec4 basis = LPV_FACE_BASIS[5 * i + f];
        float blocked = dot(blocking, vec4(basis.x, -basis.yzw));
        if (uTwoSidedOcclusion)
            blocked = max(blocked, dot(blocking, basis));
        vec4 table = LPV_FACE_LOBE[5 * i + f];
        // The lobe is c (1, -n.y, n.z, -n.x) up to scale: its face normal n_f, for directed propagation.
        vec3 faceNormal = normalize(vec3(-table.w, -table.y, table.z));
        vec4 lobe = table * ((1.0 - clamp(blocked, 0.0, 1.0)) * min(1.0, 1.0 + dot(faceNormal, directed)));
        outR += max(0.0, dot(r, basis)) * lobe;
        outG += max(0.0, dot(g, basis)) * lobe;
        outB += max(0.0, dot(b, basis)) * lobe;
    }
}

// lpv.occlusionStrength: propagation reads strength * B (docs/lpv.md); the
// stored GV and face blocking stay unscaled (bounces read the GV's coverage).
uniform float uOcclusionStrength;

#ifdef LPV_WITH_GV
// The GV stacked like the LPV, (N + 1)^3 per cascade.
layout(binding = 3) uniform sampler3D uGv;
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

#ifdef LPV_WITH_FACE_BLOCKING
// The blocking potential on the +x, +y and +z face of every cell, written once
// per frame by lpv_face_blocking.comp (zero: no occlusion). The three faces of
// cell (x, y, z) sit side by side at texels (3x + axis, y, z): one cache line
// holds a cell's faces, where three textures made the propagation wait on
// three memory streams (docs/lpv.md, "Performance notes").
layout(binding = 4) uniform sampler3D uFaceBlocking;
uniform bool uOcclusion;

vec4 lpvFaceBlocking(int axis, ivec3 texel) {
    if (!uOcclusion)
        return vec4(0.0);
    return uOcclusionStrength * texelFetch(uFaceBlocking, ivec3(3 * texel.x + axis, texel.yz), 0);
}

// The blocking on the face between q and q + sigma e_a: q's +a face for
// sigma > 0, the neighbour's for sigma < 0.
vec4 lpvBlockingBetween(int k, ivec3 q, int a, float sigma) {
    ivec3 faceCell = q;
    if (sigma < 0.0)
        faceCell[a] -= 1;
    return lpvFaceBlocking(a, ivec3(faceCell.xy, k * uGridSize + faceCell.z));
}
#endif
#ifdef LPV_WITH_DIRECTED
// Directed propagation: the dilated VPL normals (lpv_normals.comp), stacked
// like the LPV; w = 1 where a cell has one.
layout(binding = 7) uniform sampler3D uLpvNormals;
uniform bool uDirected;

vec3 lpvDirectedNormal(int k, ivec3 p) {
    return uDirected ? texelFetch(uLpvNormals, ivec3(p.xy, k * uGridSize + p.z), 0).xyz : vec3(0.0);
}
#endif
#ifdef LPV_WITH_SOURCES
#ifdef LPV_INTERLEAVED_SOURCES
// The compute gather's ping-pong volumes: 3N x N x NK, a cell's R, G, B side by side.
layout(binding = 0) uniform sampler3D uSource;

void lpvFetchSource(ivec3 source, out vec4 r, out vec4 g, out vec4 b) {
    ivec3 first = ivec3(3 * source.x, source.yz);
    r = texelFetch(uSource, first, 0);
    g = texelFetch(uSource, first + ivec3(1, 0, 0), 0);
    b = texelFetch(uSource, first + ivec3(2, 0, 0), 0);
}
#else
layout(binding = 0) uniform sampler3D uSourceR;
layout(binding = 1) uniform sampler3D uSourceG;
layout(binding = 2) uniform sampler3D uSourceB;

void lpvFetchSource(ivec3 source, out vec4 r, out vec4 g, out vec4 b) {
    r = texelFetch(uSourceR, source, 0);
    g = texelFetch(uSourceG, source, 0);
    b = texelFetch(uSourceB, source, 0);
}
#endif

// Gather: light from the neighbour q = p - sigma e_a, if it is inside. No
// branches: a neighbour outside the cascade is read at the clamped cell and
// weighted by 0. On llvmpipe, 8 cells run in one SIMD vector, and the early
// returns (outside, or a dark neighbour) cost more in masks than they saved
// (docs/lpv.md, "Performance notes").
void lpvGatherFrom(int a, float sigma, int k, ivec3 p, vec3 directed, inout vec3 accDc, inout vec3 nR,
                   inout vec3 nG, inout vec3 nB) {
    ivec3 q = p;
    q[a] -= int(sigma);
    float inside = (q[a] >= 0 && q[a] < uGridSize) ? 1.0 : 0.0; // p is inside: only axis a can leave
    q[a] = clamp(q[a], 0, uGridSize - 1);
    ivec3 source = ivec3(q.xy, k * uGridSize + q.z);
    vec4 r, g, b;
    lpvFetchSource(source, r, g, b);
    r *= inside;
    g *= inside;
    b *= inside;
    lpvSend(a, sigma, r, g, b, lpvBlockingBetween(k, q, a, sigma), directed, accDc, nR, nG, nB);
}

// The whole gather for destination cell p of cascade k.
void lpvGather(int k, ivec3 p, out vec4 r, out vec4 g, out vec4 b) {
    vec3 accDc = vec3(0.0), nR = vec3(0.0), nG = vec3(0.0), nB = vec3(0.0);
    vec3 directed = lpvDirectedNormal(k, p);
    // Literal directions, so that the compiler folds every axis index.
    lpvGatherFrom(0, 1.0, k, p, directed, accDc, nR, nG, nB);
    lpvGatherFrom(0, -1.0, k, p, directed, accDc, nR, nG, nB);
    lpvGatherFrom(1, 1.0, k, p, directed, accDc, nR, nG, nB);
    lpvGatherFrom(1, -1.0, k, p, directed, accDc, nR, nG, nB);
    lpvGatherFrom(2, 1.0, k, p, directed, accDc, nR, nG, nB);
    lpvGatherFrom(2, -1.0, k, p, directed, accDc, nR, nG, nB);
    r = lpvFinishChannel(accDc.r, nR);
    g = lpvFinishChannel(accDc.g, nG);
    b = lpvFinishChannel(accDc.b, nB);
}
#endif
