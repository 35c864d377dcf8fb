#include "scenegpu/MaterialGpu.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>

namespace lpv::renderer {

struct MaterialGpu::Locations {
    explicit Locations(GLuint p) {
        auto at = [&](const char* name) { return glGetUniformLocation(p, name); };
        diffuse = at("uDiffuse");
        hasBaseColorMap = at("uHasBaseColorMap");
        baseColorMap = at("uBaseColorMap");
        hasAlphaMap = at("uHasAlphaMap");
        alphaMap = at("uAlphaMap");
        alphaMode = at("uAlphaMode");
        alphaCutoff = at("uAlphaCutoff");
        opacity = at("uOpacity");
        translucency = at("uTranslucency");
        shadingModel = at("uShadingModel");
        specular = at("uSpecular");
        shininess = at("uShininess");
        hasSpecularMap = at("uHasSpecularMap");
        specularMap = at("uSpecularMap");
        metallic = at("uMetallic");
        roughness = at("uRoughness");
        hasMetallicRoughnessMap = at("uHasMetallicRoughnessMap");
        metallicRoughnessMap = at("uMetallicRoughnessMap");
        hasOcclusionMap = at("uHasOcclusionMap");
        occlusionMap = at("uOcclusionMap");
        emissive = at("uEmissive");
        hasEmissiveMap = at("uHasEmissiveMap");
        emissiveMap = at("uEmissiveMap");
        hasNormalMap = at("uHasNormalMap");
        normalMap = at("uNormalMap");
    }
    GLint diffuse, hasBaseColorMap, baseColorMap, hasAlphaMap, alphaMap, alphaMode, alphaCutoff, opacity, translucency;
    GLint shadingModel, specular, shininess, hasSpecularMap, specularMap, metallic, roughness,
        hasMetallicRoughnessMap, metallicRoughnessMap, hasOcclusionMap, occlusionMap, emissive, hasEmissiveMap,
        emissiveMap, hasNormalMap, normalMap;
};

MaterialGpu::MaterialGpu(const scene::Scene& scene, const scene::TextureImages& images) : materials_(scene.materials) {
    GLuint sampler = 0;
    glCreateSamplers(1, &sampler);
    coverageSampler_ = Sampler(sampler);
    glSamplerParameteri(sampler, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glSamplerParameteri(sampler, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glSamplerParameteri(sampler, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glSamplerParameteri(sampler, GL_TEXTURE_WRAP_T, GL_REPEAT);
    if (maxSupportedAnisotropy() > 1.0f)
        glSamplerParameterf(sampler, 0x84FE /* GL_TEXTURE_MAX_ANISOTROPY */, 1.0f);
    bound_.reserve(materials_.size());
    for (const scene::Material& m : materials_) {
        auto get = [&](const std::string& key, TextureUsage usage) { return textures_.get(images, key, usage); };
        Textures t;
        // A colour-keyed map has its own keyed copy (see scene/Image.h).
        if (m.colorKey && !m.diffuseTexture.empty())
            t.baseColor = get(m.diffuseTexture + scene::kColorKeySuffix, TextureUsage::Color);
        if (!t.baseColor)
            t.baseColor = get(m.diffuseTexture, TextureUsage::Color);
        t.alpha = get(m.alphaTexture, TextureUsage::Data);
        // A real normal map wins over one derived from a height map.
        t.normal = get(m.normalTexture, TextureUsage::Data);
        if (!t.normal && !m.heightTexture.empty())
            t.normal = get(m.heightTexture + scene::kHeightNormalSuffix, TextureUsage::Data);
        t.specular = get(m.specularTexture, TextureUsage::Color);
        t.metallicRoughness = get(m.metallicRoughnessTexture, TextureUsage::Data);
        t.occlusion = get(m.occlusionTexture, TextureUsage::Data);
        t.emissive = get(m.emissiveTexture, TextureUsage::Color);
        bound_.push_back(t);
    }
}

MaterialGpu::~MaterialGpu() = default;

bool MaterialGpu::additive(std::uint32_t material) const {
    return material < materials_.size() && materials_[material].additive;
}

void MaterialGpu::bind(GLuint program, std::uint32_t material, MaterialBindMode mode) const {
    if (mode == MaterialBindMode::DepthOnly)
        return;
    const bool known = material < materials_.size();
    const scene::Material m = known ? materials_[material] : scene::Material{};
    const Textures t = known ? bound_[material] : Textures{};
    // Looked up per bind (a few dozen hash lookups per material change): a
    // cache keyed by program id could outlive a program whose id GL reuses.
    const Locations l(program);
    // A texture unit and the flag that says whether to sample it. Sampler
    // uniforms are always set: left at unit 0 they would alias a shadow sampler.
    auto texture = [&](GLint hasLoc, GLint samplerLoc, Unit unit, GLuint id) {
        glProgramUniform1i(program, samplerLoc, GLint(unit));
        glProgramUniform1i(program, hasLoc, id != 0 ? 1 : 0);
        if (id != 0)
            glBindTextureUnit(unit, id);
    };

    // Coverage (shaders/coverage.glsl): every mode from here on.
    const GLuint sampler = mode == MaterialBindMode::Full ? 0 : coverageSampler_.id();
    glBindSampler(kBaseColorUnit, sampler);
    glBindSampler(kAlphaUnit, sampler);
    glProgramUniform3fv(program, l.diffuse, 1, glm::value_ptr(m.diffuseColor));
    texture(l.hasBaseColorMap, l.baseColorMap, kBaseColorUnit, t.baseColor);
    texture(l.hasAlphaMap, l.alphaMap, kAlphaUnit, t.alpha);
    // Colour-keyed and alpha-mapped materials import as Mask or Blend; an
    // opaque material with only a colour key still needs its cut-outs.
    int alphaMode = int(m.alphaMode);
    if (m.alphaMode == scene::AlphaMode::Opaque && (m.colorKey || t.alpha))
        alphaMode = int(scene::AlphaMode::Mask);
    glProgramUniform1i(program, l.alphaMode, alphaMode);
    glProgramUniform1f(program, l.alphaCutoff, m.alphaCutoff);
    glProgramUniform1f(program, l.opacity, m.opacity);
    glProgramUniform1f(program, l.translucency, std::clamp(m.translucency, 0.0f, 1.0f));
    if (mode != MaterialBindMode::Full)
        return;

    // Shading (shaders/material.glsl).
    glProgramUniform1i(program, l.shadingModel, m.shading == scene::ShadingModel::MetallicRoughness ? 1 : 0);
    glProgramUniform3fv(program, l.specular, 1, glm::value_ptr(m.specularColor));
    glProgramUniform1f(program, l.shininess, std::max(m.shininess, 1.0f));
    texture(l.hasSpecularMap, l.specularMap, kSpecularUnit, t.specular);
    glProgramUniform1f(program, l.metallic, std::clamp(m.metallic, 0.0f, 1.0f));
    glProgramUniform1f(program, l.roughness, std::clamp(m.roughness, 0.0f, 1.0f));
    texture(l.hasMetallicRoughnessMap, l.metallicRoughnessMap, kMetallicRoughnessUnit, t.metallicRoughness);
    texture(l.hasOcclusionMap, l.occlusionMap, kOcclusionUnit, t.occlusion);
    glProgramUniform3fv(program, l.emissive, 1, glm::value_ptr(m.emissive));
    texture(l.hasEmissiveMap, l.emissiveMap, kEmissiveUnit, t.emissive);
    texture(l.hasNormalMap, l.normalMap, kNormalUnit, t.normal);
    // Glossy LPV reflections (shaders/lpv_glossy.glsl); a program without them ignores location -1.
    glProgramUniform1f(program, glGetUniformLocation(program, "uGlossiness"),
                       std::clamp(m.glossiness, 0.0f, 1.0f));
}

} // namespace lpv::renderer
