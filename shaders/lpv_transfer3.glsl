// One gather step of the three-band LPV (issue #47), the GLSL twin of
// lpvref::bands::propagateStep<3> (docs/lpv.md, "Three bands"): the 30
// face-transfer terms and the occluded transfer into one destination cell.
// Include sh.glsl and sh3.glsl first. The caller supplies the volume access:
//   Sh9 lpv3Source(ivec3 q, int channel)  the source cell's SH (inside the grid)
//   Sh9 lpv3Blocking(vec3 g)              the geometry volume at GV coordinate g
// (both defined before including this file), and uGridSize3 / uStrength3.
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

bool lpv3Inside(ivec3 c) { return all(greaterThanEqual(c, ivec3(0))) && all(lessThan(c, ivec3(uGridSize3))); }

// 1 - clamp(strength B(-travel)) at GV coordinate g.
float lpv3Transmittance(vec3 g, vec3 travel) {
    return 1.0 - clamp(uStrength3 * sh9Evaluate(lpv3Blocking(g), -travel), 0.0, 1.0);
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
        Sh9 r = lpv3Source(q, 0), g = lpv3Source(q, 1), b = lpv3Source(q, 2);
        for (int f = 0; f < 6; ++f) {
            ivec3 nf = LPV3_AXES[f];
            if (nf == -d)
                continue; // the face shared with q: light enters there
            vec3 dir = normalize(vec3(d) + 0.5 * vec3(nf));
            float t = occlusion ? lpv3Transmittance(vec3(q) + 0.5 + 0.5 * vec3(d), dir) : 1.0;
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
