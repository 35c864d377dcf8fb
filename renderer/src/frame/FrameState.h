#pragma once
// What the frame's passes share while one frame is declared and run
// (Filament's blackboard): the frame, its graph, and the plan the renderer
// made before declaring it. Built by ForwardRenderer::render; a pass's
// setup() and execute() read it, never the renderer.
#include "frame/FrameContext.h"
#include "graph/FrameGraph.h"
#include "lpv/renderer/SceneAnalysis.h"
#include "lpv/renderer/SceneGpu.h"
#include "passes/lpv/LpvStages.h"
#include "scenegpu/MaterialGpu.h"

#include <cstdint>
#include <vector>

namespace lpv::radiosity {
struct BakedSolution;
}

namespace lpv::renderer {

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
    // output.depthPrepass: the camera's depth is drawn before shading.
    bool depthPrepass = false;
    // gi.method = radiosity: the decision, and the solution with a number that changes with it.
    EffectDecision radiosity;
    const radiosity::BakedSolution* baked = nullptr;
    std::uint64_t bakedGeneration = 0;
    // The LPV's stages (LpvStages.h), and the subsurface LPV's decision.
    LpvStageInputs lpv;
    EffectDecision subsurface;
};

} // namespace lpv::renderer
