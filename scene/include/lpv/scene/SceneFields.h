#pragma once
// The field tables of the scene structs (SceneField.h says what a field
// declares and who reads it). A table lists its fields in the order a
// project file writes them (docs/project-format.md). To add a field: add the
// member to its struct and one entry here; the reader, writer, hashes, fuzz
// checks and docs follow, and SceneFieldsTest walks it.
//
// Rules that tie fields together (a spot's inner cone within its outer one,
// the far plane beyond the near one) are declared below the tables, beside
// them, not in the reader or the editor.
#include "lpv/scene/Camera.h"
#include "lpv/scene/Light.h"
#include "lpv/scene/Material.h"
#include "lpv/scene/Scene.h"
#include "lpv/scene/SceneField.h"
#include "lpv/scene/ValueChecks.h"

#include <numbers>
#include <optional>
#include <string>
#include <string_view>

namespace lpv::scene {

// --- enums ----------------------------------------------------------------

template <>
inline constexpr EnumNames<LightType> kEnumNames<LightType>{"directional, point, spot, area", parseLightType};
template <> inline constexpr EnumNames<AreaShape> kEnumNames<AreaShape>{"rectangle, disc", parseAreaShape};
template <> inline constexpr EnumNames<AreaUnit> kEnumNames<AreaUnit>{"radiance, power", parseAreaUnit};
template <>
inline constexpr EnumNames<ShadingModel> kEnumNames<ShadingModel>{"blinnPhong, metallicRoughness",
                                                                  parseShadingModel};
template <>
inline constexpr EnumNames<AlphaMode> kEnumNames<AlphaMode>{"opaque, mask, blend", parseAlphaMode};

namespace fields {

inline constexpr double kHalfPi = std::numbers::pi / 2;
// Spin boxes need finite ends: a million metres is large enough for any
// scene in metres, small enough that a stray wheel turn stays visible.
inline constexpr FieldRange kEditCoordinate{-1.0e6, 1.0e6};
inline constexpr FieldRange kEditLength{1.0e-6, 1.0e6};
inline constexpr FieldRange kEditRadiometric{0.0, 1.0e6};

inline bool isArea(const Light& l) {
    return l.type == LightType::Area;
}
inline bool isRectangle(const Light& l) {
    return l.shape == AreaShape::Rectangle;
}
inline bool isDisc(const Light& l) {
    return l.shape == AreaShape::Disc;
}
inline bool hasLods(const Object& o) {
    return !o.lods.empty();
}

} // namespace fields

// --- tables ---------------------------------------------------------------

template <> struct FieldTable<Light> {
    static constexpr auto fields = std::tuple{
        field<&Light::name>({.name = "name", .hashed = false}),
        field<&Light::type>({.name = "type", .description = "`area`: format version 2"}),
        field<&Light::color>({.name = "color", .range = kNonNegative, .shape = "[r, g, b]"}),
        field<&Light::intensity>({.name = "intensity",
                                  .range = kNonNegative,
                                  .unit = "W/m^2 (directional), W/sr (point, spot), see `unit` (area)",
                                  .editRange = fields::kEditRadiometric}),
        field<&Light::position>({.name = "position", .unit = "m", .editRange = fields::kEditCoordinate}),
        field<&Light::direction>(
            {.name = "direction",
             .description =
                 "the direction light travels; non-zero for directional and spot lights (`InvalidValue`)"}),
        field<&Light::range>({.name = "range",
                              .range = kNonNegative,
                              .unit = "m",
                              .description = "0 = unlimited",
                              .editRange = {0.0, 1.0e6}}),
        field<&Light::innerConeAngle>({.name = "innerConeAngle",
                                       .range = {0.0, fields::kHalfPi},
                                       .unit = "rad",
                                       .description = "full intensity inside it; <= `outerConeAngle`"}),
        // A spot's shadow map is a perspective of twice this angle: the
        // editor stays above kMinSpotCone, which the product check demands.
        field<&Light::outerConeAngle>({.name = "outerConeAngle",
                                       .range = {0.0, fields::kHalfPi, true, false},
                                       .unit = "rad",
                                       .description = "no light outside it; a spot's at least 1e-3",
                                       .editRange = {kMinSpotCone, fields::kHalfPi}}),
        field<&Light::castShadows>({.name = "castShadows"}),
        field<&Light::shape>(
            {.name = "shape", .description = "area lights only (required)", .applies = fields::isArea}),
        field<&Light::size>(
            {.name = "size",
             .range = kPositive,
             .unit = "m",
             .description = "area lights: width, height; required for a rectangle, kept for a disc",
             .applies = fields::isArea,
             .required = fields::isRectangle,
             .editRange = fields::kEditLength,
             .shape = "[w, h]"}),
        field<&Light::tangent>({.name = "tangent",
                                .description = "area lights: the rectangle's width axis, made orthogonal to "
                                               "`direction`; not zero and not along `direction` "
                                               "(`InvalidValue`); required for a rectangle",
                                .applies = fields::isArea,
                                .required = fields::isRectangle}),
        field<&Light::radius>({.name = "radius",
                               .range = kPositive,
                               .unit = "m",
                               .description = "area lights: required for a disc, kept for a rectangle",
                               .applies = fields::isArea,
                               .required = fields::isDisc,
                               .editRange = fields::kEditLength}),
        field<&Light::twoSided>({.name = "twoSided",
                                 .description = "area lights (required): emit from the back as well (default "
                                                "one-sided, as pbrt, Cycles and glTF)",
                                 .applies = fields::isArea}),
        field<&Light::unit>({.name = "unit",
                             .description =
                                 "area lights (required): what `intensity` is, `radiance` (W/(m^2 sr) "
                                 "leaving the emitting side) or `power` (W emitted in all; radiance = "
                                 "power / (pi A sides))",
                             .applies = fields::isArea}),
    };
};

template <> struct FieldTable<Material> {
    static constexpr auto fields = std::tuple{
        field<&Material::name>({.name = "name", .hashed = false}),
        field<&Material::shading>({.name = "shading"}),
        field<&Material::diffuseColor>({.name = "diffuseColor", .range = kNonNegative, .shape = "[r, g, b]"}),
        field<&Material::diffuseTexture>(
            {.name = "diffuseTexture",
             .description = "path relative to the project file, `\"\"` = none (so every texture below)"}),
        field<&Material::normalTexture>({.name = "normalTexture"}),
        field<&Material::heightTexture>({.name = "heightTexture", .description = "bump map"}),
        field<&Material::specularColor>(
            {.name = "specularColor", .range = kNonNegative, .shape = "[r, g, b]"}),
        field<&Material::specularTexture>({.name = "specularTexture"}),
        field<&Material::shininess>({.name = "shininess",
                                     .range = kNonNegative,
                                     .description = "Blinn-Phong exponent",
                                     .editRange = {0.0, 10000.0}}),
        field<&Material::metallic>({.name = "metallic", .range = kUnitInterval}),
        field<&Material::roughness>({.name = "roughness", .range = kUnitInterval}),
        field<&Material::metallicRoughnessTexture>({.name = "metallicRoughnessTexture"}),
        field<&Material::occlusionTexture>({.name = "occlusionTexture"}),
        field<&Material::emissive>({.name = "emissive", .range = kNonNegative, .shape = "[r, g, b]"}),
        field<&Material::emissiveTexture>({.name = "emissiveTexture"}),
        field<&Material::opacity>({.name = "opacity", .range = kUnitInterval}),
        field<&Material::alphaMode>({.name = "alphaMode"}),
        field<&Material::alphaCutoff>({.name = "alphaCutoff", .range = kUnitInterval}),
        field<&Material::translucency>(
            {.name = "translucency",
             .range = kUnitInterval,
             .description = "fraction of light that passes through (subsurface LPV)"}),
        field<&Material::glossiness>(
            {.name = "glossiness", .range = kUnitInterval, .description = "0 = diffuse, 1 = mirror"}),
        field<&Material::twoSided>(
            {.name = "twoSided",
             .description =
                 "kept from the source (4ds flag, glTF `doubleSided`); the renderer draws without "
                 "culling and shades every face on the side it is seen from, as the reference path "
                 "tracer does, so it does not change the image"}),
        field<&Material::alphaTexture>(
            {.name = "alphaTexture", .description = "coverage map, red channel = alpha", .optional = true}),
        field<&Material::colorKey>({.name = "colorKey",
                                    .description =
                                        "the diffuse map's key colour (first palette entry of an 8-bit "
                                        "map, else black) is transparent",
                                    .optional = true}),
        field<&Material::additive>(
            {.name = "additive", .description = "blended by adding (glows, flares)", .optional = true}),
        field<&Material::environmentTexture>(
            {.name = "environmentTexture", .description = "reflection map (4ds)", .optional = true}),
        field<&Material::environmentRatio>({.name = "environmentRatio",
                                            .range = kUnitInterval,
                                            .description = "how much of it is mixed in",
                                            .optional = true}),
    };
};

template <> struct FieldTable<LodLevel> {
    static constexpr auto fields = std::tuple{
        field<&LodLevel::mesh>({.name = "mesh", .index = IndexOf::Meshes}),
        field<&LodLevel::distance>({.name = "distance", .range = kNonNegative, .unit = "m"}),
    };
};

template <> struct FieldTable<Object> {
    static constexpr auto fields = std::tuple{
        field<&Object::name>({.name = "name", .hashed = false}),
        field<&Object::mesh>({.name = "mesh", .description = "-1 = none", .index = IndexOf::Meshes}),
        field<&Object::parent>({.name = "parent",
                                .description =
                                    "-1 = root; parent chains must not loop (`InvalidValue`, which "
                                    "names the loop; one of more than 11 objects by its first 8, its "
                                    "last 2 and its length). Chains of any depth load, and world "
                                    "matrices are computed, in time linear in the number of objects "
                                    "(`worldMatrices`)",
                                .index = IndexOf::Objects}),
        field<&Object::transform, &Transform::translation>(
            {.name = "translation", .description = "any finite", .editRange = fields::kEditCoordinate}),
        field<&Object::transform, &Transform::rotation>(
            {.name = "rotation",
             .description = "quaternion, not all zeros (`InvalidValue`); need not be normalised"}),
        // Positive in the editor: a zero scale collapses the object and its matrix cannot be inverted.
        field<&Object::transform, &Transform::scale>(
            {.name = "scale", .description = "any finite", .editRange = {0.001, 1.0e4}}),
        field<&Object::visible>({.name = "visible"}),
        field<&Object::lods>({.name = "lods",
                              .description =
                                  "further levels of detail, each `{\"mesh\": index, \"distance\": "
                                  "number >= 0}`; stored, not drawn yet; written when there are any",
                              .optional = true,
                              .hashed = false,
                              .written = fields::hasLods}),
    };
};

template <> struct FieldTable<Camera> {
    static constexpr auto fields = std::tuple{
        field<&Camera::name>({.name = "name", .hashed = false}),
        field<&Camera::position>({.name = "position",
                                  .unit = "m",
                                  .description = "coordinates within +-1e18, as `target`'s",
                                  .editRange = fields::kEditCoordinate}),
        field<&Camera::target>({.name = "target",
                                .unit = "m",
                                .description = "not `position` (`InvalidValue`)",
                                .editRange = fields::kEditCoordinate}),
        field<&Camera::up>({.name = "up",
                            .description = "non-zero, and at least 0.06 degrees off the view direction "
                                           "(`InvalidValue`)"}),
        // The editor's 1..179 degrees; below and above, the product check's limits.
        field<&Camera::fovY>({.name = "fovY",
                              .range = {0.0, std::numbers::pi, true, true},
                              .unit = "rad",
                              .description = "vertical; 1e-4 .. 3.1241 (0.0057 .. 179 degrees)",
                              .editRange = {std::numbers::pi / 180.0, kMaxFovY}}),
        field<&Camera::nearPlane>({.name = "nearPlane",
                                   .range = kPositive,
                                   .unit = "m",
                                   .description = "1e-18 .. 1e18, and far / near <= 1.6e7 (`OutOfRange` at "
                                                  "`nearPlane`)",
                                   .editRange = {1.0e-4, 1.0e7}}),
        field<&Camera::farPlane>({.name = "farPlane",
                                  .range = kPositive,
                                  .unit = "m",
                                  .description = "> `nearPlane`, <= 1e18",
                                  .editRange = {1.0e-4, 1.0e7}}),
    };
};

template <> struct FieldTable<CameraKeyframe> {
    static constexpr auto fields = std::tuple{
        field<&CameraKeyframe::time>(
            {.name = "time", .range = kNonNegative, .unit = "s", .description = "within a day (86,400 s)"}),
        field<&CameraKeyframe::position>({.name = "position", .unit = "m"}),
        field<&CameraKeyframe::orientation>(
            {.name = "orientation", .description = "not all zeros; normalised on playback"}),
        field<&CameraKeyframe::fovY>(
            {.name = "fovY", .range = {0.0, std::numbers::pi, true, true}, .unit = "rad"}),
    };
};

template <> struct FieldTable<CameraPath> {
    static constexpr auto fields = std::tuple{
        field<&CameraPath::name>({.name = "name", .hashed = false}),
        field<&CameraPath::keyframes>({.name = "keyframes",
                                       .description =
                                           "sorted by time: equal times are allowed (a cut), an earlier "
                                           "time than the key before is `InvalidValue` at "
                                           "`cameraPaths[i].keyframes[k].time`",
                                       .hashed = false}),
        field<&CameraPath::closed>({.name = "closed",
                                    .description =
                                        "the path returns from the last key to the first, the closing "
                                        "segment lasting as long as the mean segment; default "
                                        "`false`, written always",
                                    .optional = true}),
        field<&CameraPath::constantSpeed>({.name = "constantSpeed",
                                           .description = "time maps to distance along the path (constant "
                                                          "speed); the key times then set only the total "
                                                          "duration; default `false`, written always",
                                           .optional = true}),
    };
};

template <> struct FieldTable<Sky> {
    static constexpr auto fields = std::tuple{
        field<&Sky::color>({.name = "color", .range = kNonNegative, .shape = "[r, g, b]"}),
        field<&Sky::intensity>({.name = "intensity",
                                .range = kNonNegative,
                                .description = "0 = no sky light (closed interiors)",
                                .editRange = {0.0, 1.0e4}}),
    };
};

// --- rules between fields ---------------------------------------------------

// The rules that tie a struct's fields together, then its product checks
// (ValueChecks.h): the first one broken. `field` names the JSON field. The
// structs without such rules have their product checks alone.
std::optional<ValueProblem> checkFieldRules(const Light& light);
std::optional<ValueProblem> checkFieldRules(const Camera& camera);
std::optional<ValueProblem> checkFieldRules(const CameraPath& path);
template <class S> std::optional<ValueProblem> checkFieldRules(const S& s) {
    if constexpr (std::is_same_v<S, Material>)
        return checkMaterial(s);
    else if constexpr (std::is_same_v<S, Object>)
        return checkObject(s);
    else if constexpr (std::is_same_v<S, Sky>)
        return checkSky(s);
    else if constexpr (std::is_same_v<S, CameraKeyframe>)
        return checkKeyframe(s);
    else
        return std::nullopt;
}

// What a field may take given the struct's other fields (the inner cone
// within the outer one, far / near within kMaxDepthRatio): the editor's
// widgets narrow their range by it, so they cannot offer what the rules
// refuse. Unbounded for a field no rule ties. `field` is the JSON name.
FieldRange rangeGivenOthers(const Light& light, std::string_view field);
FieldRange rangeGivenOthers(const Camera& camera, std::string_view field);

// --- docs -----------------------------------------------------------------

// The Markdown table of a struct's fields for docs/project-format.md
// ("light", "material", "object", "camera", "cameraPath", "sky"); empty for
// another name. SceneFieldsDocTest keeps the doc equal to it.
std::string sceneFieldsMarkdown(std::string_view table);
// The names the fuzz dictionary (fuzz/project.dict) must hold: every field of every table.
std::vector<std::string> sceneFieldNames();

} // namespace lpv::scene
