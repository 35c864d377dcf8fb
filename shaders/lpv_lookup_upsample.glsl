// The LPV's diffuse lookup at reduced resolution, upsampled (the
// lpvLookupResolve pass's lpv_lookup_resolve.frag; the lpvLookup pass,
// LpvLookupPass.cpp, drew the low-resolution image): a joint bilateral
// upsample over the 2x2 low-resolution texels around this pixel, each
// weighted by its bilinear weight, by how well its distance from the camera
// fits this surface's and by how close its normal is to this pixel's (cos^8:
// 20 degrees apart 0.61, 45 degrees 0.06) (both the interpolated vertex
// normal seen from the viewer's side). Where all the weights are tiny (an
// edge whose neighbours lie on other surfaces) it says so, and the pixel is
// looked up at full resolution (lpv_lookup_fallback.comp).

uniform sampler2D uLpvLowIrradiance; // rgb E, a distance x uLpvLowDistanceScale (< 0: no surface)
uniform sampler2D uLpvLowNormal;     // n * 0.5 + 0.5 (0: no surface)
uniform vec2 uLpvLowScale;           // low-resolution texels per full-resolution pixel, per axis
uniform float uLpvLowDistanceScale;

// Below this summed weight no neighbour lies on this pixel's surface.
const float LPV_UPSAMPLE_MIN_WEIGHT = 1e-3;

// The interpolated normal at x turned to the viewer's side (material.glsl's
// rule: the geometric normal turned to the viewer decides).
vec3 lpvViewerSideNormal(vec3 x, vec3 vertexNormal, vec3 cameraPos) {
    vec3 ng = cross(dFdx(x), dFdy(x));
    if (dot(ng, cameraPos - x) < 0.0)
        ng = -ng;
    vec3 nv = normalize(vertexNormal);
    return dot(nv, ng) < 0.0 ? -nv : nv;
}

// The upsampled irradiance at x into e; false where no low-resolution
// neighbour lies on this surface, and e is then the plain bilinear mean of
// the neighbours that saw a surface (a stand-in, see lpv_lookup_resolve.frag).
// nv: lpvViewerSideNormal's.
bool lpvIrradianceUpsampled(vec3 x, vec3 nv, vec3 cameraPos, out vec3 e) {
    float d = length(cameraPos - x) * uLpvLowDistanceScale;
    // The distance changes this much across one low-resolution texel on this
    // surface (a plane seen at a grazing angle changes fast); plus 1% for
    // curvature and the half float's rounding.
    float perTexel = (abs(dFdx(d)) / uLpvLowScale.x + abs(dFdy(d)) / uLpvLowScale.y);
    float tolerance = 1.5 * perTexel + 0.01 * d;

    vec2 p = gl_FragCoord.xy * uLpvLowScale - 0.5;
    ivec2 i0 = ivec2(floor(p));
    vec2 f = p - vec2(i0);
    ivec2 last = textureSize(uLpvLowIrradiance, 0) - 1;
    vec3 sum = vec3(0.0), plainSum = vec3(0.0);
    float weights = 0.0, plainWeights = 0.0;
    for (int k = 0; k < 4; ++k) {
        ivec2 o = ivec2(k & 1, k >> 1);
        ivec2 texel = clamp(i0 + o, ivec2(0), last);
        vec4 low = texelFetch(uLpvLowIrradiance, texel, 0);
        vec3 lowNormal = texelFetch(uLpvLowNormal, texel, 0).xyz * 2.0 - 1.0;
        vec2 b = mix(1.0 - f, f, vec2(o));
        float depthWeight = low.a < 0.0 ? 0.0 : max(0.0, 1.0 - abs(low.a - d) / tolerance);
        float c = max(dot(lowNormal, nv), 0.0);
        c *= c;
        c *= c;
        float normalWeight = c * c;
        float w = b.x * b.y * depthWeight * normalWeight;
        sum += w * low.rgb;
        weights += w;
        float plain = low.a < 0.0 ? 0.0 : b.x * b.y + 1e-6;
        plainSum += plain * low.rgb;
        plainWeights += plain;
    }
    e = weights >= LPV_UPSAMPLE_MIN_WEIGHT ? sum / weights
        : plainWeights > 0.0                ? plainSum / plainWeights
                                            : vec3(0.0);
    return weights >= LPV_UPSAMPLE_MIN_WEIGHT;
}
