#include "lpv/scene/Light.h"
#include "lpv/scene/Material.h"

namespace lpv::scene {

const char* toString(ShadingModel m) { return m == ShadingModel::BlinnPhong ? "blinnPhong" : "metallicRoughness"; }

const char* toString(AlphaMode m) {
    switch (m) {
    case AlphaMode::Opaque: return "opaque";
    case AlphaMode::Mask: return "mask";
    case AlphaMode::Blend: return "blend";
    }
    return "opaque";
}

const char* toString(LightType t) {
    switch (t) {
    case LightType::Directional: return "directional";
    case LightType::Point: return "point";
    case LightType::Spot: return "spot";
    case LightType::Area: return "area";
    }
    return "directional";
}

const char* toString(AreaShape s) { return s == AreaShape::Disc ? "disc" : "rectangle"; }

std::optional<AreaShape> parseAreaShape(std::string_view s) {
    if (s == "rectangle") return AreaShape::Rectangle;
    if (s == "disc") return AreaShape::Disc;
    return std::nullopt;
}

const char* toString(AreaUnit u) { return u == AreaUnit::Power ? "power" : "radiance"; }

std::optional<AreaUnit> parseAreaUnit(std::string_view s) {
    if (s == "radiance") return AreaUnit::Radiance;
    if (s == "power") return AreaUnit::Power;
    return std::nullopt;
}

std::optional<ShadingModel> parseShadingModel(std::string_view s) {
    if (s == "blinnPhong") return ShadingModel::BlinnPhong;
    if (s == "metallicRoughness") return ShadingModel::MetallicRoughness;
    return std::nullopt;
}

std::optional<AlphaMode> parseAlphaMode(std::string_view s) {
    if (s == "opaque") return AlphaMode::Opaque;
    if (s == "mask") return AlphaMode::Mask;
    if (s == "blend") return AlphaMode::Blend;
    return std::nullopt;
}

std::optional<LightType> parseLightType(std::string_view s) {
    if (s == "directional") return LightType::Directional;
    if (s == "point") return LightType::Point;
    if (s == "spot") return LightType::Spot;
    if (s == "area") return LightType::Area;
    return std::nullopt;
}

} // namespace lpv::scene
