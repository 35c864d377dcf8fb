#pragma once
// A sun shining into the built-in Cornell box through its open front, down
// onto the floor and the red wall: the light of the visualizer and --dump
// tests, which need the RSM, the LPV and the shadow cascades to see it.
#include "lpv/scene/Light.h"

#include <glm/glm.hpp>

namespace lpv::test {

inline scene::Light cornellFrontSun() {
    scene::Light sun;
    sun.name = "sun";
    sun.type = scene::LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(0.6f, -0.35f, 0.7f));
    sun.intensity = 3.0f;
    return sun;
}

} // namespace lpv::test
