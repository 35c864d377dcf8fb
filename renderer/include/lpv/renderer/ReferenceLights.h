#pragma once
// Which lights the path-traced reference traces, so that it measures the
// renderer like for like (issue #22): `reference.skyLight` and
// `reference.emissiveLight` on `auto` follow what the LPV injects. The sky
// lights the reference where the LPV injects sky light (effects.skyInjection
// and the open-sky probe decide), emissive surfaces where the LPV injects
// their VPLs (lpv.emissive). `on`/`off` force them. The decisions are made
// as if gi.method were `lpv`: a reference measures the LPV even while the
// viewport shows direct light only.
#include "lpv/renderer/SceneAnalysis.h"

namespace lpv::renderer {

struct ReferenceLights {
    bool sky = false;
    bool emissive = false;
    std::string skyReason;      // "auto: the LPV injects sky light (...)", "forced off by reference.skyLight"
    std::string emissiveReason;
};

ReferenceLights decideReferenceLights(const scene::Scene& scene, const SceneTraits& traits,
                                      const scene::ParameterSet& params);

} // namespace lpv::renderer
