#pragma once
// What the frame's passes share while one frame is declared and run
// (Filament's blackboard): the frame, its graph, and the plan the renderer
// made before declaring it. Built by ForwardRenderer::render; a pass's
// setup() and execute() read it, never the renderer.
#include "frame/FrameContext.h"
#include "frame/IndirectLight.h"
#include "graph/ContentHash.h"
#include "graph/FrameGraph.h"
#include "lpv/renderer/SceneAnalysis.h"
#include "lpv/renderer/SceneGpu.h"
#include "lpv/scene/SceneFields.h"
#include "passes/direct/ShadowPass.h"
#include "passes/lpv/LpvStages.h"
#include "scenegpu/MaterialGpu.h"

#include <cstdint>
#include <vector>

namespace lpv::radiosity {
struct BakedSolution;
}

namespace lpv::renderer {

// What lighting a pass reads: every field the light's table hashes (all but
// its name, SceneFields.h), so a field added there is in every reuse key.
inline void addLights(graph::ContentHash& h, const std::vector<scene::Light>& lights) {
    h.add(lights.size());
    for (const scene::Light& l : lights)
        scene::hashFields(l, [&](const void* p, std::size_t n) { h.bytes(p, n); });
}

struct FrameState {
    const FrameContext& frame;
    graph::FrameGraph& graph;
    // The frame's effect decisions with their reasons, as the editor and the CLI show them.
    std::vector<EffectDecision>& effects;
    // The scene on the GPU, as the passes draw it.
    const SceneGpu* sceneGpu = nullptr;
    MaterialGpu* materialGpu = nullptr;
    // Bumped on every scene change: part of every reuse key.
    std::uint64_t sceneGeneration = 0;
    // What the scene's geometry says (open sky...), cast once per scene change.
    const SceneTraits* traits = nullptr;
    // output.depthPrepass: the camera's depth is drawn before shading.
    bool depthPrepass = false;
    // gi.method = radiosity: the decision, and the solution with a number that changes with it.
    EffectDecision radiosity;
    const radiosity::BakedSolution* baked = nullptr;
    std::uint64_t bakedGeneration = 0;
    // The LPV's stages (LpvStages.h), and the subsurface LPV's decision.
    LpvStageInputs lpv;
    EffectDecision subsurface;
    // The VPLs' sources besides the sun: spot and point lights' RSMs, emissive surfaces.
    EffectDecision localLights, emissive;
    // The sun's RSM tiles (rsm.cascades of them; the LPV's are the first).
    std::vector<LpvCascade> rsmCascades;
    // The shadow maps shading samples: the shadow maps pass's, set in its setup().
    const ShadowPass* shadowMaps = nullptr;
    // The indirect light shading adds, as the passes that compute it
    // declared it in their setup() (IndirectLight.h); shading reads them all.
    std::vector<IndirectLight> indirectLight{};

    // What a pass seen from the camera is computed from: the scene, its
    // lights, the camera's matrices and position, the target size.
    std::uint64_t cameraKey() const {
        graph::ContentHash h;
        h.add(sceneGeneration).add(frame.viewProj).add(frame.camera.position).add(frame.width).add(frame.height);
        addLights(h, frame.scene.lights);
        return h.value();
    }
};

} // namespace lpv::renderer
