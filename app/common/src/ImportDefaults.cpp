#include "lpv/app/ImportDefaults.h"

#include "lpv/reference/SunPlacement.h"
#include "lpv/scene/FramingCamera.h"

#include <cstdio>

namespace lpv::app {

scene::Camera firstView(const scene::Scene& scene) {
    return scene.cameras.empty() ? scene::framingCamera(scene) : scene.cameras.front();
}

DefaultSun chooseDefaultSun(const scene::Scene& s) {
    DefaultSun out;
    scene::Light& sun = out.light;
    sun.name = "sun (added on import)";
    sun.type = scene::LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(-0.35f, -1.0f, -0.25f));
    sun.color = glm::vec3(1.0f, 0.95f, 0.85f);
    sun.intensity = 3.0f;
    out.how = "the default direction (the scene could not be ray traced to choose one)";
    if (auto embree = reference::EmbreeScene::build(s, {})) {
        const scene::Camera camera = firstView(s);
        const reference::SunChoice fallback = reference::sunlitShare(*embree, camera, sun.direction);
        const reference::SunChoice best = reference::chooseSunDirection(*embree, camera, sun.direction);
        sun.direction = best.direction;
        char text[200];
        std::snprintf(text, sizeof text,
                      "from azimuth %.0f, elevation %.0f degrees: it lights %.0f%% of what the %s camera sees "
                      "(the default direction: %.0f%%)",
                      best.azimuthDegrees, best.elevationDegrees, 100.0 * best.litFraction,
                      s.cameras.empty() ? "framing" : "scene's", 100.0 * fallback.litFraction);
        out.how = text;
    }
    return out;
}

} // namespace lpv::app
