#pragma once
// Emissive surfaces as VPLs (docs/lpv.md, "Local lights, emissive surfaces and
// bounces"): every triangle of a visible object whose material emits is cut
// into m^2 equal sub-triangles (a regular subdivision), and each becomes a VPL
// at its centroid, facing the triangle's front (the side its vertex normals
// point to), with flux pi * emissive * area / m^2: a Lambertian emitter of
// radiance L and area A sends pi L A. Sampled on the CPU once per scene
// change, not rendered into an RSM: an emitter need not be visible from the
// sun or any light, and its VPLs do not depend on the view.
#include "lpv/renderer/lpv/LpvReference.h"
#include "lpv/scene/Scene.h"

#include <vector>

namespace lpv::renderer::lpvref {

// `spacing`: target distance between VPLs (m = ceil(edge-ish size / spacing)
// per triangle, from sqrt(area) / spacing); `maxVpls`: the spacing grows until
// the scene fits. Emissive textures are not read (the material's factor only).
// `worldMagnitude`: scene::liesOnAnAreaLight's, for a scene in render space.
std::vector<Vpl> sampleEmissiveVpls(const scene::Scene& scene, float spacing, int maxVpls,
                                    float worldMagnitude = 0.0f);

// Whether a visible object draws with a material that emits (not as an area light's surface).
bool sceneHasEmissiveSurface(const scene::Scene& scene, float worldMagnitude = 0.0f);

} // namespace lpv::renderer::lpvref
