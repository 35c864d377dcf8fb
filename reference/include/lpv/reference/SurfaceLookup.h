#pragma once
// What the path tracer reads from a material at a hit: diffuse albedo
// (colour times the sRGB-decoded base-colour texture), coverage for alpha
// masks, emission, and the Blinn-Phong / metallic-roughness terms the
// renderer's direct light uses (shaders/coverage.glsl, material.glsl).
#include "lpv/scene/Image.h"
#include "lpv/scene/Material.h"

#include <glm/glm.hpp>

#include <vector>

namespace lpv::reference {

// A texture decoded once into linear floats (sRGB colour maps) so lookups are cheap.
struct LinearTexture {
    int width = 0;
    int height = 0;
    std::vector<glm::vec4> texels; // rows top to bottom, like Image8

    bool empty() const { return texels.empty(); }
    // Bilinear, repeat wrap; uv (0, 0) is the bottom-left corner (scene/Mesh.h).
    glm::vec4 sample(glm::vec2 uv) const;
};

LinearTexture decodeTexture(const scene::Image8& image, bool srgb);

struct MaterialTextures {
    LinearTexture baseColor; // linear rgb, a = alpha
    LinearTexture alpha;     // red = alpha
    LinearTexture emissive;  // linear rgb
    LinearTexture specular;  // linear rgb
};

// The same keys the renderer's MaterialGpu uses (colour-keyed maps under "#colorkey").
MaterialTextures lookUpTextures(const scene::Material& m, const scene::TextureImages& images);

struct SurfaceSample {
    glm::vec3 albedo{0.8f};  // diffuse albedo (base colour for metallic-roughness)
    glm::vec3 diffuse{0.8f}; // what a diffuse bounce reflects: albedo, times 1 - metallic for glTF
    glm::vec3 emissive{0.0f};
    glm::vec3 specular{0.0f};
    float shininess = 32.0f;
    float metallic = 0.0f;
    float roughness = 1.0f;
    bool metallicRoughness = false;
};

float materialCoverage(const scene::Material& m, const MaterialTextures& t, glm::vec2 uv);
// True where the renderer would discard (masked) or the surface lets light through (blend below half,
// additive).
bool materialCutOut(const scene::Material& m, const MaterialTextures& t, glm::vec2 uv);
SurfaceSample materialSurface(const scene::Material& m, const MaterialTextures& t, glm::vec2 uv);

// f(l, v) of brdf.glsl: the renderer's direct-light BRDF, so direct light agrees.
glm::vec3 surfaceBrdf(const SurfaceSample& s, const glm::vec3& n, const glm::vec3& l, const glm::vec3& v);

} // namespace lpv::reference
