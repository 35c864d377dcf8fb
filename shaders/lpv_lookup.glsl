// Indirect diffuse light from the LPV at shading (docs/lpv.md, Lookup):
// trilinear accumulator samples (or, with lpv.visibilityLookup, 8 taps each
// weighted by the chance that the point sees it), irradiance toward the
// normal, blend between cascades, light-bleeding damping.
// LpvPass::bindForShading sets these.
// Needs sh.glsl included before it (includes are one level deep).

uniform int uLpvCascadeCount; // 0: no LPV this frame
uniform int uLpvGridSize;
uniform vec3 uLpvOrigin[6];
uniform float uLpvCellSize[6];
uniform float uLpvIntensity;
uniform float uLpvBleedingDamping;
uniform int uLpvBlendLevels;
uniform float uLpvLookupOffset; // lpv.lookupOffset: cells along the normal
uniform sampler3D uLpvAccumR;
uniform sampler3D uLpvAccumG;
uniform sampler3D uLpvAccumB;
#if LPV_SH_BANDS == 3
// lpv.shBands = 3 (issue #47; the lpvPropagation stage adds the define):
// band 2 of the accumulator, 4N x N x NK, the planes high R, G, B (Y2-2..Y21)
// and last rgb (Y22) side by side along x. The coordinate is clamped to
// [0.5, N - 0.5] like the cascades', so the filter never mixes two planes.
uniform sampler3D uLpvAccumHigh;

// Band 2 of the irradiance (dot with cosineLobe(-n)'s band 2, pi/4 Y2m(-n)
// = pi/4 Y2m(n): band 2 is even) at clamped cell coordinate u of cascade k:
// the clamped cosine's band-2 factor pi/4 (sh3.glsl's SH_A2 and constants).
vec3 lpvBand2(int k, vec3 u, vec3 n) {
    float grid = float(uLpvGridSize);
    vec4 lobeHigh = (SH_PI / 4.0) * vec4(1.092548431 * n.x * n.y, -1.092548431 * n.y * n.z,
                                               0.315391565 * (3.0 * n.z * n.z - 1.0), -1.092548431 * n.x * n.z);
    float lobeLast = (SH_PI / 4.0) * 0.546274215 * (n.x * n.x - n.y * n.y);
    vec3 e = vec3(0.0);
    float w = (float(k) * grid + u.z) / (grid * float(uLpvCascadeCount));
    for (int c = 0; c < 3; ++c)
        e[c] = dot(texture(uLpvAccumHigh, vec3((float(c) * grid + u.x) / (4.0 * grid), u.y / grid, w)), lobeHigh);
    return e + lobeLast * texture(uLpvAccumHigh, vec3((3.0 * grid + u.x) / (4.0 * grid), u.y / grid, w)).rgb;
}
#endif
// The visibility-aware lookup (docs/lpv.md; lpvref::irradianceVisibleAt is
// the CPU twin): per cell and axis the distance moments lpv_visibility.comp
// wrote. An image, not a sampler: the forward pass has no sampler unit left.
uniform int uLpvVisibility;       // 1: on and built this frame
uniform float uLpvVisibilityBias; // cells along the normal
layout(binding = 7, rgba32f) uniform readonly image3D uLpvMoments;
const float LPV_MIN_VARIANCE = 1e-4; // cells^2 (lpvref::VisibilitySettings)

// Cells between x and the nearest face of cascade k's cube (negative outside).
float lpvMargin(int k, vec3 x) {
    vec3 u = (x - uLpvOrigin[k]) / uLpvCellSize[k];
    vec3 m = min(u, vec3(uLpvGridSize) - u);
    return min(m.x, min(m.y, m.z));
}

// The chance that a point at `offset` (cells) from the centre of the cell at
// `texel` sees it: per axis the one-sided Chebyshev bound beyond the mean
// distance toward the point, multiplied (lpvref::chebyshevVisibility).
float lpvTapVisibility(ivec3 texel, vec3 offset) {
    float visible = 1.0;
    for (int a = 0; a < 3; ++a) {
        vec4 m = imageLoad(uLpvMoments, ivec3(3 * texel.x + a, texel.yz));
        vec2 moments = offset[a] < 0.0 ? m.zw : m.xy;
        float d = abs(offset[a]);
        if (d > moments.x) {
            float variance = max(moments.y - moments.x * moments.x, LPV_MIN_VARIANCE);
            visible *= variance / (variance + (d - moments.x) * (d - moments.x));
        }
    }
    return visible;
}

// lpvIrradianceRaw with the 8 taps of the trilinear filter fetched by hand,
// each weighted by its visibility from x moved along n, renormalised.
vec3 lpvIrradianceVisible(int k, vec3 x, vec3 n) {
    int grid = uLpvGridSize;
    vec3 u = (x - uLpvOrigin[k]) / uLpvCellSize[k];
    vec3 seen = u + n * uLpvVisibilityBias;
    vec3 v = clamp(u - 0.5, vec3(0.0), vec3(float(grid - 1)));
    ivec3 i0 = min(ivec3(floor(v)), ivec3(grid - 1));
    ivec3 i1 = min(i0 + 1, ivec3(grid - 1));
    vec3 f = v - vec3(i0);
    vec4 weightedR = vec4(0.0), weightedG = vec4(0.0), weightedB = vec4(0.0);
    vec4 plainR = vec4(0.0), plainG = vec4(0.0), plainB = vec4(0.0);
    float weights = 0.0;
    for (int corner = 0; corner < 8; ++corner) {
        bvec3 o = bvec3(corner & 1, corner & 2, corner & 4);
        ivec3 c = mix(i0, i1, o);
        vec3 t = mix(1.0 - f, f, o);
        float trilinear = t.x * t.y * t.z;
        ivec3 texel = ivec3(c.xy, k * grid + c.z);
        float w = trilinear * lpvTapVisibility(texel, seen - (vec3(c) + 0.5));
        vec4 r = texelFetch(uLpvAccumR, texel, 0), g = texelFetch(uLpvAccumG, texel, 0),
             b = texelFetch(uLpvAccumB, texel, 0);
        weights += w;
        weightedR += w * r;
        weightedG += w * g;
        weightedB += w * b;
        plainR += trilinear * r;
        plainG += trilinear * g;
        plainB += trilinear * b;
    }
    vec4 lobe = shCosineLobe(-n);
    // Every tap hidden (a point inside a closed cell): the plain lookup rather than a division by zero.
    vec3 e = weights > 1e-6 ? vec3(dot(weightedR, lobe), dot(weightedG, lobe), dot(weightedB, lobe)) / weights
                            : vec3(dot(plainR, lobe), dot(plainG, lobe), dot(plainB, lobe));
    float s = uLpvCellSize[k];
    return max(e, vec3(0.0)) / (s * s);
}

// Irradiance (rgb) from cascade k at x toward normal n, times s^-2.
vec3 lpvIrradianceRaw(int k, vec3 x, vec3 n) {
    // lpv.lookupOffset: read in front of the surface; at x itself the
    // trilinear filter takes half its taps from cells behind the surface
    // (outside the room, inside the wall). lpvref::irradianceAt's twin.
    x += n * (uLpvLookupOffset * uLpvCellSize[k]);
#ifndef LPV_NO_VISIBILITY // forward.frag's variant for frames without the moments
    if (uLpvVisibility != 0)
        return lpvIrradianceVisible(k, x, n);
#endif
    float grid = float(uLpvGridSize);
    vec3 u = clamp((x - uLpvOrigin[k]) / uLpvCellSize[k], vec3(0.5), vec3(grid - 0.5));
    // Cascades are stacked along z: clamping keeps the filter inside cascade k.
    vec3 uvw = vec3(u.xy / grid, (float(k) * grid + u.z) / (grid * float(uLpvCascadeCount)));
    vec4 lobe = shCosineLobe(-n);
    vec3 e = vec3(dot(texture(uLpvAccumR, uvw), lobe), dot(texture(uLpvAccumG, uvw), lobe),
                  dot(texture(uLpvAccumB, uvw), lobe));
#if LPV_SH_BANDS == 3
    e += lpvBand2(k, u, n);
#endif
    float s = uLpvCellSize[k];
    return max(e, vec3(0.0)) / (s * s);
}

// With damping: E at x compared with E half a cell in front of the surface.
vec3 lpvIrradianceCascade(int k, vec3 x, vec3 n) {
    vec3 e0 = lpvIrradianceRaw(k, x, n);
    if (uLpvBleedingDamping <= 0.0)
        return e0;
    vec3 e1 = lpvIrradianceRaw(k, x + n * (0.5 * uLpvCellSize[k]), n);
    float l0 = dot(e0, vec3(0.2126, 0.7152, 0.0722));
    float l1 = dot(e1, vec3(0.2126, 0.7152, 0.0722));
    float damping = clamp(1.0 - uLpvBleedingDamping * max(0.0, l0 - l1) / max(l0, 1e-20), 0.0, 1.0);
    return e0 * damping;
}

// Indirect irradiance at x with normal n, times lpv.intensity (0 without an LPV).
vec3 lpvIrradiance(vec3 x, vec3 n) {
    int first = -1;
    for (int k = 0; k < uLpvCascadeCount; ++k) {
        if (lpvMargin(k, x) >= 1.0) {
            first = k;
            break;
        }
    }
    if (first < 0)
        return vec3(0.0);
    // The finest cascade fades out over its outer two cells into the next one.
    float w = clamp((lpvMargin(first, x) - 1.0) / 2.0, 0.0, 1.0);
    int next = first + 1;
    vec3 e;
    if (next < uLpvCascadeCount && w < 1.0)
        e = w * lpvIrradianceCascade(first, x, n) + (1.0 - w) * lpvIrradianceCascade(next, x, n);
    else
        e = lpvIrradianceCascade(first, x, n);
    // More blend levels average in coarser cascades (smoother, as the thesis found).
    int levels = 1;
    for (int k = first + 2; k < uLpvCascadeCount && k < first + uLpvBlendLevels; ++k) {
        if (lpvMargin(k, x) < 1.0)
            break;
        e += lpvIrradianceCascade(k, x, n);
        ++levels;
    }
    return e / float(levels) * uLpvIntensity;
}
