#version 450 core
// Test kernel for LpvGather3GLTest: the two-band twin of lpv_gather3_test.comp
// (same structure, vec4 coefficients and sh.glsl), so that one gather step's
// cost in two and three bands is compared on kernels that differ only in the
// band count; checked against lpvref::bands::propagateStep<2>.
#include "sh.glsl"

layout(local_size_x = 64) in;

// Source: ((z * n + y) * n + x) * 3 + channel, one vec4 each; GV: (n + 1)^3 vec4.
layout(std430, binding = 0) readonly buffer Source { vec4 source[]; };
layout(std430, binding = 1) readonly buffer Gv { vec4 gv[]; };
layout(std430, binding = 2) writeonly buffer Dest { vec4 dest[]; };

uniform int uGridSize3;
uniform float uStrength3;
uniform bool uOcclusion;

const ivec3 AXES[6] = ivec3[6](ivec3(1, 0, 0), ivec3(-1, 0, 0), ivec3(0, 1, 0), ivec3(0, -1, 0), ivec3(0, 0, 1),
                               ivec3(0, 0, -1));

vec4 blocking(vec3 g) {
    vec3 base = floor(g);
    vec3 f = g - base;
    ivec3 b = ivec3(base);
    int m = uGridSize3 + 1;
    vec4 sum = vec4(0.0);
    for (int corner = 0; corner < 8; ++corner) {
        ivec3 o = ivec3(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
        ivec3 c = b + o;
        if (any(lessThan(c, ivec3(0))) || any(greaterThan(c, ivec3(uGridSize3))))
            continue;
        float w = (o.x == 1 ? f.x : 1.0 - f.x) * (o.y == 1 ? f.y : 1.0 - f.y) * (o.z == 1 ? f.z : 1.0 - f.z);
        sum += w * gv[(c.z * m + c.y) * m + c.x];
    }
    return sum;
}

void main() {
    int i = int(gl_GlobalInvocationID.x);
    int n = uGridSize3;
    if (i >= n * n * n)
        return;
    ivec3 p = ivec3(i % n, (i / n) % n, i / (n * n));
    vec4 outC[3] = vec4[3](vec4(0.0), vec4(0.0), vec4(0.0));
    for (int a = 0; a < 6; ++a) {
        ivec3 d = AXES[a];
        ivec3 q = p - d;
        if (any(lessThan(q, ivec3(0))) || any(greaterThanEqual(q, ivec3(n))))
            continue;
        int at = ((q.z * n + q.y) * n + q.x) * 3;
        vec4 src[3] = vec4[3](source[at], source[at + 1], source[at + 2]);
        for (int f = 0; f < 6; ++f) {
            ivec3 nf = AXES[f];
            if (nf == -d)
                continue;
            vec3 dir = normalize(vec3(d) + 0.5 * vec3(nf));
            float t = uOcclusion
                          ? 1.0 - clamp(uStrength3 * shEvaluate(blocking(vec3(q) + 0.5 + 0.5 * vec3(d)), -dir), 0.0, 1.0)
                          : 1.0;
            vec4 gather = (nf == d ? 0.4006696846 : 0.4234313544) * shBasis(dir);
            vec4 emit = shCosineLobe(vec3(nf)) / SH_PI;
            for (int c = 0; c < 3; ++c)
                outC[c] += max(0.0, dot(src[c], gather)) * t * emit;
        }
    }
    for (int c = 0; c < 3; ++c)
        dest[i * 3 + c] = outC[c];
}
