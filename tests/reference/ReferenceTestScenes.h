#pragma once
// Scenes and views the reference's analytic tests share, written once.
#include "lpv/scene/Camera.h"
#include "lpv/scene/Primitives.h"
#include "lpv/scene/Scene.h"

namespace lpv::test {

// Five units above the origin, looking straight down, +z towards the bottom of the image.
inline scene::Camera lookingDown() {
    scene::Camera c;
    c.position = {0.0f, 5.0f, 0.0f};
    c.target = {0.0f, 0.0f, 0.0f};
    c.up = {0.0f, 0.0f, -1.0f};
    return c;
}

// A closed 4 m box (a furnace) whose walls all reflect `albedo` and emit
// `emitted`, to be seen from inside: L = Le / (1 - a) everywhere.
inline scene::Scene furnaceBox(float albedo, float emitted) {
    scene::Scene s;
    s.meshes.push_back(scene::makeBox());
    scene::Material m;
    m.diffuseColor = glm::vec3(albedo);
    m.emissive = glm::vec3(emitted);
    // The box's faces point out and the camera is inside: emission must leave the
    // back too, which a material says explicitly (emitters are one-sided otherwise).
    m.twoSided = true;
    s.materials.push_back(m);
    scene::Object o;
    o.mesh = 0;
    o.transform.scale = glm::vec3(4.0f);
    s.objects.push_back(o);
    return s;
}

} // namespace lpv::test
