#pragma once
// "A render of the loaded result is finite" (issue #42), checked on the CPU.
//
// The fuzz build is GL-free and links neither the renderer nor the Embree
// reference, so this does not draw. It evaluates the products a frame is
// made of, with the scene library's own functions where the renderer uses
// them (Camera::view and ::projection, worldMatrices, worldBounds, the area
// light's frame, area and radiance): the view basis from up and direction,
// 1/tan(fovY/2), the far/near ratio, light radiance x colour x area x
// exposure, a material's albedo times the brightest light (direct) and
// times itself (one bounce), the scene's extent (which sizes the LPV cells),
// a camera path's frame count. Each of them non-finite means a black or NaN
// image, a hang or a NaN ray, whatever the single values looked like.
//
// Why not trace an image: linking the reference (Embree, not instrumented)
// into the sanitizer build would cost a ray tracer's set-up per execution
// (the project targets run at tens of executions per second already) and
// would only see what these products already decide; a NaN found here is
// named by its field, where a black pixel would not say why.
#include "lpv/scene/AreaLight.h"
#include "lpv/scene/ParameterRegistry.h"
#include "lpv/scene/Project.h"
#include "lpv/scene/Scene.h"
#include "lpv/scene/WorldMatrices.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>

namespace lpv::fuzz {

namespace render {

[[noreturn]] inline void notFinite(const std::string& what) {
    std::fprintf(stderr, "==fuzz== render not finite: %s\n", what.c_str());
    std::abort();
}

// Nine significant digits: std::to_string would print 1e-45 as 0.000000.
inline std::string num(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", v);
    return text;
}

inline void finite(float v, const std::string& what) {
    if (!std::isfinite(v))
        notFinite(what + " = " + num(v));
}

template <int N> void finite(const glm::vec<N, float>& v, const std::string& what) {
    for (int c = 0; c < N; ++c)
        finite(v[c], what + "[" + std::to_string(c) + "]");
}

inline void finite(const glm::mat4& m, const std::string& what) {
    for (int col = 0; col < 4; ++col)
        finite(m[col], what + " column " + std::to_string(col));
}

inline float maxComponent(const glm::vec3& v) {
    return std::max({v.x, v.y, v.z});
}

// The light's strength per colour channel as the shaders take it: radiance
// for an area light, intensity x colour otherwise.
inline glm::vec3 lightStrength(const scene::Light& l) {
    return l.type == scene::LightType::Area ? scene::areaLightRadiance(l) : l.color * l.intensity;
}

} // namespace render

// The display's exposure factor: 2^output.exposure when metering is manual;
// auto exposure divides by the frame's own average, so only its
// compensation (the same parameter) scales the result.
inline float exposureScale(const scene::ParameterSet& parameters) {
    return std::exp2(parameters.getFloat("output.exposure"));
}

// What the renderer makes of a camera: the view basis from up and the view
// direction, the focal length 1/tan(fovY/2), the far/near ratio, and the
// view-projection matrix at the widest aspect a viewport or `lpv render` uses
// (a narrower one only scales the first column).
inline void checkCameraFinite(const scene::Camera& c, const std::string& at) {
    using render::finite;
    constexpr float kAspect = 21.0f / 9.0f;
    finite(c.view(), at + " view matrix (the basis from up and the view direction)");
    const float focal = 1.0f / std::tan(0.5f * c.fovY);
    if (!std::isfinite(focal) || focal <= 0.0f)
        render::notFinite(at + " 1/tan(fovY/2) = " + render::num(focal) + " (fovY " + render::num(c.fovY) +
                          ")");
    const float ratio = c.farPlane / c.nearPlane;
    if (!std::isfinite(ratio) || !(c.nearPlane > 0.0f) || !(ratio > 1.0f))
        render::notFinite(at + " far/near = " + render::num(c.farPlane) + "/" + render::num(c.nearPlane));
    finite(c.projection(kAspect) * c.view(), at + " view-projection matrix");
}

inline void checkRenderFinite(const scene::Scene& s, float exposure = 1.0f) {
    using render::finite;
    for (std::size_t i = 0; i < s.cameras.size(); ++i)
        checkCameraFinite(s.cameras[i], "cameras[" + std::to_string(i) + "] ('" + s.cameras[i].name + "')");

    float brightest = 0.0f, totalPower = 0.0f;
    for (std::size_t i = 0; i < s.lights.size(); ++i) {
        const scene::Light& l = s.lights[i];
        const std::string at = "lights[" + std::to_string(i) + "] ('" + l.name + "')";
        if (l.type != scene::LightType::Point)
            finite(glm::normalize(l.direction), at + " direction, normalised");
        const glm::vec3 strength = render::lightStrength(l);
        finite(strength * exposure, at + " colour x intensity x exposure");
        float power = render::maxComponent(strength);
        if (l.type == scene::LightType::Area) {
            const scene::AreaLightFrame frame = scene::areaLightFrame(l);
            finite(frame.center, at + " area frame centre");
            finite(frame.normal, at + " area frame normal");
            finite(frame.halfU, at + " area frame half width");
            finite(frame.halfV, at + " area frame half height");
            const float area = scene::areaLightArea(l);
            finite(area, at + " area");
            power *= area * 3.14159265f * (l.twoSided ? 2.0f : 1.0f);
            finite(power, at + " radiance x area x pi (its power, what radiosity shoots)");
        }
        if (l.type == scene::LightType::Spot) {
            finite(std::cos(l.innerConeAngle), at + " cos(inner cone)");
            finite(std::cos(l.outerConeAngle), at + " cos(outer cone)");
        }
        brightest = std::max(brightest, render::maxComponent(glm::abs(strength)));
        totalPower += std::abs(power);
        finite(totalPower, "the lights' total power up to " + at);
    }
    const glm::vec3 sky = s.sky.color * s.sky.intensity;
    finite(sky * exposure, "sky colour x intensity x exposure");
    brightest = std::max(brightest, render::maxComponent(glm::abs(sky)));

    for (std::size_t i = 0; i < s.materials.size(); ++i) {
        const scene::Material& m = s.materials[i];
        const std::string at = "materials[" + std::to_string(i) + "] ('" + m.name + "')";
        finite(m.emissive * exposure, at + " emissive x exposure");
        const glm::vec3 direct = m.diffuseColor * brightest * exposure;
        finite(direct, at + " diffuse x brightest light x exposure");
        finite(direct * m.diffuseColor, at + " diffuse^2 x brightest light x exposure (one bounce)");
    }

    const std::vector<glm::mat4> world = scene::worldMatrices(s);
    for (std::size_t i = 0; i < world.size(); ++i)
        finite(world[i], "objects[" + std::to_string(i) + "] world matrix");
    if (const scene::Bounds bounds = s.worldBounds(); !bounds.empty())
        finite(bounds.size(), "the scene's extent (it sizes the LPV cells and shadow maps)");

    // A video plays every frame of a path; at 240 frames per second, the
    // most a video is made at, its count must fit a frame index.
    constexpr double kMaxFps = 240.0;
    for (std::size_t i = 0; i < s.cameraPaths.size(); ++i) {
        const scene::CameraPath& p = s.cameraPaths[i];
        const std::string at = "cameraPaths[" + std::to_string(i) + "] ('" + p.name + "')";
        for (std::size_t k = 0; k < p.keyframes.size(); ++k) {
            const scene::CameraKeyframe& key = p.keyframes[k];
            const std::string keyAt = at + ".keyframes[" + std::to_string(k) + "]";
            finite(key.time, keyAt + ".time");
            finite(key.position, keyAt + ".position");
            finite(key.fovY, keyAt + ".fovY");
        }
        if (p.keyframes.size() < 2)
            continue;
        const double duration = double(p.keyframes.back().time) - double(p.keyframes.front().time);
        if (!(std::abs(duration) * kMaxFps < double(std::numeric_limits<int>::max())))
            render::notFinite(at + " lasts " + render::num(duration) + " s: more frames than an int counts");
    }
}

// A project renders with its own parameters or any of its presets, and the
// editor opens at its saved view.
inline void checkProjectRenderFinite(const scene::Project& p) {
    float exposure = exposureScale(p.parameters);
    for (const scene::ParameterPreset& preset : p.presets)
        exposure = std::max(exposure, exposureScale(preset.parameters));
    checkRenderFinite(p.scene, exposure);
    if (p.editorView)
        checkCameraFinite(*p.editorView, "editorView");
}

} // namespace lpv::fuzz
