// Glossy reflections from the LPV (docs/lpv.md, Glossy reflections): a ray
// marched from the surface along the reflection vector, reading at each step
// the finest cascade that holds the point and whose cells are as wide as the
// reflection cone there. The GLSL twin of renderer/src/lpvref/LpvGlossy.cpp
// (LpvGlossyGLTest checks they agree). It reuses the diffuse lookup's
// accumulator samplers: it adds no sampler to the forward pass.
// Needs sh.glsl and lpv_lookup.glsl included before it.

uniform int uGlossyEnabled;       // 1: the scene analysis runs glossy reflections this frame
uniform float uGlossyThreshold;   // effects.glossyThreshold: at or below it a material gets none
uniform int uGlossySteps;         // effects.glossySteps
uniform float uGlossyMaxDistance; // effects.glossyMaxDistance, in cells of the finest cascade
uniform float uGlossyIntensity;   // effects.glossyIntensity
uniform float uGlossiness;        // the material's (MaterialGpu::bind): 0 diffuse .. 1 mirror

bool lpvGlossyRuns(float glossiness) {
    return uGlossyEnabled != 0 && uLpvCascadeCount > 0 && glossiness > uGlossyThreshold;
}

// The cascade a sample at x reads: the finest with margin >= 1 whose cells
// are at least `footprint` wide, else the coarsest with margin >= 1; -1 if none.
int lpvGlossyCascade(vec3 x, float footprint) {
    int found = -1;
    for (int k = 0; k < uLpvCascadeCount; ++k) {
        if (lpvMargin(k, x) < 1.0)
            continue;
        found = k;
        if (uLpvCellSize[k] >= footprint)
            break;
    }
    return found;
}

// Radiance of light at x travelling along `travel`: cascade k's intensity in
// that direction over the cell's face area (as the diffuse lookup), >= 0.
vec3 lpvRadianceToward(int k, vec3 x, vec3 travel) {
    float grid = float(uLpvGridSize);
    vec3 u = clamp((x - uLpvOrigin[k]) / uLpvCellSize[k], vec3(0.5), vec3(grid - 0.5));
    vec3 uvw = vec3(u.xy / grid, (float(k) * grid + u.z) / (grid * float(uLpvCascadeCount)));
    vec4 basis = shBasis(travel);
    vec3 i = vec3(dot(texture(uLpvAccumR, uvw), basis), dot(texture(uLpvAccumG, uvw), basis),
                  dot(texture(uLpvAccumB, uvw), basis));
    float s = uLpvCellSize[k];
    return max(i, vec3(0.0)) / (s * s);
}

// Radiance arriving at x from unit direction r, averaged over the march's
// samples, times lpv.intensity and effects.glossyIntensity.
vec3 lpvGlossyIncoming(vec3 x, vec3 r, float glossiness) {
    if (uLpvCascadeCount <= 0 || uGlossySteps <= 0)
        return vec3(0.0);
    // Steps grow geometrically from one finest cell to the maximum distance:
    // equal weights per sample then favour what is near (each covers dt / t).
    float t0 = uLpvCellSize[0];
    float tMax = max(uGlossyMaxDistance * t0, t0);
    float growth = uGlossySteps > 1 ? pow(tMax / t0, 1.0 / float(uGlossySteps - 1)) : 1.0;
    // tan of the cone's half angle: a mirror reads the finest cells, a rough surface coarser ones.
    float spread = 1.0 - clamp(glossiness, 0.0, 1.0);
    vec3 sum = vec3(0.0);
    int samples = 0;
    float t = t0;
    for (int i = 0; i < uGlossySteps; ++i) {
        vec3 p = x + r * t;
        int k = lpvGlossyCascade(p, 2.0 * t * spread);
        if (k < 0)
            break; // left the coarsest cascade: a ray does not come back into a cube it left
        sum += lpvRadianceToward(k, p, -r);
        ++samples;
        t *= growth;
    }
    return samples > 0 ? sum / float(samples) * (uLpvIntensity * uGlossyIntensity) : vec3(0.0);
}

// Glossiness times Schlick's Fresnel term of the specular colour f0.
vec3 lpvGlossyReflectance(vec3 f0, float glossiness, float nDotV) {
    float m = pow(1.0 - clamp(nDotV, 0.0, 1.0), 5.0);
    return clamp(glossiness, 0.0, 1.0) * (f0 + (vec3(1.0) - f0) * m);
}

// What the glossy lobe adds toward the viewer at x (normal n, unit v toward the viewer).
vec3 lpvGlossyReflection(vec3 x, vec3 n, vec3 v, vec3 f0, float glossiness) {
    vec3 r = reflect(-v, n);
    return lpvGlossyReflectance(f0, glossiness, dot(n, v)) * lpvGlossyIncoming(x, r, glossiness);
}
