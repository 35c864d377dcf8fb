#pragma once
#include <array>
// Shadow maps of one frame and what forward shading needs to sample them
// (shaders/shadow_sampling.glsl):
//  - the sun: shadow.cascades cascades (ShadowCascades.h) rendered in ONE pass
//    into the layers of a 2D-array depth texture (shadow.geom, invocation per layer);
//  - spot lights: one perspective layer each of a 2D-array texture;
//  - point lights: one cube of a cube-map array each, its six faces in one
//    pass; area lights one cube per quarter of their rectangle (ShadowLights.h).
// Spot and point maps store distance / far. At most kMaxShadowedLocalLights
// local lights are shadowed; nothing is allocated for lights the scene lacks.
#include "frame/FrameContext.h"
#include "scenegpu/MaterialGpu.h"
#include "gl/ProgramCache.h"
#include "passes/direct/ShadowCascades.h"
#include "passes/direct/ShadowLights.h"
#include "lpv/renderer/ForwardRenderer.h"
#include "lpv/renderer/GlHandle.h"
#include "lpv/renderer/SceneGpu.h"
#include "lpv/scene/Error.h"

#include <vector>

namespace lpv::renderer {

class GpuMemoryLedger;

class ShadowPass {
public:
    static scene::Expected<ShadowPass> create();

    // Renders the shadow maps of this frame. `contentKey` names what the maps
    // are drawn from besides the cascade matrices (scene, lights, map size):
    // a sun cascade whose key and matrix are unchanged keeps its layer.
    scene::Expected<void> render(const FrameContext& frame, const SceneGpu& geometry, const MaterialGpu& materials,
                                 std::uint64_t contentKey = 0);
    // Sun cascades drawn by the last render() (the others kept their layer).
    int cascadesDrawn() const { return cascadesDrawn_; }
    // Sun cascades shaded from a layer drawn for an earlier camera
    // (shadow.farCascadeInterval > 1): the next frames redraw them in turn.
    int staleCascades() const { return staleCascades_; }
    // 0 while no cascade is stale; otherwise changes every render(), so the
    // frame graph runs the pass again and the stale layers get their turn
    // even when the camera stays still.
    std::uint64_t refreshKey() const { return staleCascades_ > 0 ? cascadeFrame_ : 0; }

    // Sets the uniforms of shadow_sampling.glsl in `program` and binds its
    // six textures to units from `nextUnit`.
    void bindForShading(const CachedProgram& program, const FrameContext& frame, const UnitAllocator& nextUnit) const;

    // One image per cascade ("shadow-cascade-K", depth 0..1), per spot light
    // ("shadow-spot-K", distance / far) and per point-light cube face
    // ("shadow-point-K-FACE", distance / far) of the last frame.
    std::vector<DebugImage> debugImages() const;

    // The frame graph's view of the maps: the sun's cascades, else the spot
    // lights', else the point lights' (0 when nothing casts a shadow).
    GLuint primaryMap() const {
        return cascadeMap_.texture ? cascadeMap_.texture.id()
                                   : spotMap_.texture ? spotMap_.texture.id() : pointMap_.texture.id();
    }

    // Names its GL objects for ForwardRenderer::gpuMemory().
    void addGpuMemory(GpuMemoryLedger& ledger) const;

    // Whether the last render() gave any spot or point light a shadow map
    // (shading leaves their sampling code out otherwise: LPV_NO_LOCAL_SHADOWS).
    bool hasLocalShadows() const { return !lights_.spots.empty() || !lights_.points.empty(); }

    // The sun's cascades of the last frame (empty without a shadowed sun).
    const std::vector<ShadowCascade>& cascades() const { return cascades_; }

private:
    ShadowPass() = default;

    // A layered depth texture and its framebuffer, reallocated when its shape
    // changes. `texture` reads raw depth (blocker search); `compareView`, a
    // texture view of the same storage, compares with linear filtering (PCF).
    // Views rather than sampler objects, so no sampler state leaks into later passes.
    struct LayeredTarget {
        GLenum target = 0;
        int size = 0;
        int layers = 0;
        Texture texture;
        Texture compareView;
        Framebuffer fbo;
    };
    static scene::Expected<void> ensureTarget(LayeredTarget& t, GLenum target, int size, int layers);
    void drawLayers(GLuint program, const SceneGpu& geometry, const MaterialGpu& materials,
                    const std::vector<const DrawItem*>& items, const glm::mat4* viewProj, int layerCount,
                    int firstLayer) const;

    // The program for `layers` layers per draw (built on first use):
    // shadow.vert + shadow.geom + shadow.frag (depth) or shadow_distance.frag.
    scene::Expected<GLuint> programFor(bool distance, int layers, bool opaque = false);
    // shadow.cascadeDraws = perCascade: one draw list and one depth-only draw per cascade, no geometry shader.
    // `farInterval` > 1: the outer half of the cascades is redrawn only every
    // farInterval-th frame each, staggered, and shaded from the layer and
    // matrix it was drawn with in between.
    scene::Expected<void> drawCascadesOneByOne(const SceneGpu& geometry, const MaterialGpu& materials,
                                               std::uint64_t contentKey, int farInterval, const glm::vec3& sunDirection);
    // Whether far cascade k may keep the layer drawn for an earlier camera this frame.
    bool mayKeepFarCascade(std::size_t k, std::uint64_t contentKey, int farInterval, const glm::vec3& sunDirection) const;
    Program perCascadeProgram_;       // cuts alpha-masked holes (discard)
    Program perCascadeOpaqueProgram_; // opaque materials: never discards, so depth is tested early
    std::vector<std::uint64_t> cascadeKeys_; // per layer: what it holds (0: nothing known)
    std::vector<std::uint64_t> layerContent_; // per layer: the contentKey it was drawn with
    std::vector<ShadowCascade> drawnCascades_; // per layer: the cascade it was drawn for
    std::uint64_t cascadeFrame_ = 0;          // render() calls, for staggering far-cascade redraws
    int staleCascades_ = 0;
    GLuint cascadeMapId_ = 0;
    int cascadesDrawn_ = 0;
    std::array<Program, 8> depthPrograms_;
    std::array<Program, 8> opaqueDepthPrograms_; // SHADOW_OPAQUE: for the opaque draws
    std::array<Program, 8> distancePrograms_;

    ShadowLightSelection lights_;
    std::vector<ShadowCascade> cascades_;
    std::vector<LocalShadowView> spotViews_, pointViews_;
    std::vector<glm::vec3> spotPositions_, pointPositions_;
    float localLightRadius_ = 0.0f;
    std::vector<float> pointRadii_; // PCSS light radius per cube (area lights: unused)
    std::vector<int> pointFirstCube_; // per entry of lights_.points: its first cube (an area light has kAreaShadowCubes)
    LayeredTarget cascadeMap_, spotMap_, pointMap_;
};

} // namespace lpv::renderer
