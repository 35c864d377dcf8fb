// Area lights' irradiance (include after common.glsl and material.glsl): the float twin of
// scene/src/AreaLight.cpp areaLightIrradianceFactor, tested against it and
// against Lambert's formula (AreaLightTest, AreaLightGLTest).
//
// E = L * F, F = 1/2 * sum of theta_i (n . g_i) over the edges of the light's
// polygon clipped to the shading point's hemisphere: the diffuse term of
// Linearly Transformed Cosines with the identity transform (Heitz et al. 2016).
const int AREA_DISC_SIDES = 24; // scene::kAreaLightDiscSides
const int AREA_MAX_VERTICES = AREA_DISC_SIDES + 1;
// A disc's polygon has the disc's area: sqrt(2 pi / (N sin(2 pi / N))) for N = 24.
const float AREA_DISC_POLYGON_SCALE = 1.00574110;

// The light's outline: 4 corners or the disc's polygon (scene::areaLightPolygon).
int areaLightPolygon(vec3 center, vec3 halfU, vec3 halfV, int shape, out vec3 polygon[AREA_DISC_SIDES]) {
    if (shape == 1) {
        for (int i = 0; i < AREA_DISC_SIDES; ++i) {
            float a = 2.0 * PI * float(i) / float(AREA_DISC_SIDES);
            polygon[i] = center + AREA_DISC_POLYGON_SCALE * (cos(a) * halfU + sin(a) * halfV);
        }
        return AREA_DISC_SIDES;
    }
    polygon[0] = center - halfU - halfV;
    polygon[1] = center + halfU - halfV;
    polygon[2] = center + halfU + halfV;
    polygon[3] = center - halfU + halfV;
    for (int i = 4; i < AREA_DISC_SIDES; ++i)
        polygon[i] = vec3(0.0);
    return 4;
}

// Lambert's formula for the polygon clipped to the hemisphere around n at p
// (Sutherland-Hodgman, then the edge sum); `visibleSum` = the sum of the
// clipped vertices, `m` their count (0 when nothing is above the horizon).
float clippedLambert(vec3 polygon[AREA_DISC_SIDES], int count, vec3 p, vec3 n, out vec3 visibleSum, out int m) {
    vec3 clipped[AREA_MAX_VERTICES];
    m = 0;
    visibleSum = vec3(0.0);
    for (int i = 0; i < count; ++i) {
        vec3 a = polygon[i], b = polygon[(i + 1) % count];
        float da = dot(a - p, n), db = dot(b - p, n);
        if (da >= 0.0)
            clipped[m++] = a;
        if ((da >= 0.0) != (db >= 0.0))
            clipped[m++] = a + (b - a) * (da / (da - db));
    }
    if (m < 3)
        return 0.0;
    float sum = 0.0;
    for (int i = 0; i < m; ++i) {
        visibleSum += clipped[i];
        vec3 a = clipped[i] - p, b = clipped[(i + 1) % m] - p;
        float la = length(a), lb = length(b);
        if (la <= 0.0 || lb <= 0.0)
            continue; // on a vertex: that edge subtends nothing
        vec3 ua = a / la, ub = b / lb;
        vec3 c = cross(ua, ub);
        float s = length(c);
        if (s <= 0.0)
            continue; // on the edge's line
        sum += atan(s, dot(ua, ub)) * dot(c / s, n); // atan2 keeps small angles exact
    }
    return abs(sum) * 0.5;
}

// `lightDir`: the direction toward the centroid of the visible part of the
// light (a representative direction for the diffuse Fresnel weight and the
// shadow bias). `polygon` and `count` return the light's outline for
// areaLightSpecularFactor, so a fragment builds it once (count 0: the light
// is behind, or small enough to be a point).
float areaLightFactor(vec3 center, vec3 normal, vec3 halfU, vec3 halfV, int shape, bool twoSided, vec3 p, vec3 n,
                      out vec3 lightDir, out vec3 polygon[AREA_DISC_SIDES], out int count) {
    lightDir = normalize(center - p);
    count = 0;
    vec3 toPoint = p - center;
    float height = dot(toPoint, normal);
    if (!(height > 0.0) && !(twoSided && height < 0.0))
        return 0.0; // behind a one-sided light, or in its plane
    float dist = length(toPoint);
    float extent = length(halfU) + length(halfV);
    if (extent < 1e-3 * dist) {
        // A point of the light's area: A cos(light) cos(surface) / d^2.
        float area = shape == 1 ? PI * dot(halfU, halfU) : 4.0 * length(halfU) * length(halfV);
        return area * abs(height) / dist * max(dot(n, lightDir), 0.0) / (dist * dist);
    }
    count = areaLightPolygon(center, halfU, halfV, shape, polygon);
    vec3 visibleSum;
    int m;
    float factor = clippedLambert(polygon, count, p, n, visibleSum, m);
    if (m < 3)
        return 0.0;
    vec3 toCentroid = visibleSum / float(m) - p;
    if (dot(toCentroid, toCentroid) > 0.0)
        lightDir = normalize(toCentroid);
    return factor;
}

// --- The specular lobe: Linearly Transformed Cosines (Heitz et al. 2016) ---
// The float twin of scene::areaLightSpecularFactor (scene/LtcSpecular.h has
// the table's layout and the fit; AreaLightGLTest checks the two agree).
// The table is a shader storage buffer, not textures: the forward pass's 16
// fragment samplers are taken (shadow maps, material maps, LPV volumes). It
// is filtered here bilinearly, as the CPU twin filters it.
const int LTC_SIZE = 64;   // scene::kLtcTableSize
const int LTC_FLOATS = 6;  // scene::kLtcCellFloats
layout(std430, binding = 3) readonly buffer LtcGgxTable { float ltcTable[]; }; // ForwardRenderer kLtcTableBinding

void ltcCell(int t, int r, out vec4 m, out vec2 scale) {
    int i = (t * LTC_SIZE + r) * LTC_FLOATS;
    m = vec4(ltcTable[i], ltcTable[i + 1], ltcTable[i + 2], ltcTable[i + 3]);
    scale = vec2(ltcTable[i + 4], ltcTable[i + 5]);
}

// The table at (roughness, n.v): M^-1's entries (m00, m02, m20, m22) and (magnitude, fresnel).
void ltcLookup(float roughness, float nv, out vec4 m, out vec2 scale) {
    float s = clamp(roughness, 0.0, 1.0) * float(LTC_SIZE - 1);
    float t = sqrt(1.0 - clamp(nv, 0.0, 1.0)) * float(LTC_SIZE - 1);
    int r0 = int(floor(s)), t0 = int(floor(t));
    float fs = s - float(r0), ft = t - float(t0);
    int r1 = min(r0 + 1, LTC_SIZE - 1), t1 = min(t0 + 1, LTC_SIZE - 1);
    vec4 ma, mb, mc, md;
    vec2 sa, sb, sc, sd;
    ltcCell(t0, r0, ma, sa);
    ltcCell(t0, r1, mb, sb);
    ltcCell(t1, r0, mc, sc);
    ltcCell(t1, r1, md, sd);
    m = mix(mix(ma, mb, fs), mix(mc, md, fs), ft);
    scale = mix(mix(sa, sb, fs), mix(sc, sd, fs), ft);
}

// (x, y) such that the specular radiance is L * (F0 * x + (1 - F0) * y), for the
// GGX lobe of brdf.glsl at `roughness`; v = unit direction toward the viewer.
// Only for a point in front of the light (areaLightFactor > 0), with the
// outline areaLightFactor returned (count 0: the light is a point from p).
vec2 areaLightSpecularFactor(vec3 polygon[AREA_DISC_SIDES], int count, vec3 center, vec3 normal, vec3 halfU,
                             vec3 halfV, int shape, vec3 p, vec3 n, vec3 v, float roughness) {
    vec3 toPoint = p - center;
    float height = dot(toPoint, normal);
    float nv = dot(n, v);
    vec4 m;
    vec2 scale;
    ltcLookup(roughness, nv, m, scale);
    // The fit's frame: v in the x-z plane on the +x side (any tangent when v is along n).
    vec3 t1 = v - n * nv;
    if (dot(t1, t1) > 1e-12)
        t1 = normalize(t1);
    else
        t1 = normalize(cross(abs(n.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0), n));
    vec3 t2 = cross(n, t1);
    mat3 toLobe = mat3(vec3(m.x, 0.0, m.z), vec3(0.0, 1.0, 0.0), vec3(m.y, 0.0, m.w)) * transpose(mat3(t1, t2, n));
    float dist = length(toPoint);
    float integral;
    if (count == 0) {
        // A point of the light's area: the LTC's density toward it times its solid angle.
        float area = shape == 1 ? PI * dot(halfU, halfU) : 4.0 * length(halfU) * length(halfV);
        vec3 o = toLobe * (-toPoint / dist);
        float len = length(o);
        float density = len > 0.0 ? max(o.z / len, 0.0) / PI * abs(determinant(toLobe)) / (len * len * len) : 0.0;
        integral = density * area * abs(height) / dist / (dist * dist);
    } else {
        vec3 lobe[AREA_DISC_SIDES];
        for (int i = 0; i < AREA_DISC_SIDES; ++i)
            lobe[i] = toLobe * (polygon[i] - p);
        vec3 visibleSum;
        int visible;
        integral = clippedLambert(lobe, count, vec3(0.0), vec3(0.0, 0.0, 1.0), visibleSum, visible) / PI;
    }
    return scale * integral;
}


// An area light's reflected radiance over its radiance L (area_light.glsl):
// the diffuse term from the exact irradiance factor, the specular lobe by
// Linearly Transformed Cosines over the light's polygon. `l` points to the
// visible part's centroid: the diffuse term's Fresnel weight (glTF) is
// evaluated there. Blinn-Phong's lobe is taken as the GGX lobe of the same
// width (alpha^2 = 2 / (shininess + 2), Walter et al. 2007) without Fresnel,
// its specular colour as the scale; metallic-roughness uses Schlick's F0.
vec3 areaLightReflectance(Surface s, vec3 l, vec3 v, float diffuseFactor, vec3 polygon[AREA_DISC_SIDES], int count,
                          vec3 center, vec3 normal, vec3 halfU, vec3 halfV, int shape, vec3 p) {
    if (uShadingModel == 1) {
        vec3 f0 = mix(vec3(0.04), s.albedo, s.metallic);
        float vh = max(dot(v, normalize(l + v)), 0.0);
        vec3 F = f0 + (1.0 - f0) * pow(1.0 - vh, 5.0);
        vec3 diffuse = (1.0 - F) * (1.0 - s.metallic) * s.albedo / PI * diffuseFactor;
        vec2 spec = areaLightSpecularFactor(polygon, count, center, normal, halfU, halfV, shape, p, s.normal, v,
                                            s.roughness);
        return diffuse + f0 * spec.x + (1.0 - f0) * spec.y;
    }
    vec3 diffuse = s.albedo / PI * diffuseFactor;
    if (max(s.specular.r, max(s.specular.g, s.specular.b)) <= 0.0)
        return diffuse;
    float roughness = sqrt(sqrt(2.0 / (max(s.shininess, 0.0) + 2.0)));
    vec2 spec = areaLightSpecularFactor(polygon, count, center, normal, halfU, halfV, shape, p, s.normal, v,
                                        roughness);
    return diffuse + s.specular * spec.x;
}
