#pragma once
#include <glm/glm.hpp>

#include <optional>
#include <string>
#include <string_view>

namespace lpv::scene {

enum class LightType { Directional, Point, Spot };
const char* toString(LightType t);
std::optional<LightType> parseLightType(std::string_view s);

// Units: a directional light's intensity is irradiance (W/m^2) on a surface
// facing it; point and spot intensities are radiant intensity (W/sr).
struct Light {
    std::string name;
    LightType type = LightType::Directional;
    glm::vec3 color{1.0f};
    float intensity = 1.0f;
    glm::vec3 position{0.0f};
    glm::vec3 direction{0.0f, -1.0f, 0.0f}; // direction the light travels
    float range = 0.0f;                     // 0 = unlimited
    float innerConeAngle = 0.0f;            // radians, spot only
    float outerConeAngle = 0.7853982f;      // radians, spot only
    bool castShadows = true;

    bool operator==(const Light&) const = default;
};

} // namespace lpv::scene
