#pragma once
// Materials on the GPU: their constants and textures, bound per draw. Each
// pass asks only for what it reads (depth-only passes for nothing, shadow
// passes for coverage, the RSM for reflectance, shading for everything).
//
// Texture units: 8 base colour and 9 alpha map (shaders/coverage.glsl, every
// mode but DepthOnly); in Full mode also 10 normal, 11 specular,
// 12 metallic-roughness, 13 occlusion, 14 emissive (shaders/material.glsl);
// 15 is kept for the environment map, which nothing shades yet (so it is
// not uploaded). Units 0..7 are left to the passes' own inputs
// (shadow maps, RSM, LPV).
#include "scenegpu/TextureGpu.h"
#include "lpv/renderer/GlHandle.h"
#include "lpv/scene/Image.h"
#include "lpv/scene/Scene.h"

#include <cstdint>
#include <vector>

namespace lpv::renderer {

enum class MaterialBindMode {
    DepthOnly,   // nothing
    Coverage,    // alpha mask / colour key only, so masked leaves cast masked shadows
    Reflectance, // coverage + diffuse albedo (RSM flux)
    Full,        // everything forward shading reads
};

struct SamplerDeleter {
    void operator()(GLuint id) const { glDeleteSamplers(1, &id); }
};
using Sampler = GlHandle<SamplerDeleter>;

class MaterialGpu {
public:
    // Uploads every texture the materials use (each image once); a path
    // missing from `textures` draws as if the material had no such texture.
    MaterialGpu(const scene::Scene& scene, const scene::TextureImages& textures);
    ~MaterialGpu();
    MaterialGpu(const MaterialGpu&) = delete;
    MaterialGpu& operator=(const MaterialGpu&) = delete;

    // Sets the uniforms and texture units of `program` for `material`.
    void bind(GLuint program, std::uint32_t material, MaterialBindMode mode) const;

    // Blended materials that add to what is behind them instead of covering it.
    bool additive(std::uint32_t material) const;
    // Anisotropic filtering of all material textures (parameter output.anisotropy).
    void setAnisotropy(float samples) { textures_.setAnisotropy(samples); }
    // GL textures created (one per image and colour/data use).
    std::size_t textureCount() const { return textures_.uploadedCount(); }

    // The texture units (see the file comment).
    enum Unit : GLuint {
        kBaseColorUnit = 8,
        kAlphaUnit = 9,
        kNormalUnit = 10,
        kSpecularUnit = 11,
        kMetallicRoughnessUnit = 12,
        kOcclusionUnit = 13,
        kEmissiveUnit = 14,
    };

private:
    struct Textures {
        GLuint baseColor = 0, alpha = 0, normal = 0, specular = 0, metallicRoughness = 0, occlusion = 0,
               emissive = 0;
    };
    struct Locations;

    std::vector<scene::Material> materials_;
    std::vector<Textures> bound_;
    TextureCache textures_;
    // Coverage and reflectance (shadow maps, RSMs, the sky's height map)
    // sample trilinearly without anisotropic filtering: an alpha test or a
    // low-resolution flux gains nothing from it, and on llvmpipe it cost the
    // shadow pass about 4x (issue #25). Forward shading keeps the textures' own.
    Sampler coverageSampler_;
};

} // namespace lpv::renderer
