// The product checks of ValueChecks.h. Products are formed in double, so a
// check never overflows itself, and messages quote the product and the
// limit with its reason in a few words.
#include "lpv/scene/ValueChecks.h"
#include "lpv/scene/WorldMatrices.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace lpv::scene {
namespace {

constexpr double kPi = std::numbers::pi;

std::string number(double v) {
    char text[64];
    std::snprintf(text, sizeof text, "%.9g", v);
    return text;
}

std::string element(const std::string& field, int i) {
    return field + "[" + std::to_string(i) + "]";
}

ValueProblem problem(ErrorCode code, std::string field, std::string message) {
    return ValueProblem{code, std::move(field), std::move(message)};
}

// Each component finite and within +-kMaxLength.
template <int N>
std::optional<ValueProblem> checkCoordinates(const glm::vec<N, float>& v, const std::string& field) {
    for (int i = 0; i < N; ++i) {
        if (!std::isfinite(v[i]))
            return problem(ErrorCode::NonFinite, element(field, i), number(v[i]) + " is not a finite number");
        if (std::abs(double(v[i])) > kMaxLength)
            return problem(ErrorCode::OutOfRange, element(field, i),
                           number(v[i]) + " is beyond +-1e18, the largest coordinate whose square stays a "
                                          "finite float");
    }
    return std::nullopt;
}

// A direction-like vector (light direction, tangent, up): finite and long
// enough that normalising it in float gives a unit vector, not 0/0.
std::optional<ValueProblem> checkNormalisable(const glm::vec3& v, const std::string& field,
                                              const char* what) {
    if (auto p = checkCoordinates(v, field))
        return p;
    const double length = glm::length(glm::dvec3(v));
    if (length < kMinLength)
        return problem(ErrorCode::InvalidValue, field,
                       std::string(what) + " is " + number(length) +
                           " long, below 1e-18: it cannot be normalised in 32-bit floats");
    return std::nullopt;
}

std::optional<ValueProblem> checkLength(float v, const std::string& field, bool zeroAllowed) {
    if (!std::isfinite(v))
        return problem(ErrorCode::NonFinite, field, number(v) + " is not a finite number");
    if (zeroAllowed && v == 0.0f)
        return std::nullopt;
    if (std::abs(v) > float(kMaxLength) || std::abs(v) < float(kMinLength))
        return problem(ErrorCode::OutOfRange, field,
                       number(v) +
                           " is outside 1e-18..1e18 (lengths whose squares stay normal, finite floats)");
    return std::nullopt;
}

std::optional<ValueProblem> checkFov(float fovY, const std::string& field) {
    // Bounds rounded to float, as the project reader's ranges: a value the
    // program itself produces (a repair to the limit) must pass.
    if (!std::isfinite(fovY) || fovY < float(kMinFovY) || fovY > float(kMaxFovY))
        return problem(ErrorCode::OutOfRange, field,
                       "field of view " + number(fovY) + " rad (" + number(double(fovY) * 180.0 / kPi) +
                           " degrees) is outside 1e-4..3.1241 rad (0.0057..179 degrees): 1/tan(fovY/2) must "
                           "leave the projection and its inverse finite");
    return std::nullopt;
}

// The larger of colour component and intensity is named: it is the one to fix.
std::string brighterField(const glm::vec3& colour, float intensity, const char* colourField) {
    const float c = std::max({colour.r, colour.g, colour.b});
    return c > intensity ? std::string(colourField) : std::string("intensity");
}

std::optional<ValueProblem> checkEmission(double value, const std::string& field, const std::string& what) {
    if (!(value <= kMaxRadiometric))
        return problem(
            ErrorCode::OutOfRange, field,
            what + " is " + number(value) +
                ", over 1e30: products kept under 1e30 leave 1e8 of float headroom for exposure, SH "
                "constants and sums over lights");
    return std::nullopt;
}

std::optional<ValueProblem> checkAreaLight(const Light& l, double emitted, const std::string& field) {
    double area = 0.0;
    if (l.shape == AreaShape::Disc) {
        if (auto p = checkLength(l.radius, "radius", false))
            return p;
        area = kPi * double(l.radius) * double(l.radius);
    } else {
        if (auto p = checkLength(l.size.x, "size[0]", false))
            return p;
        if (auto p = checkLength(l.size.y, "size[1]", false))
            return p;
        if (auto p = checkNormalisable(l.tangent, "tangent", "the tangent"))
            return p;
        area = double(l.size.x) * double(l.size.y);
    }
    const double sides = l.twoSided ? 2.0 : 1.0;
    const double radiance = l.unit == AreaUnit::Radiance ? emitted : emitted / (kPi * area * sides);
    const double power = l.unit == AreaUnit::Power ? emitted : emitted * kPi * area * sides;
    // The quantity the light states first, naming colour or intensity; then
    // the one the area turns it into, naming the size.
    const std::string sizeField = l.shape == AreaShape::Disc ? "radius" : "size";
    if (l.unit == AreaUnit::Radiance) {
        if (auto p = checkEmission(radiance, field, "the radiance (colour x intensity)"))
            return p;
        if (auto p = checkEmission(power, sizeField, "the emitted power (colour x intensity x area x pi)"))
            return p;
    } else {
        if (auto p = checkEmission(power, field, "the emitted power (colour x intensity)"))
            return p;
        if (auto p = checkEmission(radiance, sizeField, "the radiance (power / (area x pi))"))
            return p;
    }
    if (area < 1e-30 || area > 1e30)
        return problem(ErrorCode::OutOfRange, sizeField,
                       "the light's area " + number(area) + " m^2 is outside 1e-30..1e30");
    return std::nullopt;
}

} // namespace

std::optional<ValueProblem> checkCamera(const Camera& c) {
    if (auto p = checkCoordinates(c.position, "position"))
        return p;
    if (auto p = checkCoordinates(c.target, "target"))
        return p;
    if (auto p = checkCoordinates(c.up, "up"))
        return p;
    const glm::dvec3 view = glm::dvec3(c.target) - glm::dvec3(c.position);
    if (glm::length(view) < kMinLength)
        return problem(ErrorCode::InvalidValue, "target",
                       "the target is " + number(glm::length(view)) +
                           " from the position, below 1e-18: the view direction cannot be normalised");
    if (auto p = checkNormalisable(c.up, "up", "the up vector"))
        return p;
    const double sine = glm::length(glm::cross(glm::normalize(view), glm::normalize(glm::dvec3(c.up))));
    if (sine < kMinUpSine)
        return problem(ErrorCode::InvalidValue, "up",
                       "the up vector is parallel to the view direction (" +
                           number(std::asin(std::min(sine, 1.0)) * 180.0 / kPi) +
                           " degrees apart, at least 0.06 needed): the camera's side axis is undefined");
    if (auto p = checkFov(c.fovY, "fovY"))
        return p;
    if (auto p = checkLength(c.nearPlane, "nearPlane", false))
        return p;
    if (auto p = checkLength(c.farPlane, "farPlane", false))
        return p;
    const double ratio = double(c.farPlane) / double(c.nearPlane);
    if (ratio > kMaxDepthRatio)
        return problem(
            ErrorCode::OutOfRange, "nearPlane",
            "far / near is " + number(ratio) +
                ", over 1.6e7: the 32-bit depth buffer cannot tell the far part of the view from the "
                "background; move the near plane out to at least far / 1.6e7 = " +
                number(double(c.farPlane) / kMaxDepthRatio));
    return std::nullopt;
}

std::optional<ValueProblem> checkLight(const Light& l) {
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(l.color[i]) || l.color[i] < 0.0f)
            return problem(ErrorCode::OutOfRange, element("color", i), number(l.color[i]) + " is not >= 0");
    if (!std::isfinite(l.intensity) || l.intensity < 0.0f)
        return problem(ErrorCode::OutOfRange, "intensity", number(l.intensity) + " is not >= 0");
    if (auto p = checkCoordinates(l.position, "position"))
        return p;
    if (l.type != LightType::Point)
        if (auto p = checkNormalisable(l.direction, "direction", "the direction"))
            return p;
    if (auto p = checkLength(l.range, "range", true))
        return p;
    // A spot's shadow map is a perspective of twice the outer angle, and the
    // renderer softens the cone's edge over 1e-3 rad inside it.
    if (l.type == LightType::Spot && !(double(l.outerConeAngle) >= kMinSpotCone))
        return problem(
            ErrorCode::OutOfRange, "outerConeAngle",
            "outer cone angle " + number(l.outerConeAngle) +
                " rad is below 0.001 rad (0.057 degrees): the spot's shadow projection, 1/tan of the "
                "angle, and its 0.001 rad soft edge need at least that");
    // Each factor too, not only the product: a colour of 3.4e38 at intensity
    // 0 multiplies to 0 here but not where colour is used alone.
    for (int i = 0; i < 3; ++i)
        if (auto p = checkEmission(l.color[i], element("color", i), "the colour"))
            return p;
    const double emitted = double(std::max({l.color.r, l.color.g, l.color.b})) * double(l.intensity);
    const std::string field = brighterField(l.color, l.intensity, "color");
    if (l.type == LightType::Area)
        return checkAreaLight(l, emitted, field);
    const char* what = l.type == LightType::Directional ? "the irradiance (colour x intensity)"
                                                        : "the radiant intensity (colour x intensity)";
    return checkEmission(emitted, field, what);
}

std::optional<ValueProblem> checkMaterial(const Material& m) {
    for (const auto& [colour, field] :
         {std::pair{&m.diffuseColor, "diffuseColor"}, std::pair{&m.specularColor, "specularColor"}})
        for (int i = 0; i < 3; ++i)
            if (!(double((*colour)[i]) <= kMaxColourScale))
                return problem(
                    ErrorCode::OutOfRange, element(field, i),
                    number((*colour)[i]) +
                        " is over 100: a reflectance is at most 1, and 100 times the brightest light "
                        "is where the renderers' products leave float range");
    for (int i = 0; i < 3; ++i)
        if (auto p = checkEmission(m.emissive[i], element("emissive", i), "the emitted radiance"))
            return p;
    if (!(double(m.shininess) <= kMaxShininess))
        return problem(ErrorCode::OutOfRange, "shininess",
                       number(m.shininess) +
                           " is over 1e6: (n + 8) / (8 pi) times the light must stay finite");
    return std::nullopt;
}

std::optional<ValueProblem> checkSky(const Sky& s) {
    for (int i = 0; i < 3; ++i)
        if (auto p = checkEmission(s.color[i], element("color", i), "the colour"))
            return p;
    const double emitted = double(std::max({s.color.r, s.color.g, s.color.b})) * double(s.intensity);
    return checkEmission(emitted, brighterField(s.color, s.intensity, "color"),
                         "the sky radiance (colour x intensity)");
}

std::optional<ValueProblem> checkRotation(const glm::quat& q, const std::string& field) {
    const glm::vec4 v(q.x, q.y, q.z, q.w);
    if (auto p = checkCoordinates(v, field))
        return p;
    const double length = glm::length(glm::dvec4(v));
    if (length < kMinLength)
        return problem(ErrorCode::InvalidValue, field,
                       "the quaternion is " + number(length) + " long, below 1e-18: it cannot be normalised");
    return std::nullopt;
}

std::optional<ValueProblem> checkObject(const Object& o) {
    if (auto p = checkCoordinates(o.transform.translation, "translation"))
        return p;
    // Not 0 either: the normal matrix is the inverse of the scale, and a
    // zero made the normals of a flattened object NaN.
    for (int i = 0; i < 3; ++i) {
        if (o.transform.scale[i] == 0.0f)
            return problem(ErrorCode::OutOfRange, element("scale", i),
                           "a scale of 0 flattens the object and makes its normal matrix (the inverse of the "
                           "scale) infinite");
        if (auto p = checkLength(o.transform.scale[i], element("scale", i), false))
            return p;
    }
    if (auto p = checkRotation(o.transform.rotation, "rotation"))
        return p;
    for (std::size_t i = 0; i < o.lods.size(); ++i)
        if (auto p = checkLength(o.lods[i].distance, element("lods", int(i)) + ".distance", true))
            return p;
    return std::nullopt;
}

std::optional<ValueProblem> checkKeyframe(const CameraKeyframe& k) {
    if (!std::isfinite(k.time) || k.time < 0.0f || double(k.time) > kMaxKeyTime)
        return problem(ErrorCode::OutOfRange, "time",
                       "key time " + number(k.time) +
                           " s is outside 0..86400 (a day): float times resolve 1/128 s there, half a frame "
                           "at 60 fps");
    if (auto p = checkCoordinates(k.position, "position"))
        return p;
    if (auto p = checkRotation(k.orientation, "orientation"))
        return p;
    return checkFov(k.fovY, "fovY");
}

std::optional<std::string> checkPlannedFrames(double duration, double fps) {
    const double frames = duration * fps;
    if (std::isfinite(frames) && frames <= kMaxPlannedFrames)
        return std::nullopt;
    return "the path lasts " + number(duration) + " s: at " + number(fps) + " fps that is " + number(frames) +
           " frames, over the limit of 1000000 (9 hours at 30 fps)";
}

std::optional<ValueProblem> checkObjectChains(const Scene& scene) {
    const std::vector<glm::mat4> worlds = worldMatrices(scene);
    for (std::size_t i = 0; i < worlds.size(); ++i)
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 3; ++r) {
                const float v = worlds[i][c][r];
                if (!std::isfinite(v) || std::abs(double(v)) > kMaxLength)
                    return problem(
                        ErrorCode::OutOfRange, element("objects", int(i)),
                        "its world transform (its and its parents' translation x rotation x scale) "
                        "reaches " +
                            number(v) + ", beyond +-1e18");
            }
    return std::nullopt;
}

} // namespace lpv::scene
