#pragma once
// The scene of many light-transport tests: one large floor, nothing else, no
// sky. Analytic answers are known for it (a point or area light above an
// infinite Lambertian plane), so the reference and the renderer are both
// checked on it.
#include "lpv/scene/Primitives.h"
#include "lpv/scene/Scene.h"

namespace lpv::test {

// The unit plane at y = 0 scaled to `side` x `side` metres, of `material`, with the sky off.
inline scene::Scene greyFloor(const scene::Material& material, float side) {
    scene::Scene s;
    s.meshes.push_back(scene::makePlane());
    s.materials.push_back(material);
    scene::Object floor;
    floor.mesh = 0;
    floor.transform.scale = glm::vec3(side, 1.0f, side);
    s.objects.push_back(floor);
    s.sky.intensity = 0.0f;
    return s;
}

// The same with a Lambertian material of `albedo`.
inline scene::Scene greyFloor(float albedo, float side) {
    scene::Material m;
    m.diffuseColor = glm::vec3(albedo);
    return greyFloor(m, side);
}

} // namespace lpv::test
