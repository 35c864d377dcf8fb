// The importers' repairs (ValueRepair.h): each one leaves a value that
// ValueChecks.h accepts, or drops the camera or light it cannot save.
#include "lpv/scene/ValueRepair.h"
#include "lpv/scene/ValueChecks.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lpv::scene {
namespace {

constexpr double kPi = std::numbers::pi;

bool usableCoordinates(const glm::vec3& v) {
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(v[i]) || std::abs(double(v[i])) > kMaxLength)
            return false;
    return true;
}

bool normalisable(const glm::vec3& v) {
    return usableCoordinates(v) && glm::length(glm::dvec3(v)) >= kMinLength;
}

std::string quoted(const std::string& what, const std::string& name) {
    return what + " '" + name + "': ";
}

// Up is the world's +Y unless the camera looks (nearly) along it; then +Z.
glm::vec3 uprightFor(const glm::dvec3& view) {
    const glm::dvec3 unit = glm::normalize(view);
    return std::abs(unit.y) < 0.99 ? glm::vec3(0, 1, 0) : glm::vec3(0, 0, 1);
}

// false: the camera cannot be repaired (its position or target is unusable).
bool repairCamera(Camera& c, std::vector<std::string>& notes) {
    const std::string who = quoted("camera", c.name);
    const glm::dvec3 view = glm::dvec3(c.target) - glm::dvec3(c.position);
    if (!usableCoordinates(c.position) || !usableCoordinates(c.target) || glm::length(view) < kMinLength) {
        notes.push_back(who +
                        "position or target not finite, beyond +-1e18 or equal; the camera was dropped");
        return false;
    }
    const bool upUsable =
        normalisable(c.up) &&
        glm::length(glm::cross(glm::normalize(view), glm::normalize(glm::dvec3(c.up)))) >= kMinUpSine;
    if (!upUsable) {
        c.up = uprightFor(view);
        notes.push_back(who +
                        "the up vector was zero, not finite or parallel to the view direction; set to (" +
                        std::to_string(int(c.up.x)) + ", " + std::to_string(int(c.up.y)) + ", " +
                        std::to_string(int(c.up.z)) + ")");
    }
    if (!std::isfinite(c.fovY) || double(c.fovY) < kMinFovY || double(c.fovY) > kMaxFovY) {
        const float before = c.fovY;
        c.fovY =
            std::isfinite(c.fovY) ? float(std::clamp(double(c.fovY), kMinFovY, kMaxFovY)) : Camera{}.fovY;
        notes.push_back(who + "field of view " + std::to_string(before) + " rad set to " +
                        std::to_string(c.fovY) + " (the limits are 1e-4..3.1241 rad)");
    }
    const Camera defaults;
    const bool farUsable = std::isfinite(c.farPlane) && double(c.farPlane) >= kMinLength;
    const bool nearUsable = std::isfinite(c.nearPlane) && double(c.nearPlane) >= kMinLength;
    const float far = farUsable ? float(std::min(double(c.farPlane), kMaxLength)) : defaults.farPlane;
    float near = nearUsable ? c.nearPlane : std::min(defaults.nearPlane, far * 0.5f);
    // A hair above far / kMaxDepthRatio, so the division in float still passes.
    near = float(std::max({double(near), double(far) / kMaxDepthRatio * (1.0 + 1e-6), kMinLength}));
    if (near >= far)
        near = float(double(far) * 0.5);
    if (near != c.nearPlane || far != c.farPlane) {
        notes.push_back(who + "near/far planes " + std::to_string(c.nearPlane) + " / " +
                        std::to_string(c.farPlane) + " set to " + std::to_string(near) + " / " +
                        std::to_string(far) +
                        " (far / near at most 1.6e7, the 32-bit depth buffer's precision)");
        c.nearPlane = near;
        c.farPlane = far;
    }
    return true;
}

// The light's brightest product (radiance or power, as ValueChecks forms them).
double emittedProduct(const Light& l) {
    const double emitted = double(std::max({l.color.r, l.color.g, l.color.b})) * double(l.intensity);
    if (l.type != LightType::Area)
        return emitted;
    const double area = l.shape == AreaShape::Disc ? kPi * double(l.radius) * double(l.radius)
                                                   : double(l.size.x) * double(l.size.y);
    const double spread = kPi * area * (l.twoSided ? 2.0 : 1.0);
    return l.unit == AreaUnit::Radiance ? std::max(emitted, emitted * spread)
                                        : std::max(emitted, spread > 0.0 ? emitted / spread : emitted);
}

bool repairLight(Light& l, std::vector<std::string>& notes) {
    const std::string who = quoted("light", l.name);
    if (!usableCoordinates(l.position)) {
        notes.push_back(who + "position not finite or beyond +-1e18; the light was dropped");
        return false;
    }
    if (l.type == LightType::Spot && !(double(l.outerConeAngle) >= kMinSpotCone)) {
        l.outerConeAngle = float(kMinSpotCone);
        l.innerConeAngle = std::min(l.innerConeAngle, l.outerConeAngle);
        notes.push_back(who + "outer cone angle below 0.001 rad; set to 0.001");
    }
    if (l.type != LightType::Point && !normalisable(l.direction)) {
        l.direction = glm::vec3(0.0f, -1.0f, 0.0f);
        notes.push_back(who + "direction zero, too short or not finite; set to straight down (0, -1, 0)");
    }
    if (!std::isfinite(l.range) || double(l.range) > kMaxLength ||
        (l.range > 0.0f && double(l.range) < kMinLength)) {
        l.range = 0.0f;
        notes.push_back(who + "range not finite or outside 1e-18..1e18; set to 0 (unlimited)");
    }
    // A colour or intensity that is not a finite float is a broken file, not
    // a value out of range: it is left for the import's read check to refuse,
    // naming the input file and the field (ReadPolicy), as before issue #42.
    if (!std::isfinite(l.intensity) || !std::isfinite(l.color.r) || !std::isfinite(l.color.g) ||
        !std::isfinite(l.color.b))
        return true;
    const double product = emittedProduct(l);
    const double peak = std::max({l.color.r, l.color.g, l.color.b});
    if (product > kMaxRadiometric || peak > kMaxRadiometric) {
        const float before = l.intensity;
        double intensity = l.intensity;
        // A colour beyond the limit carries the brightness: it moves into the intensity.
        if (peak > kMaxRadiometric) {
            l.color = glm::vec3(glm::dvec3(l.color) / peak);
            intensity *= peak;
        }
        // Scaled by a hair more than needed, so the float product lands below the limit.
        if (product > kMaxRadiometric)
            intensity *= kMaxRadiometric / product * (1.0 - 1e-6);
        l.intensity = float(intensity);
        notes.push_back(who + "colour x intensity (x area) " + std::to_string(product) +
                        " is over 1e30; intensity " + std::to_string(before) + " scaled to " +
                        std::to_string(l.intensity));
    }
    return true;
}

void repairMaterial(Material& m, std::vector<std::string>& notes) {
    bool changed = false;
    const auto clampTo = [&](float& v, double limit) {
        if (!(double(v) <= limit)) {
            v = std::isnan(v) ? 0.0f : float(limit);
            changed = true;
        }
    };
    for (int i = 0; i < 3; ++i) {
        clampTo(m.diffuseColor[i], kMaxColourScale);
        clampTo(m.specularColor[i], kMaxColourScale);
        clampTo(m.emissive[i], kMaxRadiometric);
    }
    clampTo(m.shininess, kMaxShininess);
    if (changed)
        notes.push_back(
            quoted("material", m.name) +
            "colours over 100, emission over 1e30 or shininess over 1e6 were clamped to those limits");
}

} // namespace

std::vector<std::string> repairSceneValues(Scene& scene) {
    std::vector<std::string> notes;
    std::vector<Camera> cameras;
    for (Camera& c : scene.cameras)
        if (repairCamera(c, notes))
            cameras.push_back(std::move(c));
    scene.cameras = std::move(cameras);
    std::vector<Light> lights;
    for (Light& l : scene.lights)
        if (repairLight(l, notes))
            lights.push_back(std::move(l));
    scene.lights = std::move(lights);
    for (Material& m : scene.materials)
        repairMaterial(m, notes);
    return notes;
}

} // namespace lpv::scene
