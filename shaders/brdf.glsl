// Reflectance models for direct light. Each returns the BRDF f(l, v); the
// caller multiplies by irradiance * max(n.l, 0). Needs common.glsl (PI).

// Lambert diffuse + normalised Blinn-Phong specular: the (s + 8) / (8 PI)
// factor keeps the lobe's energy constant as the shininess s grows.
vec3 blinnPhongBrdf(vec3 albedo, vec3 specular, float shininess, vec3 n, vec3 l, vec3 v) {
    vec3 h = normalize(l + v);
    float spec = (shininess + 8.0) / (8.0 * PI) * pow(max(dot(n, h), 0.0), shininess);
    return albedo / PI + specular * spec;
}

// glTF 2.0 metallic-roughness: GGX distribution, height-correlated Smith
// visibility, Schlick Fresnel; dielectrics reflect 4% at normal incidence,
// metals tint their reflection with the base colour and have no diffuse term.
vec3 metallicRoughnessBrdf(vec3 baseColor, float metallic, float roughness, vec3 n, vec3 l, vec3 v) {
    // Roughness below ~0.03 turns a punctual light's highlight into a sub-pixel spike.
    float alpha = max(roughness * roughness, 1e-3);
    float a2 = alpha * alpha;
    vec3 h = normalize(l + v);
    float nl = max(dot(n, l), 1e-4);
    float nv = max(dot(n, v), 1e-4);
    float nh = max(dot(n, h), 0.0);
    float vh = max(dot(v, h), 0.0);
    float dDenom = nh * nh * (a2 - 1.0) + 1.0;
    float D = a2 / (PI * dDenom * dDenom);
    float V = 0.5 / (nl * sqrt(nv * nv * (1.0 - a2) + a2) + nv * sqrt(nl * nl * (1.0 - a2) + a2));
    vec3 f0 = mix(vec3(0.04), baseColor, metallic);
    vec3 F = f0 + (1.0 - f0) * pow(1.0 - vh, 5.0);
    vec3 diffuse = (1.0 - F) * (1.0 - metallic) * baseColor / PI;
    return diffuse + F * (D * V);
}
