// One gather step of the three-band LPV (issue #47), the GLSL twin of
// lpvref::bands::propagateStep<3> (docs/lpv.md, "Three bands"): the 30
// face-transfer terms and the occluded transfer into one destination cell.
// Include sh.glsl and sh3.glsl first. The caller supplies the volume access
// (defined before including this file):
//   void lpv3Sources(ivec3 q, out Sh9 r, out Sh9 g, out Sh9 b)
//                                          the source cell's SH (q inside the grid)
//   Sh9 lpv3BlockingBetween(ivec3 q, ivec3 d)
//                                          the geometry volume on the face between q and q + d
// and may define before it (defaults in brackets): LPV3_GRID, cells per axis
// [uGridSize3]; LPV3_STRENGTH, lpv.occlusionStrength [uStrength3];
// LPV3_TWO_SIDED, lpv.twoSidedOcclusion [false]; LPV3_DIRECTED, the
// destination's dilated VPL normal for directed propagation [none].
#ifndef LPV3_GRID
#define LPV3_GRID uGridSize3
#endif
#ifndef LPV3_STRENGTH
#define LPV3_STRENGTH uStrength3
#endif
#ifndef LPV3_TWO_SIDED
#define LPV3_TWO_SIDED false
#endif
const ivec3 LPV3_AXES[6] = ivec3[6](ivec3(1, 0, 0), ivec3(-1, 0, 0), ivec3(0, 1, 0), ivec3(0, -1, 0),
                                    ivec3(0, 0, 1), ivec3(0, 0, -1));
const float LPV3_FRONT_SOLID_ANGLE = 0.4006696846;
const float LPV3_SIDE_SOLID_ANGLE = 0.4234313544;

// Face f of travel direction d: from the source's centre towards the face's
// centre, dir = normalize(d + 0.5 n_f); gather = omega_f Y(dir), emit = cosineLobe(n_f) / pi.
Sh9 lpv3GatherTerm(ivec3 d, ivec3 nf) {
    float omega = nf == d ? LPV3_FRONT_SOLID_ANGLE : LPV3_SIDE_SOLID_ANGLE;
    return sh9Scale(sh9Basis(normalize(vec3(d) + 0.5 * vec3(nf))), omega);
}
Sh9 lpv3EmitTerm(ivec3 nf) { return sh9Scale(sh9CosineLobe(vec3(nf)), 1.0 / SH_PI); }

bool lpv3Inside(ivec3 c) { return all(greaterThanEqual(c, ivec3(0))) && all(lessThan(c, ivec3(LPV3_GRID))); }

// 1 - clamp(strength B(-travel)) for the blocking potential B on a face
// (two-sided: the larger of B(-travel) and B(travel)).
float lpv3Transmittance(Sh9 blocking, vec3 travel) {
    float blocked = sh9Evaluate(blocking, -travel);
    if (LPV3_TWO_SIDED)
        blocked = max(blocked, sh9Evaluate(blocking, travel));
    return 1.0 - clamp(LPV3_STRENGTH * blocked, 0.0, 1.0);
}

// The light gathered into cell p, per channel; `occlusion` false: no GV.
void lpv3Gather(ivec3 p, bool occlusion, out Sh9 outR, out Sh9 outG, out Sh9 outB) {
    outR = Sh9(vec4(0.0), vec4(0.0), 0.0);
    outG = outR;
    outB = outR;
    for (int a = 0; a < 6; ++a) {
        ivec3 d = LPV3_AXES[a];
        ivec3 q = p - d;
        if (!lpv3Inside(q))
            continue;
        Sh9 r, g, b;
        lpv3Sources(q, r, g, b);
        // The CPU twin samples the GV at the face's centre, q + 0.5 + 0.5 d, for all 5 faces.
        Sh9 blocking = occlusion ? lpv3BlockingBetween(q, d) : Sh9(vec4(0.0), vec4(0.0), 0.0);
        for (int f = 0; f < 6; ++f) {
            ivec3 nf = LPV3_AXES[f];
            if (nf == -d)
                continue; // the face shared with q: light enters there
            vec3 dir = normalize(vec3(d) + 0.5 * vec3(nf));
            float t = occlusion ? lpv3Transmittance(blocking, dir) : 1.0;
#ifdef LPV3_DIRECTED
            t *= min(1.0, 1.0 + dot(vec3(nf), LPV3_DIRECTED)); // lpvref::directedWeight
#endif
            Sh9 gather = lpv3GatherTerm(d, nf), emit = lpv3EmitTerm(nf);
            float fr = max(0.0, sh9Dot(r, gather)) * t;
            float fg = max(0.0, sh9Dot(g, gather)) * t;
            float fb = max(0.0, sh9Dot(b, gather)) * t;
            outR = Sh9(outR.low + fr * emit.low, outR.high + fr * emit.high, outR.last + fr * emit.last);
            outG = Sh9(outG.low + fg * emit.low, outG.high + fg * emit.high, outG.last + fg * emit.last);
            outB = Sh9(outB.low + fb * emit.low, outB.high + fb * emit.high, outB.last + fb * emit.last);
        }
    }
}
