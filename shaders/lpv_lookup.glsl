// Indirect diffuse light from the LPV at shading (docs/lpv.md, Lookup):
// trilinear accumulator samples, irradiance toward the normal, blend between
// cascades, light-bleeding damping. LpvPass::bindForShading sets these.
// Needs sh.glsl included before it (includes are one level deep).

uniform int uLpvCascadeCount; // 0: no LPV this frame
uniform int uLpvGridSize;
uniform vec3 uLpvOrigin[6];
uniform float uLpvCellSize[6];
uniform float uLpvIntensity;
uniform float uLpvBleedingDamping;
uniform int uLpvBlendLevels;
uniform sampler3D uLpvAccumR;
uniform sampler3D uLpvAccumG;
uniform sampler3D uLpvAccumB;

// Cells between x and the nearest face of cascade k's cube (negative outside).
float lpvMargin(int k, vec3 x) {
    vec3 u = (x - uLpvOrigin[k]) / uLpvCellSize[k];
    vec3 m = min(u, vec3(uLpvGridSize) - u);
    return min(m.x, min(m.y, m.z));
}

// Irradiance (rgb) from cascade k at x toward normal n, times s^-2.
vec3 lpvIrradianceRaw(int k, vec3 x, vec3 n) {
    float grid = float(uLpvGridSize);
    vec3 u = clamp((x - uLpvOrigin[k]) / uLpvCellSize[k], vec3(0.5), vec3(grid - 0.5));
    // Cascades are stacked along z: clamping keeps the filter inside cascade k.
    vec3 uvw = vec3(u.xy / grid, (float(k) * grid + u.z) / (grid * float(uLpvCascadeCount)));
    vec4 lobe = shCosineLobe(-n);
    vec3 e = vec3(dot(texture(uLpvAccumR, uvw), lobe), dot(texture(uLpvAccumG, uvw), lobe),
                  dot(texture(uLpvAccumB, uvw), lobe));
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
