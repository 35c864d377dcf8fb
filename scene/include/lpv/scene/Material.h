#pragma once
#include <glm/glm.hpp>

#include <optional>
#include <string>
#include <string_view>

namespace lpv::scene {

enum class ShadingModel { BlinnPhong, MetallicRoughness };
enum class AlphaMode { Opaque, Mask, Blend };

const char* toString(ShadingModel m);
const char* toString(AlphaMode m);
std::optional<ShadingModel> parseShadingModel(std::string_view s);
std::optional<AlphaMode> parseAlphaMode(std::string_view s);

// Texture fields are paths relative to the project file (empty = none).
struct Material {
    std::string name;
    ShadingModel shading = ShadingModel::BlinnPhong;

    glm::vec3 diffuseColor{0.8f};
    std::string diffuseTexture;
    std::string normalTexture;
    std::string heightTexture; // bump map, turned into normals by the renderer

    // Blinn-Phong
    glm::vec3 specularColor{0.0f};
    std::string specularTexture;
    float shininess = 32.0f;

    // Metallic-roughness (glTF)
    float metallic = 0.0f;
    float roughness = 1.0f;
    std::string metallicRoughnessTexture;
    std::string occlusionTexture;

    glm::vec3 emissive{0.0f};
    std::string emissiveTexture;

    float opacity = 1.0f;
    AlphaMode alphaMode = AlphaMode::Opaque;
    // A separate coverage map (4ds alpha map, OBJ map_d); its red channel is alpha.
    std::string alphaTexture;
    // The first palette colour (8-bit maps) or black (others) of the diffuse
    // map becomes transparent when the map is loaded (4ds COLOR_KEY).
    bool colorKey = false;
    // Blended by adding to what is behind (4ds ADDITIVE: glows, flares).
    bool additive = false;
    // A reflection texture (4ds environment map) mixed in by environmentRatio.
    std::string environmentTexture;
    float environmentRatio = 0.0f;
    float alphaCutoff = 0.5f;
    // Fraction of light that passes through the surface (subsurface LPV).
    float translucency = 0.0f;
    // 0 = diffuse, 1 = mirror (glossy LPV reflections).
    float glossiness = 0.0f;
    bool twoSided = false;

    bool operator==(const Material&) const = default;
};

} // namespace lpv::scene
