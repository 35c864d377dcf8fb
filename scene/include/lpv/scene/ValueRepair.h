#pragma once
// Imported values that the product checks (ValueChecks.h) would refuse are
// repaired where a sensible value exists, with a warning: an importer turns
// a file it can read into a scene, and a camera with a parallel up vector
// or a light too bright to multiply is no reason to lose the whole file.
// The project reader does not repair: a project file is ours, and its
// errors name the field to fix.
#include "lpv/scene/Scene.h"

#include <string>
#include <vector>

namespace lpv::scene {

// Repairs cameras (up vector, field of view, near/far planes), lights
// (intensity scaled to the radiometric limit, direction, range) and
// materials (colours and shininess clamped); drops cameras and lights whose
// position is not finite or beyond +-1e18. Returns one warning per change,
// naming the camera, light or material.
std::vector<std::string> repairSceneValues(Scene& scene);

} // namespace lpv::scene
