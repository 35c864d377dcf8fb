#version 450 core
// Test kernel for LpvGather3GLTest: one three-band gather step
// (lpv_transfer3.glsl) over volumes in buffers, to compare with the CPU twin
// lpvref::bands::propagateStep<3>. A cell's nine coefficients per channel
// are three vec4: (low, high, (last, 0, 0, 0)).
#include "sh.glsl"
#include "sh3.glsl"

layout(local_size_x = 64) in;

// Source: ((z * n + y) * n + x) * 3 + channel, times 3 vec4.
layout(std430, binding = 0) readonly buffer Source { vec4 source[]; };
// Geometry volume: (n + 1)^3 cells, 3 vec4 each.
layout(std430, binding = 1) readonly buffer Gv { vec4 gv[]; };
layout(std430, binding = 2) writeonly buffer Dest { vec4 dest[]; };

uniform int uGridSize3;
uniform float uStrength3;
uniform bool uOcclusion;

Sh9 sh9At(int base, bool fromGv) {
    vec4 l = fromGv ? gv[base] : source[base];
    vec4 h = fromGv ? gv[base + 1] : source[base + 1];
    vec4 t = fromGv ? gv[base + 2] : source[base + 2];
    return Sh9(l, h, t.x);
}

Sh9 lpv3Source(ivec3 q, int channel) {
    return sh9At((((q.z * uGridSize3 + q.y) * uGridSize3 + q.x) * 3 + channel) * 3, false);
}
void lpv3Sources(ivec3 q, out Sh9 r, out Sh9 g, out Sh9 b) {
    r = lpv3Source(q, 0);
    g = lpv3Source(q, 1);
    b = lpv3Source(q, 2);
}

// Trilinear over the GV's corner-centred cells, zero outside 0..n.
Sh9 lpv3Blocking(vec3 g) {
    vec3 base = floor(g);
    vec3 f = g - base;
    ivec3 b = ivec3(base);
    int m = uGridSize3 + 1;
    Sh9 sum = Sh9(vec4(0.0), vec4(0.0), 0.0);
    for (int corner = 0; corner < 8; ++corner) {
        ivec3 o = ivec3(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
        ivec3 c = b + o;
        if (any(lessThan(c, ivec3(0))) || any(greaterThan(c, ivec3(uGridSize3))))
            continue;
        float w = (o.x == 1 ? f.x : 1.0 - f.x) * (o.y == 1 ? f.y : 1.0 - f.y) * (o.z == 1 ? f.z : 1.0 - f.z);
        Sh9 s = sh9At(((c.z * m + c.y) * m + c.x) * 3, true);
        sum = Sh9(sum.low + w * s.low, sum.high + w * s.high, sum.last + w * s.last);
    }
    return sum;
}

// The face between q and q + d: GV coordinate q + 0.5 + 0.5 d.
Sh9 lpv3BlockingBetween(ivec3 q, ivec3 d) { return lpv3Blocking(vec3(q) + 0.5 + 0.5 * vec3(d)); }

#include "lpv_transfer3.glsl"

void write(int base, Sh9 f) {
    dest[base] = f.low;
    dest[base + 1] = f.high;
    dest[base + 2] = vec4(f.last, 0.0, 0.0, 0.0);
}

void main() {
    int i = int(gl_GlobalInvocationID.x);
    int n = uGridSize3;
    if (i >= n * n * n)
        return;
    ivec3 p = ivec3(i % n, (i / n) % n, i / (n * n));
    Sh9 r, g, b;
    lpv3Gather(p, uOcclusion, r, g, b);
    write((i * 3 + 0) * 3, r);
    write((i * 3 + 1) * 3, g);
    write((i * 3 + 2) * 3, b);
}
