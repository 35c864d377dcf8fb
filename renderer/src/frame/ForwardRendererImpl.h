#pragma once
// ForwardRenderer's state between frames, and the frame as a graph of
// passes (graph/FrameGraph.h). Each frame render() plans the indirect light
// (which effects the scene calls for), lets every pass of the table
// (PassTable.cpp) declare itself with its resources, then compiles and
// executes the graph. The passes live in their own files (FramePass.h) and
// read the frame's FrameState; the renderer keeps typed views of those it
// asks for read-backs, dumps and counters, and the LPV's volumes, which the
// plan fits before the graph is built and its stages share.
#include "frame/FrameContext.h"
#include "frame/FramePass.h"
#include "frame/FrameResources.h"
#include "frame/FrameState.h"
#include "graph/ContentHash.h"
#include "graph/FrameGraph.h"
#include "lpv/renderer/ForwardRenderer.h"
#include "lpv/renderer/lpv/SceneGeometryVolume.h"
#include "passes/direct/ExposureFramePass.h"
#include "passes/direct/ShadingPass.h"
#include "passes/direct/ShadowMapsFramePass.h"
#include "passes/direct/TonemapPass.h"
#include "passes/lpv/EmissiveVplsFramePass.h"
#include "passes/lpv/LocalRsmFramePass.h"
#include "passes/lpv/LpvPass.h"
#include "passes/lpv/RsmFramePass.h"
#include "passes/lpv/SkyHeightFramePass.h"
#include "passes/lpv/SubsurfaceFramePass.h"
#include "scenegpu/MaterialGpu.h"
#include "scenegpu/RenderSpace.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace lpv::renderer {

struct ForwardRenderer::Impl {
    const TonemapPass* tonemap = nullptr; // in `passes`: blitTo shows its display image
    ShadingPass* shading = nullptr;       // in `passes`: its camera statistics and cascade tint
    const ShadowMapsFramePass* shadows = nullptr; // in `passes`: shading samples its maps
    const RsmFramePass* rsm = nullptr; // in `passes`: the LPV injects its tiles
    // The LPV's volumes and kernels (not a pass: planIndirect fits them before
    // the graph is built, and its stages, LpvStages.h, share them).
    std::optional<LpvPass> lpv;
    // Passes that run only when the scene calls for them are created on
    // their first frame and dropped when culled: they hold no GPU memory then.
    ExposureFramePass* exposure = nullptr; // in `passes`: its result stays on the GPU
    const SkyHeightFramePass* skyHeight = nullptr; // in `passes`: the sky injection reads its map
    const SubsurfaceFramePass* subsurface = nullptr; // in `passes`: shading samples its volume
    const LocalRsmFramePass* localRsm = nullptr; // in `passes`: the LPV injects its faces
    const EmissiveVplsFramePass* emissiveVpls = nullptr; // in `passes`: the LPV injects its VPLs
    // gi.method = radiosity: the solution given (setBakedRadiosity), and a
    // number that changes with it (part of the pass's reuse key).
    std::shared_ptr<const radiosity::BakedSolution> baked;
    std::uint64_t bakedGeneration = 0;
    // What the scene's geometry says (open sky...): rays are cast once per scene change.
    std::optional<SceneTraits> traits;
    // Bumped on every scene change: part of every reuse key.
    std::uint64_t sceneGeneration = 0;
    // The scene as the passes see it (RenderSpace.h), and its bounds there;
    // worldBounds is scene.worldBounds() of sceneGeneration (it walks every vertex).
    RenderSpace space;
    scene::Bounds worldBounds;
    scene::Bounds sceneBounds;
    std::uint64_t sceneBoundsGeneration = ~std::uint64_t(0);
    // Moves `world`'s objects, lights and sky into render space (per frame:
    // lights change without a new generation) and updates the bounds.
    const scene::Scene& enterRenderSpace(const scene::Scene& world);
    mutable std::optional<LpvSnapshot> worldSnapshot; // lpvSnapshot() in world space
    // The LPV fitted to the scene (LpvFit.h): this frame's fit, what it
    // means for the light delivered, and the parameters every pass of the
    // frame reads (the fit written in).
    LpvFit lpvFit;
    LpvDelivery lpvDelivery;
    scene::ParameterSet frameParams;
    std::uint64_t gBufferSceneGeneration = 0; // the scene the camera G-buffer shows
    std::vector<EffectDecision> frameEffects;
    std::unique_ptr<SceneGpu> sceneGpu;
    std::unique_ptr<MaterialGpu> materialGpu;
    GpuTimer timer;
    graph::FrameGraph graph;
    // The camera G-buffer as the last frame left it: the geometry volume
    // reads it before this frame's shading overwrites it.
    bool gBufferValid = false;
    LpvCameraInput previousCamera;
    // The scene's geometry volume (lpv.geometrySource = scene), sampled on the
    // CPU per object: an edit samples again only the objects it moved, hid or
    // added; setScene empties it (other meshes). Each frame that recomputes
    // the GV cuts the cascades' windows of it (sceneGeometry).
    lpvref::SceneGvCache sceneGvCache;
    LpvSceneGeometry sceneGeometry;
    int width = 0, height = 0;

    // The indirect light this frame calls for, decided before the graph is built.
    struct IndirectPlan {
        bool lpvRuns = false;
        std::string lpvOffReason;
        bool sun = false;
        EffectDecision local, emissive, sky, sss;
        LpvSettings settings;
        std::vector<LpvCascade> cascades;    // the LPV's: min(lpv.cascades, rsm.cascades)
        std::vector<LpvCascade> rsmCascades; // the sun's RSM tiles': rsm.cascades, the LPV's first
        bool cameraGv = false; // the geometry volume reads last frame's camera G-buffer
        EffectDecision radiosity; // gi.method = radiosity with a solution: the baked indirect light
    } plan;

    // The frame's passes in declaration order (PassTable.cpp): each adds
    // itself to the graph every frame.
    std::vector<std::unique_ptr<FramePass>> passes;
    scene::Expected<void> buildPassTable();

    // CameraTargets.cpp
    scene::Expected<void> checkSize(int w, int h) const;
    void declareCameraTargets(const FrameContext& frame);

    // IndirectPlan.cpp
    scene::Expected<void> planIndirect(const FrameContext& frame);
    // The plan as the LPV's stages read it.
    LpvStageInputs lpvStageInputs(const FrameContext& frame);
    // Passes the graph culled free what they hold.
    void releaseCulled();
    LpvRsmInput rsmInput(const FrameContext& frame) const;
    // This frame's cascades' windows of the scene's geometry volume, building it first if the scene changed.
    const LpvSceneGeometry& sceneGeometryFor(const FrameContext& frame);
    std::vector<LpvLocalInput> localInputs() const;

    // FrameDumps.cpp
    std::vector<DebugImage> dump(const std::string& name) const;
    std::vector<DebugImage> dumpResource(const std::string& name) const;
    std::vector<std::string> dumpNames() const;
};

} // namespace lpv::renderer
