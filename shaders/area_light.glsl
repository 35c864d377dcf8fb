// Area lights' irradiance (include after common.glsl): the float twin of
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

// `lightDir`: the direction toward the visibleSum of the visible part of the
// light (a representative direction for the specular lobe and the shadow bias).
float areaLightFactor(vec3 center, vec3 normal, vec3 halfU, vec3 halfV, int shape, bool twoSided, vec3 p, vec3 n,
                      out vec3 lightDir) {
    lightDir = normalize(center - p);
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
    vec3 polygon[AREA_DISC_SIDES];
    int count = 4;
    if (shape == 1) {
        count = AREA_DISC_SIDES;
        for (int i = 0; i < AREA_DISC_SIDES; ++i) {
            float a = 2.0 * PI * float(i) / float(AREA_DISC_SIDES);
            polygon[i] = center + AREA_DISC_POLYGON_SCALE * (cos(a) * halfU + sin(a) * halfV);
        }
    } else {
        polygon[0] = center - halfU - halfV;
        polygon[1] = center + halfU - halfV;
        polygon[2] = center + halfU + halfV;
        polygon[3] = center - halfU + halfV;
    }
    // Sutherland-Hodgman against the shading point's tangent plane.
    vec3 clipped[AREA_MAX_VERTICES];
    int m = 0;
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
    vec3 visibleSum = vec3(0.0);
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
    vec3 toCentroid = visibleSum / float(m) - p;
    if (dot(toCentroid, toCentroid) > 0.0)
        lightDir = normalize(toCentroid);
    return abs(sum) * 0.5;
}
