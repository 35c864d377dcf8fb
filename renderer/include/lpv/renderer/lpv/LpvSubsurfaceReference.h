#pragma once
// CPU twin of the subsurface-scattering LPV (docs/lpv.md, "Subsurface LPV"):
// a second volume set fed only by translucent RSM texels, each a VPL that
// points into the surface (along -normal, no offset) with the flux the
// material lets through, propagated a few steps without occlusion and
// attenuated per step. LpvSubsurfacePass (GPU) is tested against it.
#include "lpv/renderer/lpv/LpvReference.h"

#include <span>

namespace lpv::renderer::lpvref {

// A VPL of a translucent texel: `translucency` (0..1) of its flux enters the material.
struct TranslucentVpl {
    Vpl vpl;
    float translucency = 0.0f;
};

// Injection: every VPL with translucency > 0 into the cell its surface point
// lies in (no offset), as flux * translucency / pi * cosineLobe(-normal).
ShGrid injectSubsurface(const GridFrame& grid, std::span<const TranslucentVpl> vpls);

// V_0 + V_1 + ... + V_steps with V_{i+1} = (1 - attenuation) * propagate(V_i),
// propagate being the LPV's gather step without occlusion.
ShGrid propagateSubsurface(const ShGrid& injected, int steps, float attenuation);

// Irradiance on the back of a surface (normal n): light that crossed the
// material and leaves through the face, i.e. irradianceAt toward -n.
glm::vec3 subsurfaceIrradianceAt(const ShGrid& accumulated, const GridFrame& grid, const glm::vec3& x,
                                 const glm::vec3& n);

} // namespace lpv::renderer::lpvref
