#pragma once
// "LPV: reused, nothing changed since the last frame" (DESIGN.md, scene
// analysis): everything the LPV of a frame is computed from. When this
// frame's key equals the last computed frame's, the volumes still hold the
// answer and injection, geometry volume and propagation are skipped
// (`lpv.reuse`, on by default; benchmarks turn it off).
#include "RsmCascades.h"
#include "lpv/scene/ParameterRegistry.h"
#include "lpv/scene/Scene.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace lpv::renderer {

struct LpvReuseKey {
    std::uint64_t sceneGeneration = 0;  // bumped when objects, materials or the scene change
    std::vector<scene::Light> lights;   // the sun (RSM) and the rest, by value
    scene::Sky sky;
    std::vector<scene::ParameterValue> parameters; // every parameter that invalidates an LPV pass
    std::vector<LpvCascade> cascades;   // where the volumes are (they follow the camera)
    bool cameraGv = false;              // the geometry volume also reads the camera's G-buffer ...
    glm::mat4 cameraInverseViewProj{1.0f}; // ... seen from here (only compared when cameraGv)
    std::uint64_t gBufferGeneration = 0;     // ... of the scene as it was (only compared when cameraGv)

    bool operator==(const LpvReuseKey&) const = default;
};

// The passes whose parameters make the LPV stale (the registry says which parameters invalidate which passes).
inline constexpr scene::Pass kLpvPasses = scene::Pass::Rsm | scene::Pass::LpvInjection |
                                          scene::Pass::GeometryVolume | scene::Pass::LpvPropagation |
                                          scene::Pass::SkyInjection | scene::Pass::Subsurface;

inline std::vector<scene::ParameterValue> lpvParameterValues(const scene::ParameterSet& params) {
    std::vector<scene::ParameterValue> values;
    for (const scene::ParameterInfo& info : scene::ParameterRegistry::instance().all())
        if (scene::any(info.invalidates, kLpvPasses))
            values.push_back(params.get(info.key));
    return values;
}

} // namespace lpv::renderer
