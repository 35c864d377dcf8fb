#pragma once
// Leak diagnostics on a read-back LPV (LpvSnapshot): where light gets through
// walls that the geometry volume knows about. Plain C++ over the same maths
// as the CPU reference (docs/lpv.md), so they can be sliced and coloured like
// any other volume (SliceImage.h).
#include "lpv/renderer/LpvSnapshot.h"

#include <glm/glm.hpp>

#include <vector>

namespace lpv::renderer::viz {

// Per destination cell and colour channel (value in .x), the flux (W) that
// one propagation step of `volume` moves into it across faces whose blocking
// (the GV toward the light's travel direction, 0..1) is at least `threshold`,
// after the occlusion that propagation applies (`occlusion` off: none). With
// a GV that covered the walls completely this map would be dark.
ShVolume leakHeat(const ShVolume& volume, const std::vector<glm::vec4>& geometry, int gridSize,
                  bool occlusion, float threshold = 0.3f);

// Per cell where the GV holds a wall (its blocking toward the wall's normal
// reaches `threshold`), the irradiance (W/m^2, per channel in .x) that
// arrives on the wall's back side: the light a thin wall, seen from one side
// only, lets through. Zero elsewhere.
ShVolume backsideLight(const ShVolume& volume, const std::vector<glm::vec4>& geometry,
                       const LpvGridFrame& frame, float threshold = 0.3f);

} // namespace lpv::renderer::viz
