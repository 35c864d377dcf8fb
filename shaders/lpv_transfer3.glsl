// One gather step of the three-band LPV (issue #47), the GLSL twin of
// lpvref::bands::propagateStep<3> (docs/lpv.md, "Three bands"): the 30
// face-transfer terms and the occluded transfer into one destination cell,
// in a per-axis form like lpv_common.glsl's two-band lpvSend.
// Include sh.glsl and sh3.glsl first. The caller supplies the volume access
// (defined before including this file):
//   void lpv3Sources(ivec3 q, out Sh9 r, out Sh9 g, out Sh9 b)
//                                          the source cell's SH (q inside the grid)
//   Sh9 lpv3BlockingBetween(ivec3 q, ivec3 d)
//                                          the geometry volume on the face between q and q + d
// and may define before it (defaults in brackets): LPV3_GRID, cells per axis
// [uGridSize3]; LPV3_STRENGTH, lpv.occlusionStrength [uStrength3];
// LPV3_TWO_SIDED, lpv.twoSidedOcclusion [false]; LPV3_DIRECTED, the
// destination's dilated VPL normal for directed propagation [vec3(0): none].
#ifndef LPV3_GRID
#define LPV3_GRID uGridSize3
#endif
#ifndef LPV3_STRENGTH
#define LPV3_STRENGTH uStrength3
#endif
#ifndef LPV3_TWO_SIDED
#define LPV3_TWO_SIDED false
#endif
#ifndef LPV3_DIRECTED
#define LPV3_DIRECTED vec3(0.0)
#endif
const float LPV3_FRONT_SOLID_ANGLE = 0.4006696846;
const float LPV3_SIDE_SOLID_ANGLE = 0.4234313544;
const float LPV3_SIDE_MAIN = 0.894427191; // 1 / sqrt(1.25)
const float LPV3_SIDE_OFF = 0.447213595;  // 0.5 / sqrt(1.25)

// The per-axis form. On unit directions an SH vector of three bands is
// f(w) = dc + v.w + w^T Q w (3z^2 - 1 = 2z^2 - x^2 - y^2 there), with
// dc = Y00 c0, v = Y1 (-c3, -c1, c2) and Q symmetric and traceless from band 2.
// For travel sigma e_a (side axes b, c) the 5 face directions are sigma e_a
// and (sigma e_a +- 0.5 e_b) / sqrt(1.25), ..., so f there is a few
// multiply-adds of dc, v and Q: the gather term omega_f Y(dir_f) dotted
// with the source, without the 9 x 30 table.
void lpv3Quadratic(Sh9 f, out float dc, out vec3 v, out mat3 q) {
    dc = SH_Y0 * f.low.x;
    v = SH_Y1 * vec3(-f.low.w, -f.low.y, f.low.z);
    float xx = -SH_Y20 * f.high.z + SH_Y22 * f.last, yy = -SH_Y20 * f.high.z - SH_Y22 * f.last;
    float xy = 0.5 * SH_Y2 * f.high.x, yz = -0.5 * SH_Y2 * f.high.y, xz = -0.5 * SH_Y2 * f.high.w;
    q = mat3(xx, xy, xz, xy, yy, yz, xz, yz, 2.0 * SH_Y20 * f.high.z);
}

// f at the front direction sigma e_a and at the 4 side directions (+b, -b, +c, -c).
void lpv3AtFaces(int a, float sigma, float dc, vec3 v, mat3 q, out float front, out vec4 sides) {
    int b = (a + 1) % 3, c = (a + 2) % 3;
    front = dc + sigma * v[a] + q[a][a];
    float along = dc + sigma * LPV3_SIDE_MAIN * v[a];
    float towardB = along + 0.8 * (q[a][a] + 0.25 * q[b][b]), towardC = along + 0.8 * (q[a][a] + 0.25 * q[c][c]);
    float acrossB = LPV3_SIDE_OFF * v[b] + sigma * 0.8 * q[a][b], acrossC = LPV3_SIDE_OFF * v[c] + sigma * 0.8 * q[a][c];
    sides = vec4(towardB + acrossB, towardB - acrossB, towardC + acrossC, towardC - acrossC);
}

// One channel's flux through the 5 faces, with transmittances t, summed by the
// face normal's axis: F (all) and S (signed by the normal's direction).
void lpv3SendChannel(int a, float sigma, Sh9 f, float t0, vec4 tSide, inout vec3 flux, inout vec3 signedFlux) {
    int b = (a + 1) % 3, c = (a + 2) % 3;
    float dc, front;
    vec3 v;
    mat3 q;
    vec4 sides;
    lpv3Quadratic(f, dc, v, q);
    lpv3AtFaces(a, sigma, dc, v, q, front, sides);
    front = max(0.0, front) * (LPV3_FRONT_SOLID_ANGLE * t0);
    sides = max(vec4(0.0), sides) * (LPV3_SIDE_SOLID_ANGLE * tSide);
    flux[a] += front;
    signedFlux[a] += sigma * front;
    flux[b] += sides.x + sides.y;
    signedFlux[b] += sides.x - sides.y;
    flux[c] += sides.z + sides.w;
    signedFlux[c] += sides.z - sides.w;
}

// The re-emitted lobes summed: cosineLobe(n_f) / pi of an axis normal has
// DC Y00, one band-1 coefficient 2/3 Y1, and of band 2 only Y20 (1/4 Y20
// (3 n_z^2 - 1)) and Y22 (1/4 Y22 (n_x^2 - n_y^2)).
Sh9 lpv3Finish(vec3 flux, vec3 signedFlux) {
    float k1 = (2.0 / 3.0) * SH_Y1;
    return Sh9(vec4(SH_Y0 * (flux.x + flux.y + flux.z), -k1 * signedFlux.y, k1 * signedFlux.z, -k1 * signedFlux.x),
               vec4(0.0, 0.0, 0.25 * SH_Y20 * (2.0 * flux.z - flux.x - flux.y), 0.0),
               0.25 * SH_Y22 * (flux.x - flux.y));
}

// Light from the neighbour q = p - sigma e_a. No branch: a neighbour outside
// the grid is read at the clamped cell and weighted by 0 (as lpvGatherFrom).
void lpv3GatherFrom(int a, float sigma, ivec3 p, bool occlusion, inout vec3 fluxR, inout vec3 signedR,
                    inout vec3 fluxG, inout vec3 signedG, inout vec3 fluxB, inout vec3 signedB) {
    int b = (a + 1) % 3, c = (a + 2) % 3;
    ivec3 d = ivec3(0);
    d[a] = int(sigma);
    ivec3 q = p - d;
    float inside = (q[a] >= 0 && q[a] < LPV3_GRID) ? 1.0 : 0.0; // p is inside: only axis a can leave
    q[a] = clamp(q[a], 0, LPV3_GRID - 1);
    Sh9 r, g, bl;
    lpv3Sources(q, r, g, bl);
    // Transmittance 1 - clamp(strength B(-dir)) per face, the GV at the face's
    // centre q + 0.5 + 0.5 d (two-sided: the larger of B(-dir) and B(dir)).
    float t0 = inside;
    vec4 tSide = vec4(inside);
    if (occlusion) {
        float dcB, blockedFront, otherFront;
        vec3 vB;
        mat3 qB;
        vec4 blockedSides, otherSides;
        lpv3Quadratic(lpv3BlockingBetween(q, d), dcB, vB, qB);
        lpv3AtFaces(a, sigma, dcB, -vB, qB, blockedFront, blockedSides);
        if (LPV3_TWO_SIDED) {
            lpv3AtFaces(a, sigma, dcB, vB, qB, otherFront, otherSides);
            blockedFront = max(blockedFront, otherFront);
            blockedSides = max(blockedSides, otherSides);
        }
        t0 *= 1.0 - clamp(LPV3_STRENGTH * blockedFront, 0.0, 1.0);
        tSide *= vec4(1.0) - clamp(LPV3_STRENGTH * blockedSides, 0.0, 1.0);
    }
    // Directed propagation: each re-emitted lobe n_f weighted by min(1, 1 + n_f . directed).
    vec3 directed = LPV3_DIRECTED;
    t0 *= min(1.0, 1.0 + sigma * directed[a]);
    tSide *= min(vec4(1.0), vec4(1.0) + vec4(directed[b], -directed[b], directed[c], -directed[c]));
    lpv3SendChannel(a, sigma, r, t0, tSide, fluxR, signedR);
    lpv3SendChannel(a, sigma, g, t0, tSide, fluxG, signedG);
    lpv3SendChannel(a, sigma, bl, t0, tSide, fluxB, signedB);
}

// The light gathered into cell p, per channel; `occlusion` false: no GV.
void lpv3Gather(ivec3 p, bool occlusion, out Sh9 outR, out Sh9 outG, out Sh9 outB) {
    vec3 fR = vec3(0.0), sR = vec3(0.0), fG = vec3(0.0), sG = vec3(0.0), fB = vec3(0.0), sB = vec3(0.0);
    // Literal directions, so that the compiler folds every axis index.
    lpv3GatherFrom(0, 1.0, p, occlusion, fR, sR, fG, sG, fB, sB);
    lpv3GatherFrom(0, -1.0, p, occlusion, fR, sR, fG, sG, fB, sB);
    lpv3GatherFrom(1, 1.0, p, occlusion, fR, sR, fG, sG, fB, sB);
    lpv3GatherFrom(1, -1.0, p, occlusion, fR, sR, fG, sG, fB, sB);
    lpv3GatherFrom(2, 1.0, p, occlusion, fR, sR, fG, sG, fB, sB);
    lpv3GatherFrom(2, -1.0, p, occlusion, fR, sR, fG, sG, fB, sB);
    outR = lpv3Finish(fR, sR);
    outG = lpv3Finish(fG, sG);
    outB = lpv3Finish(fB, sB);
}
