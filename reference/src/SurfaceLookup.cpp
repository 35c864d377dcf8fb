#include "lpv/reference/SurfaceLookup.h"

#include <algorithm>
#include <cmath>

namespace lpv::reference {

namespace {

constexpr float kPi = 3.14159265358979f;

float srgbToLinear(float c) {
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

int wrap(int i, int n) {
    const int m = i % n;
    return m < 0 ? m + n : m;
}

const scene::Image8* find(const scene::TextureImages& images, const std::string& key) {
    if (key.empty())
        return nullptr;
    auto it = images.find(key);
    return it == images.end() ? nullptr : &it->second;
}

LinearTexture decodeIf(const scene::TextureImages& images, const std::string& key, bool srgb) {
    const scene::Image8* image = find(images, key);
    return image ? decodeTexture(*image, srgb) : LinearTexture{};
}

} // namespace

glm::vec4 LinearTexture::sample(glm::vec2 uv) const {
    // Texel centres at (i + 0.5) / width; v = 0 is the bottom row, stored last.
    const float x = uv.x * float(width) - 0.5f;
    const float y = (1.0f - uv.y) * float(height) - 0.5f;
    const float fx = std::floor(x), fy = std::floor(y);
    const float ax = x - fx, ay = y - fy;
    const int x0 = wrap(int(fx), width), x1 = wrap(int(fx) + 1, width);
    const int y0 = wrap(int(fy), height), y1 = wrap(int(fy) + 1, height);
    auto at = [&](int xi, int yi) { return texels[std::size_t(yi) * std::size_t(width) + std::size_t(xi)]; };
    return glm::mix(glm::mix(at(x0, y0), at(x1, y0), ax), glm::mix(at(x0, y1), at(x1, y1), ax), ay);
}

LinearTexture decodeTexture(const scene::Image8& image, bool srgb) {
    LinearTexture t;
    if (image.width <= 0 || image.height <= 0 || image.channels <= 0 ||
        image.pixels.size() <
            std::size_t(image.width) * std::size_t(image.height) * std::size_t(image.channels))
        return t;
    t.width = image.width;
    t.height = image.height;
    t.texels.resize(std::size_t(image.width) * std::size_t(image.height));
    float table[256];
    for (int i = 0; i < 256; ++i)
        table[i] = srgb ? srgbToLinear(float(i) / 255.0f) : float(i) / 255.0f;
    const int c = image.channels;
    for (std::size_t p = 0; p < t.texels.size(); ++p) {
        const std::uint8_t* px = &image.pixels[p * std::size_t(c)];
        glm::vec4 v{0.0f, 0.0f, 0.0f, 1.0f};
        if (c >= 3) {
            v = {table[px[0]], table[px[1]], table[px[2]], c >= 4 ? float(px[3]) / 255.0f : 1.0f};
        } else {
            v = glm::vec4(glm::vec3(table[px[0]]), c == 2 ? float(px[1]) / 255.0f : 1.0f);
        }
        t.texels[p] = v;
    }
    return t;
}

MaterialTextures lookUpTextures(const scene::Material& m, const scene::TextureImages& images) {
    MaterialTextures t;
    if (!m.diffuseTexture.empty())
        t.baseColor =
            decodeIf(images, m.colorKey ? m.diffuseTexture + scene::kColorKeySuffix : m.diffuseTexture, true);
    t.alpha = decodeIf(images, m.alphaTexture, false);
    t.emissive = decodeIf(images, m.emissiveTexture, true);
    t.specular = decodeIf(images, m.specularTexture, true);
    return t;
}

float materialCoverage(const scene::Material& m, const MaterialTextures& t, glm::vec2 uv) {
    // coverage.glsl: an opaque material with a colour key or alpha map is drawn masked (MaterialGpu).
    const bool masked = m.alphaMode != scene::AlphaMode::Opaque || m.colorKey || !m.alphaTexture.empty();
    if (!masked)
        return 1.0f;
    float a = m.opacity;
    if (!t.baseColor.empty())
        a *= t.baseColor.sample(uv).a;
    if (!t.alpha.empty())
        a *= t.alpha.sample(uv).r;
    return a;
}

bool materialCutOut(const scene::Material& m, const MaterialTextures& t, glm::vec2 uv) {
    // Additive glows add light in front of what is behind and reflect nothing.
    if (m.additive)
        return true;
    const float coverage = materialCoverage(m, t, uv);
    if (m.alphaMode == scene::AlphaMode::Blend)
        return coverage < 0.5f; // a path tracer has no "half a surface"; the renderer blends
    return coverage < m.alphaCutoff;
}

SurfaceSample materialSurface(const scene::Material& m, const MaterialTextures& t, glm::vec2 uv) {
    SurfaceSample s;
    s.albedo = m.diffuseColor;
    if (!t.baseColor.empty())
        s.albedo *= glm::vec3(t.baseColor.sample(uv));
    s.metallicRoughness = m.shading == scene::ShadingModel::MetallicRoughness;
    s.metallic = m.metallic;
    s.roughness = m.roughness;
    s.diffuse = s.metallicRoughness ? s.albedo * (1.0f - s.metallic) : s.albedo;
    s.emissive = m.emissive;
    if (!t.emissive.empty())
        s.emissive *= glm::vec3(t.emissive.sample(uv));
    s.specular = m.specularColor;
    if (!t.specular.empty())
        s.specular *= glm::vec3(t.specular.sample(uv));
    s.shininess = std::max(m.shininess, 1.0f); // as MaterialGpu binds it
    return s;
}

glm::vec3 surfaceBrdf(const SurfaceSample& s, const glm::vec3& n, const glm::vec3& l, const glm::vec3& v) {
    const glm::vec3 h = glm::normalize(l + v);
    if (!s.metallicRoughness) {
        const float spec =
            (s.shininess + 8.0f) / (8.0f * kPi) * std::pow(std::max(glm::dot(n, h), 0.0f), s.shininess);
        return s.albedo / kPi + s.specular * spec;
    }
    const float alpha = std::max(s.roughness * s.roughness, 1e-3f);
    const float a2 = alpha * alpha;
    const float nl = std::max(glm::dot(n, l), 1e-4f);
    const float nv = std::max(glm::dot(n, v), 1e-4f);
    const float nh = std::max(glm::dot(n, h), 0.0f);
    const float vh = std::max(glm::dot(v, h), 0.0f);
    const float dDenom = nh * nh * (a2 - 1.0f) + 1.0f;
    const float D = a2 / (kPi * dDenom * dDenom);
    const float V =
        0.5f / (nl * std::sqrt(nv * nv * (1.0f - a2) + a2) + nv * std::sqrt(nl * nl * (1.0f - a2) + a2));
    const glm::vec3 f0 = glm::mix(glm::vec3(0.04f), s.albedo, s.metallic);
    const glm::vec3 F = f0 + (1.0f - f0) * std::pow(1.0f - vh, 5.0f);
    const glm::vec3 diffuse = (1.0f - F) * (1.0f - s.metallic) * s.albedo / kPi;
    return diffuse + F * (D * V);
}

} // namespace lpv::reference
