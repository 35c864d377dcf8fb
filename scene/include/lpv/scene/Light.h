#pragma once
#include <glm/glm.hpp>

#include <optional>
#include <string>
#include <string_view>

namespace lpv::scene {

enum class LightType { Directional, Point, Spot, Area };
const char* toString(LightType t);
std::optional<LightType> parseLightType(std::string_view s);

// An area light's outline (AreaLight.h has its geometry).
enum class AreaShape { Rectangle, Disc };
const char* toString(AreaShape s);
std::optional<AreaShape> parseAreaShape(std::string_view s);

// What an area light's `intensity` measures.
enum class AreaUnit {
    Radiance, // W/(m^2 sr): the radiance leaving the emitting side
    Power,    // W: the flux it emits in all, over every emitting side
};
const char* toString(AreaUnit u);
std::optional<AreaUnit> parseAreaUnit(std::string_view s);

// Units: a directional light's intensity is irradiance (W/m^2) on a surface
// facing it; point and spot intensities are radiant intensity (W/sr); an area
// light's is radiance or power (`unit`).
//
// An area light is a flat Lambertian emitter centred on `position` that emits
// toward `direction` (its front normal) only, unless `twoSided`. A rectangle
// is `size.x` wide along `tangent` (made orthogonal to `direction`) and
// `size.y` high along direction x tangent; a disc has `radius`.
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
    // --- area lights only ---
    AreaShape shape = AreaShape::Rectangle;
    glm::vec2 size{1.0f, 1.0f};             // rectangle: width, height (m)
    float radius = 0.5f;                    // disc (m)
    glm::vec3 tangent{1.0f, 0.0f, 0.0f};    // the rectangle's width axis
    bool twoSided = false;
    AreaUnit unit = AreaUnit::Radiance;

    bool operator==(const Light&) const = default;
};

} // namespace lpv::scene
