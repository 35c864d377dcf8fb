// Subsurface LPV at shading (docs/lpv.md, "Subsurface LPV"): the irradiance
// on the back of a translucent surface, i.e. light that crossed the material
// and leaves through this face, from the packed subsurface accumulator
// (lpv_subsurface.glsl's layout, one sampler for the three channels). Same
// cascade choice and blend as lpvIrradiance; no bleeding damping: this light
// is meant to come from behind. Needs sh.glsl and lpv_lookup.glsl before it.
//
// The fragment stage already has 16 samplers, GL's minimum: ForwardRenderer
// defines LPV_NO_SUBSURFACE_SAMPLER where GL_MAX_TEXTURE_IMAGE_UNITS < 17,
// and the renderer then never runs the subsurface LPV.

uniform bool uLpvSubsurface; // false: no subsurface LPV this frame
#ifndef LPV_NO_SUBSURFACE_SAMPLER
uniform sampler3D uLpvSubsurfaceVolume;
#endif

vec3 lpvSubsurfaceRaw(int k, vec3 x, vec3 n) {
#ifdef LPV_NO_SUBSURFACE_SAMPLER
    return vec3(0.0);
#else
    float grid = float(uLpvGridSize);
    vec3 u = clamp((x - uLpvOrigin[k]) / uLpvCellSize[k], vec3(0.5), vec3(grid - 0.5));
    // Clamped inside the cell block, the filter never reads the next channel or cascade.
    float y = u.y / grid, z = (float(k) * grid + u.z) / (grid * float(uLpvCascadeCount));
    // The back face's normal is -n: irradiance(L, -n) = dot(L, cosineLobe(n)).
    vec4 lobe = shCosineLobe(n);
    vec3 e;
    for (int c = 0; c < 3; ++c)
        e[c] = dot(texture(uLpvSubsurfaceVolume, vec3((u.x + float(c) * grid) / (3.0 * grid), y, z)), lobe);
    float s = uLpvCellSize[k];
    return max(e, vec3(0.0)) / (s * s);
#endif
}

// Irradiance leaving through the surface at x with normal n, times lpv.intensity.
vec3 lpvSubsurfaceIrradiance(vec3 x, vec3 n) {
    if (!uLpvSubsurface)
        return vec3(0.0);
    for (int k = 0; k < uLpvCascadeCount; ++k) {
        float margin = lpvMargin(k, x);
        if (margin < 1.0)
            continue;
        float w = clamp((margin - 1.0) / 2.0, 0.0, 1.0);
        vec3 e = lpvSubsurfaceRaw(k, x, n);
        if (k + 1 < uLpvCascadeCount && w < 1.0)
            e = w * e + (1.0 - w) * lpvSubsurfaceRaw(k + 1, x, n);
        return e * uLpvIntensity;
    }
    return vec3(0.0);
}
