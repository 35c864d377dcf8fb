#include "lpv/renderer/ReferenceLights.h"

#include <algorithm>

namespace lpv::renderer {
namespace {

// The reference's choice for one light kind: on/off forced, auto from the LPV's decision.
bool decide(const std::string& setting, const std::string& key, const EffectDecision& lpvDecision,
            std::string& reason) {
    if (setting == "on" || setting == "off") {
        reason = "forced " + setting + " by " + key;
        return setting == "on";
    }
    reason = std::string("auto: ") + (lpvDecision.wanted ? "the LPV injects it" : "the LPV does not inject it") +
             " (" + lpvDecision.reason + ")";
    return lpvDecision.wanted;
}

} // namespace

ReferenceLights decideReferenceLights(const scene::Scene& scene, const SceneTraits& traits,
                                      const scene::ParameterSet& params) {
    scene::ParameterSet asLpv = params;
    if (!giMethodRuns(asLpv))
        (void)asLpv.setFromText("gi.method", "lpv", "reference");
    const std::vector<EffectDecision> effects = decideEffects(scene, traits, asLpv, nullptr);
    auto find = [&](const char* key) {
        auto it = std::ranges::find(effects, std::string(key), &EffectDecision::parameter);
        return it != effects.end() ? *it : EffectDecision{};
    };
    ReferenceLights out;
    out.sky = decide(params.getEnum("reference.skyLight"), "reference.skyLight", find("effects.skyInjection"),
                     out.skyReason);
    out.emissive = decide(params.getEnum("reference.emissiveLight"), "reference.emissiveLight",
                          find("lpv.emissive"), out.emissiveReason);
    return out;
}

} // namespace lpv::renderer
