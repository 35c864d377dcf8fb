// Soft shadows for forward shading (include after common.glsl). ShadowPass::
// bindForShading sets these uniforms; shading calls shadowVisibility() per light.
//
// PCSS (Fernando 2005): a blocker search over a region that grows with the
// light's size, the mean blocker depth, then a percentage-closer filter as
// wide as the penumbra that blocker casts: it grows with the blocker-receiver
// distance. The sun is an angular disc (tan of its half angle), local lights
// are spheres of radius uLocalLightRadius. Taps are a fixed Poisson disc
// (16 + 16, modest for llvmpipe); hardware 2x2 compare filtering smooths each.
const int MAX_CASCADES = 8;
const int MAX_LOCAL_SHADOWS = 4;
// Cubes of the point-light map (ShadowLights.h kMaxPointShadowCubes): an
// area light has one per quarter of its rectangle.
const int MAX_POINT_SHADOW_CUBES = 16;
const float MAX_FILTER_TEXELS = 24.0;
// A spot or point map's near plane over its far plane (ShadowLights.h
// kLocalShadowNearFraction): no blocker is nearer the light than that, so
// the mean blocker distance is floored there, not at a length in metres.
const float LOCAL_SHADOW_NEAR_FRACTION = 1e-3;

uniform float uShadowBias;            // shadow.bias, in texels
uniform mat4 uShadowCameraView;       // view depth selects the cascade

// The sun's cascades.
uniform int uSunShadowLight;          // light index, -1 = no sun shadows
uniform int uCascadeCount;
uniform mat4 uCascadeViewProj[MAX_CASCADES];
uniform float uCascadeSplitFar[MAX_CASCADES];   // view distance each cascade ends at
uniform float uCascadeTexel[MAX_CASCADES];      // world size of one texel
uniform float uCascadeDepthRange[MAX_CASCADES]; // world distance from depth 0 to depth 1
uniform float uSunTanHalfAngle;                 // 0 = hard shadows
uniform sampler2DArrayShadow uCascadeCompare;
uniform sampler2DArray uCascadeDepth;

// Spot and point lights: which layer (a point light's: cube) each light
// index uses, -1 = none; an area light's quarters take that cube and the next three.
uniform int uSpotShadowLayer[MAX_LIGHTS];
uniform int uPointShadowLayer[MAX_LIGHTS];
uniform mat4 uSpotViewProj[MAX_LOCAL_SHADOWS];
uniform float uSpotTanHalfFov[MAX_LOCAL_SHADOWS];
uniform vec3 uSpotPosition[MAX_LOCAL_SHADOWS];
uniform float uSpotFar[MAX_LOCAL_SHADOWS];
uniform vec3 uPointPosition[MAX_POINT_SHADOW_CUBES]; // per cube: a point light's, a quarter of an area light's centre
uniform float uPointFar[MAX_POINT_SHADOW_CUBES];
uniform float uPointRadius[MAX_POINT_SHADOW_CUBES]; // PCSS light radius: uLocalLightRadius (area lights: unused)
uniform float uLocalLightRadius;                // 0 = hard shadows
uniform sampler2DArrayShadow uSpotCompare;      // stores distance / far
uniform sampler2DArray uSpotDepth;
uniform samplerCubeArrayShadow uPointCompare;   // stores distance / far
uniform samplerCubeArray uPointDepth;

const vec2 SHADOW_POISSON[16] = vec2[](
    vec2(-0.94201624, -0.39906216), vec2(0.94558609, -0.76890725), vec2(-0.09418410, -0.92938870),
    vec2(0.34495938, 0.29387760), vec2(-0.91588581, 0.45771432), vec2(-0.81544232, -0.87912464),
    vec2(-0.38277543, 0.27676845), vec2(0.97484398, 0.75648379), vec2(0.44323325, -0.97511554),
    vec2(0.53742981, -0.47373420), vec2(-0.26496911, -0.41893023), vec2(0.79197514, 0.19090188),
    vec2(-0.24188840, 0.99706507), vec2(-0.81409955, 0.91437590), vec2(0.19984126, 0.78641367),
    vec2(0.14383161, -0.14100790));

// tan of the angle between the normal and the light, for slope-scaled bias.
float shadowSlope(vec3 n, vec3 toLight) {
    float c = clamp(dot(n, toLight), 0.0, 1.0);
    return min(sqrt(1.0 - c * c) / max(c, 1e-3), 8.0); // a cosine: unitless
}

// Visibility of `worldPos` in cascade k, or -1 when it falls outside the cascade.
float cascadeVisibility(int k, vec3 worldPos, vec3 n, vec3 toLight) {
    float texel = uCascadeTexel[k];
    float range = uCascadeDepthRange[k];
    float slope = shadowSlope(n, toLight);
    // Normal offset: a texel's worth along the normal, more at grazing angles.
    vec3 p = worldPos + n * (uShadowBias * texel * (1.0 + min(slope, 2.0)));
    vec3 uvz = (uCascadeViewProj[k] * vec4(p, 1.0)).xyz * 0.5 + 0.5;
    if (any(lessThan(uvz.xy, vec2(0.0))) || any(greaterThan(uvz.xy, vec2(1.0))))
        return -1.0;
    if (uvz.z >= 1.0)
        return 1.0;
    float receiver = uvz.z - uShadowBias * texel * 0.5 / range;
    float texelUv = 1.0 / float(textureSize(uCascadeCompare, 0).x);
    if (uSunTanHalfAngle <= 0.0)
        return texture(uCascadeCompare, vec4(uvz.xy, float(k), receiver));

    // Blockers can be anywhere between the receiver and the map's near plane;
    // the disc they must fall into grows with that distance.
    float searchTexels = clamp(uSunTanHalfAngle * uvz.z * range / texel, 1.0, MAX_FILTER_TEXELS);
    float blockerSum = 0.0;
    float blockers = 0.0;
    for (int i = 0; i < 16; ++i) {
        float d = texture(uCascadeDepth, vec3(uvz.xy + SHADOW_POISSON[i] * searchTexels * texelUv, float(k))).r;
        if (d < receiver) {
            blockerSum += d;
            blockers += 1.0;
        }
    }
    if (blockers == 0.0)
        return 1.0;
    float blocker = blockerSum / blockers;
    // Half-width of the penumbra: the sun's half angle over the blocker-receiver distance.
    float filterTexels = clamp(uSunTanHalfAngle * (uvz.z - blocker) * range / texel, 1.0, MAX_FILTER_TEXELS);
    // Taps away from the centre meet a tilted receiver at other depths.
    float reference = receiver - filterTexels * texel * min(slope, 2.0) / range;
    float lit = 0.0;
    for (int i = 0; i < 16; ++i)
        lit += texture(uCascadeCompare,
                       vec4(uvz.xy + SHADOW_POISSON[i] * filterTexels * texelUv, float(k), reference));
    return lit / 16.0;
}

// Cascade by view depth; the last 10% of each cascade blends into the next.
float sunVisibility(vec3 worldPos, vec3 n, vec3 toLight) {
    float depth = -(uShadowCameraView * vec4(worldPos, 1.0)).z;
    for (int k = 0; k < uCascadeCount && k < MAX_CASCADES; ++k) {
        if (depth > uCascadeSplitFar[k])
            continue;
        float v = cascadeVisibility(k, worldPos, n, toLight);
        if (v < 0.0)
            continue;
        float start = k == 0 ? 0.0 : uCascadeSplitFar[k - 1];
        float band = 0.1 * (uCascadeSplitFar[k] - start);
        float t = (depth - (uCascadeSplitFar[k] - band)) / band;
        if (t > 0.0 && k + 1 < uCascadeCount) {
            float next = cascadeVisibility(k + 1, worldPos, n, toLight);
            if (next >= 0.0)
                v = mix(v, next, t);
        }
        return v;
    }
    return 1.0;
}

// The sun cascade that shades `worldPos`, -1 beyond the last (the visualizers' cascade tint).
int sunCascadeIndex(vec3 worldPos) {
    float depth = -(uShadowCameraView * vec4(worldPos, 1.0)).z;
    for (int k = 0; k < uCascadeCount && k < MAX_CASCADES; ++k)
        if (depth <= uCascadeSplitFar[k])
            return k;
    return -1;
}

// Spot maps store distance / far: the blocker search region is the light's
// radius at the receiver, the penumbra radius * (receiver - blocker) / blocker.
float spotVisibility(int layer, vec3 worldPos, vec3 n, vec3 toLight) {
    float size = float(textureSize(uSpotCompare, 0).x);
    float far = uSpotFar[layer];
    float slope = shadowSlope(n, toLight);
    float dist = distance(worldPos, uSpotPosition[layer]);
    float texel = 2.0 * uSpotTanHalfFov[layer] * dist / size; // world size of a texel at the receiver
    vec3 p = worldPos + n * (uShadowBias * texel * (1.0 + min(slope, 2.0)));
    vec4 clip = uSpotViewProj[layer] * vec4(p, 1.0);
    if (clip.w <= 0.0)
        return 1.0;
    vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0))))
        return 1.0;
    float receiver = distance(p, uSpotPosition[layer]);
    float reference = (receiver - uShadowBias * texel * (1.0 + min(slope, 4.0))) / far;
    float texelUv = 1.0 / size;
    if (uLocalLightRadius <= 0.0)
        return texture(uSpotCompare, vec4(uv, float(layer), reference));
    float searchTexels = clamp(uLocalLightRadius / texel, 1.0, MAX_FILTER_TEXELS);
    float blockerSum = 0.0;
    float blockers = 0.0;
    for (int i = 0; i < 16; ++i) {
        float d = texture(uSpotDepth, vec3(uv + SHADOW_POISSON[i] * searchTexels * texelUv, float(layer))).r;
        if (d < reference) {
            blockerSum += d;
            blockers += 1.0;
        }
    }
    if (blockers == 0.0)
        return 1.0;
    float blocker = max(blockerSum / blockers, LOCAL_SHADOW_NEAR_FRACTION) * far;
    float penumbra = uLocalLightRadius * (receiver - blocker) / blocker; // world, at the receiver
    float filterTexels = clamp(penumbra / texel, 1.0, MAX_FILTER_TEXELS);
    reference -= filterTexels * texel * min(slope, 2.0) / far;
    float lit = 0.0;
    for (int i = 0; i < 16; ++i)
        lit += texture(uSpotCompare, vec4(uv + SHADOW_POISSON[i] * filterTexels * texelUv, float(layer), reference));
    return lit / 16.0;
}

float pointVisibility(int layer, vec3 worldPos, vec3 n, vec3 toLight) {
    float size = float(textureSize(uPointCompare, 0).x);
    float radius = uPointRadius[layer];
    float far = uPointFar[layer];
    float slope = shadowSlope(n, toLight);
    float dist = distance(worldPos, uPointPosition[layer]);
    float texel = 2.0 * dist / size; // world size of a cube texel at the receiver (face centre)
    vec3 p = worldPos + n * (uShadowBias * texel * (1.0 + min(slope, 2.0)));
    vec3 d = p - uPointPosition[layer];
    float receiver = length(d);
    vec3 dir = receiver > 0.0 ? d / receiver : vec3(0.0, 0.0, 1.0); // a float guard only: a receiver on the light
    float reference = (receiver - uShadowBias * texel * (1.0 + min(slope, 4.0))) / far;
    if (radius <= 0.0)
        return texture(uPointCompare, vec4(dir, float(layer)), reference);
    // Offsets on the plane perpendicular to the direction, in radians ~ world / distance.
    vec3 t = normalize(cross(abs(dir.y) < 0.99 ? vec3(0, 1, 0) : vec3(1, 0, 0), dir));
    vec3 b = cross(dir, t);
    float texelAngle = texel / receiver;
    float searchTexels = clamp(radius / texel, 1.0, MAX_FILTER_TEXELS);
    float blockerSum = 0.0;
    float blockers = 0.0;
    for (int i = 0; i < 16; ++i) {
        vec2 o = SHADOW_POISSON[i] * searchTexels * texelAngle;
        float s = texture(uPointDepth, vec4(dir + t * o.x + b * o.y, float(layer))).r;
        if (s < reference) {
            blockerSum += s;
            blockers += 1.0;
        }
    }
    if (blockers == 0.0)
        return 1.0;
    float blocker = max(blockerSum / blockers, LOCAL_SHADOW_NEAR_FRACTION) * far;
    float penumbra = radius * (receiver - blocker) / blocker;
    float filterTexels = clamp(penumbra / texel, 1.0, MAX_FILTER_TEXELS);
    reference -= filterTexels * texel * min(slope, 2.0) / far;
    float lit = 0.0;
    for (int i = 0; i < 16; ++i) {
        vec2 o = SHADOW_POISSON[i] * filterTexels * texelAngle;
        lit += texture(uPointCompare, vec4(dir + t * o.x + b * o.y, float(layer)), reference);
    }
    return lit / 16.0;
}

// Area lights (issue #46): the share of the light's rectangle a receiver
// sees, estimated at points spread over the rectangle, each weighted by the
// light it sends the receiver (cos cos / d^2), each looked up in the cube
// map of its quarter of the rectangle (ShadowPass: one cube at each
// quarter's centre). So the penumbra takes the light's shape and the
// receiver's foreshortened view of it, a face that sees only part of the
// light counts only that part, and nothing caps the penumbra's width in
// texels. Before, one cube at the centre was filtered by PCSS with a disc
// of the half diagonal, 16 fixed Poisson taps and a 24-texel cap: the
// penumbrae of the Cornell lamp were cut to half their width (a hard edge
// inside a soft one), banded (16 copies of the edge) and lumpy where the one
// mean blocker depth jumped.
// The points: correlated multi-jittered (Kensler 2013, 6 x 4 strata, pattern
// 5) on [-1, 1]^2, 6 in each quarter. Each has its own row and column and
// their projections on any direction are spread, so the taps' hard edges do
// not stack into bands; fixed, so shadows do not crawl when the camera moves.
const int AREA_SHADOW_TAPS = 24;
const vec2 AREA_SHADOW_TAP_POINTS[AREA_SHADOW_TAPS] = vec2[](
    vec2(-0.723102, -0.856415),
    vec2(-0.363777, -0.621122),
    vec2(-0.000336, -0.827524),
    vec2(0.291422, -0.917303),
    vec2(0.600516, -0.715499),
    vec2(0.921141, -0.559952),
    vec2(-0.885077, -0.355005),
    vec2(-0.553063, -0.113444),
    vec2(-0.197288, -0.287719),
    vec2(0.150274, -0.425800),
    vec2(0.472002, -0.226763),
    vec2(0.807420, -0.051551),
    vec2(-0.801870, 0.129805),
    vec2(-0.467036, 0.405410),
    vec2(-0.099945, 0.237794),
    vec2(0.199664, 0.055832),
    vec2(0.504075, 0.258680),
    vec2(0.835132, 0.482790),
    vec2(-0.951277, 0.616181),
    vec2(-0.652267, 0.868992),
    vec2(-0.271317, 0.720533),
    vec2(0.055206, 0.508532),
    vec2(0.402739, 0.785796),
    vec2(0.748104, 0.918814));

// Quarter offsets of a tap's stratum (6 x 4 strata on [-1, 1]^2: 1/3 wide,
// 1/2 high), rotated a little so no two land on one row or column.
const vec2 AREA_SHADOW_STRATUM_OFFSETS[4] = vec2[](
    vec2(-1.0 / 12.0, -1.0 / 16.0), vec2(1.0 / 24.0, -1.0 / 8.0),
    vec2(1.0 / 12.0, 1.0 / 16.0), vec2(-1.0 / 24.0, 1.0 / 8.0));

// A tap point on the light: the rectangle's, or for a disc (shape 1) the
// square mapped onto the disc by Shirley and Chiu's concentric map, which
// keeps each quarter in its quarter and the strata even.
vec2 areaShadowPoint(vec2 s, int shape) {
    if (shape != 1 || s == vec2(0.0))
        return s;
    float r = abs(s.x) > abs(s.y) ? s.x : s.y;
    float phi = abs(s.x) > abs(s.y) ? 0.25 * PI * s.y / s.x : 0.5 * PI - 0.25 * PI * s.x / s.y;
    return r * vec2(cos(phi), sin(phi));
}

// Where the segment from the receiver p to the light point q lies at depth
// z along `dir`, the unit direction from the map's centre c to p (d = their
// distance): relative to c, for the map lookup.
vec3 areaShadowTap(vec3 p, vec3 q, vec3 c, vec3 dir, float d, float z) {
    float f = (d - z) / max(d - dot(q - c, dir), 1e-6 * d);
    return p + clamp(f, 0.0, 1.0) * (q - p) - c;
}

// Distance from c along the unit direction u to the receiver's plane
// (through p, normal n): each tap is compared against the receiver's own
// depth there, so a flat receiver never shadows itself however far the taps
// spread (receiver-plane depth bias; a slope term that grew with the
// filter's width stood in for it). A plane the ray cannot meet, or meets
// only far behind the receiver, gives twice the receiver's distance.
float areaShadowPlaneDistance(vec3 p, vec3 n, vec3 c, vec3 u, float d) {
    float denominator = dot(u, n);
    float t = denominator < 0.0 ? dot(p - c, n) / denominator : 2.0 * d;
    return t > 0.0 ? min(t, 2.0 * d) : 2.0 * d;
}

// The light point q's share of the light at p (normal n): cos cos / d^2,
// 0 where q is below p's horizon or p behind a one-sided light.
float areaShadowWeight(vec3 p, vec3 n, vec3 q, vec3 lightNormal, bool twoSided) {
    vec3 pq = q - p;
    float d2 = dot(pq, pq);
    float cosLight = -dot(lightNormal, pq);
    cosLight = twoSided ? abs(cosLight) : max(cosLight, 0.0);
    return max(dot(n, pq), 0.0) * cosLight / max(d2 * d2, 1e-30);
}

// Tap i of the area light: its quarter (which of the four cubes sees it) and
// its point on the light's surface. Both loops below take their taps here.
int areaShadowQuarter(int i) {
    vec2 s = AREA_SHADOW_TAP_POINTS[i];
    return (s.x > 0.0 ? 1 : 0) + (s.y > 0.0 ? 2 : 0);
}
vec3 areaShadowLightPoint(int i, vec3 center, vec3 halfU, vec3 halfV, int shape) {
    vec2 a = areaShadowPoint(AREA_SHADOW_TAP_POINTS[i], shape);
    return center + halfU * a.x + halfV * a.y;
}

// 1 = the whole light seen, 0 = none of it; `firstCube` is its first quarter's cube.
float areaLightVisibility(int firstCube, vec3 worldPos, vec3 n, vec3 center, vec3 lightNormal, vec3 halfU,
                          vec3 halfV, int shape, bool twoSided) {
    float size = float(textureSize(uPointCompare, 0).x);
    float dist = distance(worldPos, center);
    if (dist <= 0.0)
        return 1.0; // a float guard only: a receiver on the light
    float texel = 2.0 * dist / size; // world size of a cube texel at the receiver (face centre)
    // A texel along the normal, no more: the taps compare against the
    // receiver's plane, which keeps flat receivers from shadowing
    // themselves, and the point lights' wider offset (up to 3 texels at
    // grazing angles) moved the penumbrae measurably (issue #46: the red
    // wall's error against the reference 4.5% with it, 3.1% without).
    vec3 p = worldPos + n * (uShadowBias * texel);
    float bias = uShadowBias * texel;

    // Blocker search: each point's segment sampled half way to the light,
    // where what blocks it shows. A tap counts by how much of its bilinear
    // footprint is in front of the receiver, so blocker depths change
    // smoothly as blockers come into the taps; counted all or nothing, they
    // jumped and made lumps.
    float blockedShare[AREA_SHADOW_TAPS];
    float blockerDepth[AREA_SHADOW_TAPS];
    vec4 quarterSum = vec4(0.0);    // per quarter: blocked share x depth
    vec4 quarterWeight = vec4(0.0); // per quarter: blocked share
    for (int i = 0; i < AREA_SHADOW_TAPS; ++i) {
        int quarter = areaShadowQuarter(i);
        int cube = firstCube + quarter;
        vec3 c = uPointPosition[cube];
        vec3 q = areaShadowLightPoint(i, center, halfU, halfV, shape);
        blockedShare[i] = 0.0;
        blockerDepth[i] = 0.0;
        if (areaShadowWeight(p, n, q, lightNormal, twoSided) <= 0.0 || dot(c - p, n) <= 0.0)
            continue;
        float d = distance(p, c);
        vec3 u = normalize(areaShadowTap(p, q, c, (p - c) / d, d, 0.5 * d));
        float receiver = areaShadowPlaneDistance(p, n, c, u, d) - bias;
        float far = uPointFar[cube];
        float blocked = 1.0 - texture(uPointCompare, vec4(u, float(cube)), receiver / far);
        if (blocked <= 0.0)
            continue;
        blockedShare[i] = blocked;
        blockerDepth[i] = min(texture(uPointDepth, vec4(u, float(cube))).r * far, receiver);
        quarterSum[quarter] += blocked * blockerDepth[i];
        quarterWeight[quarter] += blocked;
    }
    if (all(equal(quarterWeight, vec4(0.0))))
        return 1.0;

    // Each point tested where its segment crosses the depth of what blocked
    // its own search tap, or, as far as that found nothing, its quarter's
    // mean blocker depth (PCSS for the quarter); a quarter with no blocker is seen.
    float lit = 0.0;
    float weight = 0.0;
    for (int i = 0; i < AREA_SHADOW_TAPS; ++i) {
        int quarter = areaShadowQuarter(i);
        int cube = firstCube + quarter;
        vec3 c = uPointPosition[cube];
        vec3 q = areaShadowLightPoint(i, center, halfU, halfV, shape);
        float w = areaShadowWeight(p, n, q, lightNormal, twoSided);
        if (w <= 0.0)
            continue;
        weight += w;
        // A quarter whose centre is behind the receiver's plane cannot see
        // it (the tall block's front face sees the lamp's front edge only):
        // its points in front of the plane are taken as seen, not as
        // blocked by the receiver's own body.
        if (quarterWeight[quarter] <= 0.0 || dot(c - p, n) <= 0.0) {
            lit += w;
            continue;
        }
        float far = uPointFar[cube];
        float meanBlocker = quarterSum[quarter] / quarterWeight[quarter];
        float blocker = max(mix(meanBlocker, blockerDepth[i], blockedShare[i]), LOCAL_SHADOW_NEAR_FRACTION * far);
        float d = distance(p, c);
        vec3 dir = (p - c) / d;
        // The point stands for its stratum of the light (a sixth of the
        // width, a quarter of the height): four points at the stratum's
        // quarter offsets, tested at the same blocker depth, so each tap's
        // edge is a ramp as wide as the stratum's own penumbra in four
        // steps, not one hard line (the faint lines of issue #46).
        vec2 s = AREA_SHADOW_TAP_POINTS[i];
        float seen = 0.0;
        for (int k = 0; k < 4; ++k) {
            vec2 o = AREA_SHADOW_STRATUM_OFFSETS[k];
            vec2 a = areaShadowPoint(clamp(s + o, vec2(-1.0), vec2(1.0)), shape);
            vec3 qk = center + halfU * a.x + halfV * a.y;
            vec3 u = normalize(areaShadowTap(p, qk, c, dir, d, blocker));
            float reference = (areaShadowPlaneDistance(p, n, c, u, d) - bias) / far;
            seen += texture(uPointCompare, vec4(u, float(cube)), reference);
        }
        lit += w * 0.25 * seen;
    }
    return weight > 0.0 ? lit / weight : 1.0;
}

// 1 = lit, 0 = in shadow, for light `lightIndex` seen along `toLight` from
// `worldPos` (`dist` = distance to a local light; unused for the sun).
float shadowVisibility(int lightIndex, vec3 worldPos, vec3 n, vec3 toLight, float dist) {
    if (lightIndex == uSunShadowLight)
        return sunVisibility(worldPos, n, toLight);
    if (lightIndex < 0 || lightIndex >= MAX_LIGHTS)
        return 1.0;
#ifndef LPV_NO_LOCAL_SHADOWS // forward.frag's variant for scenes whose local lights cast none
    if (uSpotShadowLayer[lightIndex] >= 0)
        return spotVisibility(uSpotShadowLayer[lightIndex], worldPos, n, toLight);
    if (uPointShadowLayer[lightIndex] >= 0)
        return pointVisibility(uPointShadowLayer[lightIndex], worldPos, n, toLight);
#endif
    return 1.0;
}

// An area light's visibility (its own function: it needs the light's frame);
// 1 where the light casts no shadows or the variant has no local shadows.
float areaShadowVisibility(int lightIndex, vec3 worldPos, vec3 n, vec3 center, vec3 lightNormal, vec3 halfU,
                           vec3 halfV, int shape, bool twoSided) {
#ifndef LPV_NO_LOCAL_SHADOWS
    if (lightIndex >= 0 && lightIndex < MAX_LIGHTS && uPointShadowLayer[lightIndex] >= 0)
        return areaLightVisibility(uPointShadowLayer[lightIndex], worldPos, n, center, lightNormal, halfU, halfV,
                                   shape, twoSided);
#endif
    return 1.0;
}
