#pragma once
// Values checked as products, not one by one (issue #42). Each field of a
// light, camera or path may be a finite float and still give a renderer,
// the radiosity solver, the reference or the video planner an infinity once
// multiplied (intensity x colour x area x exposure, 1/tan(fov/2), far/near,
// duration x fps). These checks bound the products; the project reader runs
// them on every value it reads (so saves, imports and edits, which all pass
// through it, get them too), and importers repair what they can first
// (ValueRepair.h). docs/hard-cases.md lists the limits and their reasons.
#include "lpv/scene/Camera.h"
#include "lpv/scene/Error.h"
#include "lpv/scene/Light.h"
#include "lpv/scene/Material.h"
#include "lpv/scene/Scene.h"

#include <glm/gtc/quaternion.hpp>

#include <optional>
#include <string>

namespace lpv::scene {

// Emitted radiance, irradiance, intensity or power, and each of their
// products with an area: kept under 1e30, which leaves 1e8 of float
// headroom (FLT_MAX is 3.4e38) for exposure, SH constants, BRDF factors and
// sums over lights and bounces.
inline constexpr double kMaxRadiometric = 1e30;
// A diffuse or specular colour above 1 reflects more than arrives; up to 100
// is kept for files that store colours on another scale (the solvers clamp
// reflectance below 1), beyond it the product with light leaves the headroom.
inline constexpr double kMaxColourScale = 100.0;
// Blinn-Phong exponent: (n + 8) / (8 pi) and pow(cos, n) stay finite; 1e6
// is a mirror for any purpose.
inline constexpr double kMaxShininess = 1e6;
// Coordinates and lengths: a square of one (distance^2, dot products) stays
// a normal, finite float (1e-36 .. 1e36), whatever unit the scene uses.
inline constexpr double kMaxLength = 1e18;
inline constexpr double kMinLength = 1e-18;
// Far / near: the far plane's depth, 1 - near/far in the 32-bit float depth
// buffer, must stay at least one float step (2^-24 = 5.96e-8) below the
// cleared 1.0, or what lies there is lost: 1 / 5.96e-8 = 1.68e7. A near
// plane of 1 mm with a far plane of 10 km (1e7) passes.
inline constexpr double kMaxDepthRatio = 1.6e7;
// Field of view: below 1e-4 rad (0.0057 degrees; the narrowest view we
// test is 4e-4 rad, 4 m wide at 10 km) the projection's 1/tan(fov/2)
// squared drives its inverse towards overflow (fovY 1e-30 rendered 75%
// black); above 179 degrees 1/tan(fov/2) vanishes. The editor's range.
inline constexpr double kMinFovY = 1e-4;
inline constexpr double kMaxFovY = 3.1241393; // 179 degrees
// The up vector must be at least 0.06 degrees off the view direction: their
// cross product (the camera's side axis) is then 1e-3 long and rounding
// (1e-7) turns it by at most 1e-4 rad.
inline constexpr double kMinUpSine = 1e-3;
// A spot light's outer cone half-angle: its shadow map is a perspective of
// twice the angle (1/tan overflows near 0), and the renderer softens the
// cone's edge over 1e-3 rad inside it.
inline constexpr double kMinSpotCone = 1e-3;
// Camera path key times: float times resolve 1/128 s up to a day (86,400 s),
// half a frame at 60 fps; later keys would snap frames together.
inline constexpr double kMaxKeyTime = 86400.0;
// Frames a video or CSV export plans (duration x fps): 10^6 is 9 hours at
// 30 fps; a 1e30 s key would otherwise plan 10^9 frames and run for ever.
inline constexpr double kMaxPlannedFrames = 1e6;

// What is wrong, and where: `field` is relative to the checked struct
// ("intensity", "up", "size[0]"), so a reader can prefix its own path.
struct ValueProblem {
    ErrorCode code = ErrorCode::OutOfRange;
    std::string field;
    std::string message;
};

std::optional<ValueProblem> checkCamera(const Camera& camera);
std::optional<ValueProblem> checkLight(const Light& light);
std::optional<ValueProblem> checkMaterial(const Material& material);
std::optional<ValueProblem> checkSky(const Sky& sky);
std::optional<ValueProblem> checkObject(const Object& object);
// A key of a camera path: time, position, orientation, field of view.
std::optional<ValueProblem> checkKeyframe(const CameraKeyframe& key);
// A rotation quaternion: normalisable in float.
std::optional<ValueProblem> checkRotation(const glm::quat& rotation, const std::string& field);

// Frames planned for `duration` seconds at `fps`: the message when the
// count is over kMaxPlannedFrames (or not finite), else nothing.
std::optional<std::string> checkPlannedFrames(double duration, double fps);

// The world matrices of all objects (their translation x scale products
// along the parent chains) within +-kMaxLength; the problem's field is
// "objects[i]". Parent chains must already be checked (no cycles).
std::optional<ValueProblem> checkObjectChains(const Scene& scene);

} // namespace lpv::scene
