// Everything forward shading reads from a material beyond coverage.glsl
// (include that first): MaterialGpu::bind sets these in Full mode.
// Texture units: normal 10, specular 11, metallic-roughness 12, occlusion 13, emissive 14.
uniform int uShadingModel;              // 0 Blinn-Phong, 1 glTF metallic-roughness
uniform vec3 uSpecular;                 // Blinn-Phong specular colour, linear
uniform float uShininess;
uniform bool uHasSpecularMap;
uniform sampler2D uSpecularMap;         // sRGB colour, multiplies uSpecular
uniform float uMetallic;
uniform float uRoughness;
uniform bool uHasMetallicRoughnessMap;
uniform sampler2D uMetallicRoughnessMap; // glTF: B = metallic, G = roughness (linear)
uniform bool uHasOcclusionMap;
uniform sampler2D uOcclusionMap;        // R = ambient occlusion (linear)
uniform vec3 uEmissive;                 // emitted radiance
uniform bool uHasEmissiveMap;
uniform sampler2D uEmissiveMap;         // sRGB colour, multiplies uEmissive
uniform bool uHasNormalMap;
uniform sampler2D uNormalMap;           // tangent space, +Y = +v (OpenGL/glTF convention); also height-derived maps

struct Surface {
    vec3 normal;     // shading normal (after normal mapping), world space, facing the viewer for two-sided materials
    vec3 albedo;     // diffuse albedo (Blinn-Phong) or base colour (metallic-roughness), linear
    vec3 specular;   // Blinn-Phong
    float shininess; // Blinn-Phong
    float metallic;
    float roughness;
    float occlusion; // for indirect light only (glTF): direct light has its own shadows
    vec3 emissive;
};

// Tangent frame from screen-space derivatives, for meshes without tangents
// (Schüler, "Normal mapping without precomputed tangents").
mat3 derivativeTangentFrame(vec3 n, vec3 p, vec2 uv) {
    vec3 dp1 = dFdx(p), dp2 = dFdy(p);
    vec2 duv1 = dFdx(uv), duv2 = dFdy(uv);
    vec3 dp2perp = cross(dp2, n), dp1perp = cross(n, dp1);
    vec3 t = dp2perp * duv1.x + dp1perp * duv2.x;
    vec3 b = dp2perp * duv1.y + dp1perp * duv2.y;
    float invmax = inversesqrt(max(max(dot(t, t), dot(b, b)), 1e-20));
    return mat3(t * invmax, b * invmax, n);
}

// `n` the interpolated world normal, `tangent` the world tangent with the
// handedness in w (bitangent = w * cross(n, t)); `backFacing` flips the frame
// of faces seen from behind.
vec3 materialNormal(vec3 n, vec4 tangent, vec2 uv, vec3 worldPos, bool backFacing) {
    n = normalize(n);
    if (backFacing) {
        n = -n;
        tangent.xyz = -tangent.xyz;
    }
    if (!uHasNormalMap)
        return n;
    vec3 tn = texture(uNormalMap, uv).xyz * 2.0 - 1.0;
    mat3 tbn;
    if (dot(tangent.xyz, tangent.xyz) < 1e-12) {
        tbn = derivativeTangentFrame(n, worldPos, uv);
    } else {
        // Gram-Schmidt: interpolation leaves t slightly off perpendicular to n.
        vec3 t = normalize(tangent.xyz - n * dot(n, tangent.xyz));
        vec3 b = (tangent.w < 0.0 ? -1.0 : 1.0) * cross(n, t);
        tbn = mat3(t, b, n);
    }
    vec3 mapped = tbn * tn;
    return dot(mapped, mapped) > 1e-12 ? normalize(mapped) : n;
}

Surface materialSurface(vec3 n, vec4 tangent, vec2 uv, vec3 worldPos, vec3 toViewer) {
    Surface s;
    // Every face is shaded on the side it is seen from, as the RSM and the
    // reference path tracer do: the renderer draws without culling, and a
    // one-sided wall seen from inside must not take the sun that falls on its
    // outside. The geometric normal decides (winding-independent, as Embree's Ng).
    vec3 ng = cross(dFdx(worldPos), dFdy(worldPos));
    if (dot(ng, toViewer) < 0.0)
        ng = -ng;
    bool backFacing = dot(n, ng) < 0.0;
    s.normal = materialNormal(n, tangent, uv, worldPos, backFacing);
    s.albedo = materialAlbedo(uv);
    s.specular = uSpecular;
    if (uHasSpecularMap)
        s.specular *= texture(uSpecularMap, uv).rgb;
    s.shininess = uShininess;
    s.metallic = uMetallic;
    s.roughness = uRoughness;
    if (uHasMetallicRoughnessMap) {
        vec4 mr = texture(uMetallicRoughnessMap, uv);
        s.metallic *= mr.b;
        s.roughness *= mr.g;
    }
    s.occlusion = uHasOcclusionMap ? texture(uOcclusionMap, uv).r : 1.0;
    s.emissive = uEmissive;
    if (uHasEmissiveMap)
        s.emissive *= texture(uEmissiveMap, uv).rgb;
    return s;
}

vec3 surfaceBrdf(Surface s, vec3 l, vec3 v) {
    if (uShadingModel == 1)
        return metallicRoughnessBrdf(s.albedo, s.metallic, s.roughness, s.normal, l, v);
    return blinnPhongBrdf(s.albedo, s.specular, s.shininess, s.normal, l, v);
}
