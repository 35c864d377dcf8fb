#pragma once
// "Simulate only what the scene calls for" (DESIGN.md): for each effect, the
// decision whether its passes run, and the reason in words, from the scene's
// contents and the parameter that can force it (auto/on/off). The editor's
// Effects panel and `lpv render` show these decisions.
#include "lpv/scene/Camera.h"
#include "lpv/scene/ParameterRegistry.h"
#include "lpv/scene/Scene.h"

#include <string>
#include <vector>

namespace lpv::renderer {

struct EffectDecision {
    std::string effect;    // display name, e.g. "Sky light injection"
    std::string parameter; // the registry key that forces it, e.g. "effects.skyInjection"
    std::string setting;   // that parameter's value: "auto", "on", "off" (or "true"/"false")
    bool wanted = false;   // the decision: the scene calls for it (or the setting forces it)
    bool implemented = true; // false: the pass does not exist yet, so it does not run whatever the decision
    std::string reason;

    bool runs() const { return wanted && implemented; }
};

// What the scene's geometry says, computed once per scene change (it casts rays).
struct SceneTraits {
    bool hasDirectionalLight = false;
    bool hasTranslucentMaterial = false; // translucency > 0 on a material a visible object draws with
    bool hasGlossyMaterial = false;      // glossiness > 0 likewise
    // Share of vertical probe columns where the sky reaches the ground
    // (0 = closed room, near 1 = open ground); see SceneAnalysis.cpp.
    float openSkyFraction = 0.0f;
    int skyProbes = 0;
    // The largest glossiness of a visible material (auto compares it with effects.glossyThreshold).
    float maxGlossiness = 0.0f;
    // The scene's world bounds, which the LPV's fit needs (LpvFit.h): walked
    // once here, not on every camera move of the Effects dock.
    scene::Bounds bounds;
};

// A share of open sky above which `auto` injects sky light.
inline constexpr float kOpenSkyThreshold = 0.05f;

SceneTraits analyseSceneTraits(const scene::Scene& scene);

// gi.method is lpv: the indirect passes may run (off and reference draw
// direct light only, radiosity a baked solution's indirect light).
bool giMethodRuns(const scene::ParameterSet& params);
// Why they do not: "gi.method is off", "gi.method is radiosity".
std::string giMethodOffReason(const scene::ParameterSet& params);
// The same, with what lights the frame instead: "gi.method is off: direct
// light only", "gi.method is radiosity: the indirect light is a baked solution's".
std::string giMethodLpvOffReason(const scene::ParameterSet& params);

// gi.method is radiosity: a program loads the project's solution for the renderer.
bool showsBakedRadiosity(const scene::ParameterSet& params);

// gi.method = radiosity: a baked solution (radiosity::loadBakedSolution) is
// drawn as the indirect light. The renderer's decision, given the solution
// it was handed (`patches` 0: none, and the frame has direct light only).
EffectDecision decideBakedRadiosity(const scene::ParameterSet& params, std::size_t patches, double residual);

// The first directional light (the sun, as the RSM picks it), or null.
const scene::Light* sunOf(const scene::Scene& scene);

// The sun rays' decision alone: cheap, so the renderer makes it every frame.
EffectDecision decideSunRays(const scene::Scene& scene, const scene::ParameterSet& params, const scene::Camera* camera,
                             float aspect);

// Sky light injection's decision alone (the renderer makes it every frame from cached traits).
EffectDecision decideSkyInjection(const scene::Scene& scene, const SceneTraits& traits,
                                  const scene::ParameterSet& params);
// Directed propagation's decision, given whether the LPV runs.
EffectDecision decideDirectedPropagation(const scene::ParameterSet& params, bool lpvRuns,
                                         const std::string& lpvReason);

// The subsurface LPV's decision, given whether the LPV runs (it is a second
// volume set fed by the same RSM, so it needs the LPV).
EffectDecision decideSubsurface(const SceneTraits& traits, const scene::ParameterSet& params, bool lpvRuns,
                                const std::string& lpvReason);
// Glossy LPV reflections' decision, given whether the LPV runs (they march through it).
EffectDecision decideGlossyReflections(const SceneTraits& traits, const scene::ParameterSet& params,
                                       bool lpvRuns, const std::string& lpvReason);

// lpv.lookupResolution (issue #48): the LPV's diffuse lookup once per
// `reduction` x `reduction` pixels (1 full, 2 half, 4 quarter), and why.
struct LookupResolutionDecision {
    int reduction = 1;
    std::string reason;
};
// `auto` takes the cheapest resolution that measured within the path-traced
// reference's noise of the full lookup (docs/renderer.md, "The lookup at
// reduced resolution"): a reduced lookup only where a cell of the LPV spans
// enough pixels of this view for its texels to stay well inside a cell, and
// where the view has enough pixels per triangle to pay for the extra draws of
// the scene (the low-resolution lookup's two and the resolve's one).
LookupResolutionDecision decideLookupResolution(const scene::ParameterSet& params, int viewWidth, int viewHeight,
                                                float fovY, std::size_t triangles);

// The decisions for every effect; `camera` (may be null) decides the sun rays (sun on screen).
std::vector<EffectDecision> decideEffects(const scene::Scene& scene, const SceneTraits& traits,
                                          const scene::ParameterSet& params, const scene::Camera* camera,
                                          float aspect = 16.0f / 9.0f);

} // namespace lpv::renderer
