#pragma once
// Adding one scene to another (`lpv import` into an existing project).
#include "lpv/scene/Scene.h"

namespace lpv::scene {

// Appends every mesh, material, object, light, camera and camera path of
// `from` to `into`, shifting the indices `from` uses (object meshes, LOD
// meshes, parents, submesh materials) past what `into` already holds. The
// sky of `into` is kept. Names are kept as they are.
void appendScene(Scene& into, Scene from);

} // namespace lpv::scene
