#pragma once
// Multi-bounce LPV, CPU twin of shaders/lpv_bounce.comp (docs/lpv.md, "Local
// lights, emissive surfaces and bounces"). After one bounce has propagated,
// every cell with geometry-volume surfels reflects the light the bounce's
// accumulator brings to them as a secondary VPL; those are propagated again
// into a volume of their own, which is added to the total.
#include "lpv/renderer/lpv/LpvReference.h"

#include <vector>

namespace lpv::renderer::lpvref {

// The secondary VPLs of cell p: the GV at p's centre (the mean of its 8 corner
// GV cells) gives an oriented surfel, net normal n and coverage c = min(|net
// oriented area| / s^2, 1) (two faces of a thin wall cancel and reflect
// nothing); it receives E s^2 = max(0, A(p) . cosineLobe(-n)) per channel from
// the accumulator A and re-emits albedo * c * E s^2 as a VPL facing n in p.
ShGrid bounceVpls(const ShGrid& accumulated, const GvGrid& gv, float albedo);

// Bounce 1 is propagateAndAccumulate(injected); each further bounce injects
// bounceVpls of the previous bounce's accumulator and propagates them the same
// way (occlusion by `gv` when `occlude`). Returns the sum of all bounces;
// `perBounce`, when given, receives each bounce's accumulator.
ShGrid propagateWithBounces(const ShGrid& injected, const GvGrid& gv, bool occlude, int steps, int bounces,
                            float albedo, std::vector<ShGrid>* perBounce = nullptr, bool occludeFirstStep = true);

} // namespace lpv::renderer::lpvref
