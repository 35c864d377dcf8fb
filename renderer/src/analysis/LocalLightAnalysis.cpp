#include "lpv/renderer/LocalLightAnalysis.h"

#include "passes/lpv/LocalRsmPass.h"
#include "lpv/renderer/SceneAnalysis.h"
#include "lpv/scene/AreaLight.h"

#include <algorithm>
#include "lpv/renderer/lpv/EmissiveVpls.h"

namespace lpv::renderer {

int injectableLocalLights(const scene::Scene& scene) {
    return int(selectInjectedLocalLights(scene).size());
}

EffectDecision decideLocalLightInjection(const scene::Scene& scene, const scene::ParameterSet& params) {
    EffectDecision d;
    d.effect = "Local-light RSM";
    d.parameter = "lpv.localLights";
    d.setting = params.getEnum(d.parameter);
    const std::vector<int> injected = selectInjectedLocalLights(scene);
    const int lights = int(injected.size());
    // Names the lights, so a user sees which lamp feeds the LPV (at most 4 are injected).
    std::string names;
    for (int i : injected) {
        const scene::Light& l = scene.lights[std::size_t(i)];
        names += (names.empty() ? "" : ", ") + l.name +
                 (l.type == scene::LightType::Point ? " (point)" : l.type == scene::LightType::Area ? " (area)" : " (spot)");
    }
    const std::string found =
        names + " injected through " + std::to_string(params.getInt("lpv.localRsmSize")) + "^2 RSM face" +
        (lights == 1 && scene.lights[std::size_t(injected[0])].type == scene::LightType::Spot ? "" : "s");
    if (!giMethodRuns(params)) {
        d.reason = giMethodOffReason(params);
    } else if (d.setting == "off") {
        d.reason = "forced off by lpv.localLights";
    } else if (lights == 0) {
        d.reason = d.setting == "on"
                       ? "forced on by lpv.localLights, but the scene has no lit spot, point or area light"
                       : "no spot, point or area light with a positive intensity";
    } else if (params.getFloat("lpv.intensity") <= 0.0) {
        d.reason = "lpv.intensity is 0";
    } else {
        d.wanted = true;
        d.reason = found;
    }
    return d;
}

EffectDecision decideEmissiveInjection(const scene::Scene& scene, const scene::ParameterSet& params,
                                       float worldMagnitude) {
    EffectDecision d;
    d.effect = "Emissive VPLs";
    d.parameter = "lpv.emissive";
    d.setting = params.getEnum(d.parameter);
    const bool emissive = lpvref::sceneHasEmissiveSurface(scene, worldMagnitude);
    if (!giMethodRuns(params)) {
        d.reason = giMethodOffReason(params);
    } else if (d.setting == "off") {
        d.reason = "forced off by lpv.emissive";
    } else if (!emissive) {
        // Emitting triangles that are an area light's visible surface are that light (no double counting).
        bool lampSurfaces = false;
        for (const scene::Material& m : scene.materials)
            lampSurfaces |= std::max({m.emissive.r, m.emissive.g, m.emissive.b}) > 0.0f;
        const std::string why = lampSurfaces && scene::hasAreaLight(scene.lights)
                                    ? "every emissive surface is an area light's visible surface (injected as that light)"
                                    : "no visible material emits";
        d.reason = d.setting == "on" ? "forced on by lpv.emissive, but " + why : why;
    } else if (params.getFloat("lpv.intensity") <= 0.0) {
        d.reason = "lpv.intensity is 0";
    } else {
        d.wanted = true;
        d.reason = "a visible material emits: its triangles are sampled as VPLs";
    }
    return d;
}

EffectDecision decideBounces(const scene::ParameterSet& params, bool lpvRuns) {
    EffectDecision d;
    d.effect = "LPV bounces";
    d.parameter = "lpv.bounces";
    const int bounces = params.getInt("lpv.bounces");
    d.setting = std::to_string(bounces);
    d.wanted = lpvRuns && bounces > 1;
    d.reason = bounces <= 1 ? "one bounce (lpv.bounces = 1)"
               : lpvRuns    ? std::to_string(bounces - 1) + " more bounce" + (bounces > 2 ? "s" : "") +
                               " re-injected at the geometry volume's surfels"
                         : "the LPV does not run";
    if (d.wanted && params.getInt("lpv.shBands") == 3) { // issue #47: LpvSettings turns them off too
        d.wanted = false;
        d.reason += "; but lpv.shBands = 3: bounces re-inject two bands only";
    }
    return d;
}

} // namespace lpv::renderer
