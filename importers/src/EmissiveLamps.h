#pragma once
// Planar emissive rectangles and discs become area lights (issue #22): an OBJ
// `Ke` quad, a glTF `emissiveFactor` panel, any importer's. The mesh stays as
// the lamp's visible surface; the renderer and the reference leave a surface
// that lies on an area light out of their emitters (scene::liesOnAnAreaLight),
// so the lamp counts once. Other emissive meshes (boxes, spheres, textured
// emitters) stay emissive surfaces.
#include "lpv/scene/Scene.h"

#include <string>
#include <vector>

namespace lpv::importers {

// Adds one area light per submesh instance that is a flat, uniformly
// emitting rectangle or disc; returns how many, with one note each in `notes`.
int addAreaLightsForEmissivePanels(scene::Scene& scene, std::vector<std::string>& notes);

} // namespace lpv::importers
