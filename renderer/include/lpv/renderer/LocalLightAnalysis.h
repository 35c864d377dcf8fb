#pragma once
// The scene analysis' decisions for local lights and bounces (docs/lpv.md,
// "Local lights, emissive surfaces and bounces"), next to SceneAnalysis.h's.
#include "lpv/renderer/SceneAnalysis.h"

namespace lpv::renderer {

// Spot and point lights the LPV can inject (lit, among the shaded lights).
int injectableLocalLights(const scene::Scene& scene);

// "Local-light RSM": runs when the scene has a spot or point light (lpv.localLights auto/on/off).
EffectDecision decideLocalLightInjection(const scene::Scene& scene, const scene::ParameterSet& params);
// "Emissive VPLs": runs when a visible material emits (lpv.emissive auto/on/off).
// `worldMagnitude`: scene::liesOnAnAreaLight's, for a scene in render space.
EffectDecision decideEmissiveInjection(const scene::Scene& scene, const scene::ParameterSet& params,
                                       float worldMagnitude = 0.0f);
// "LPV bounces": more than one when lpv.bounces > 1 and the LPV runs.
EffectDecision decideBounces(const scene::ParameterSet& params, bool lpvRuns);

} // namespace lpv::renderer
