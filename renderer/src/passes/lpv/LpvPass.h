#pragma once
// Cascaded Light Propagation Volumes on the GPU (docs/lpv.md is the maths,
// lpvref::* in LpvReference.h the CPU twin the tests compare with).
//
// One frame: the brightest RSM texel per tile (fixed-point scale), VPL
// injection ("lpvInjection"), geometry volume from the RSM and the previous
// frame's camera G-buffer ("geometryVolume"), then lpv.propagationSteps steps
// per cascade in one of four variants ("lpvPropagation"), summed into
// accumulators that the forward pass samples (bindForShading).
#include "frame/FrameContext.h"
#include "passes/lpv/LpvVolumes.h"
#include "gl/ProgramCache.h"
#include "passes/lpv/RsmCascades.h"
#include "lpv/renderer/ForwardRenderer.h"
#include "lpv/renderer/GlHandle.h"
#include "lpv/renderer/LpvSnapshot.h"
#include "lpv/scene/Error.h"

#include <glm/glm.hpp>

#include <array>
#include <map>
#include <optional>
#include <string>
#include <algorithm>
#include <vector>

namespace lpv::renderer {

class GpuMemoryLedger;

enum class LpvVariant { ComputeGather, ComputeScatter, RasterGather, RasterScatter };
// "computeGather" ... (the lpv.variant choices); nullopt for anything else.
std::optional<LpvVariant> lpvVariantFromName(const std::string& name);
const char* lpvVariantName(LpvVariant variant);

struct LpvSettings {
    int gridSize = 32;
    // lpv.shBands (issue #47): 3 runs in the compute gather only; prepare()
    // refuses it for the other variants and for a reduced-resolution lookup.
    // With 3, fromParameters turns off what reads or writes two bands only
    // (bounces, the visibility-aware lookup) and says so in threeBandsNote.
    int shBands = 2;
    std::string threeBandsNote;
    bool reducedLookup = false; // lpv.lookupResolution is half or quarter
    int propagationSteps = 8;
    // lpv.cascadeSteps = byCellSize: cascade k runs propagationSteps >> k steps
    // (at least 1): cells twice as large carry light twice as far per step.
    bool stepsByCellSize = false;
    float injectionOffset = 1.0f; // cells
    bool occlusion = true;
    // lpv.occlusionFirstStep: false = the first step ignores the GV (no
    // self-occlusion by the surface that injected the light).
    bool occludeFirstStep = true;
    // lpv.occlusionStrength: blocking potential scale (1, as lpvref::GvGrid
    // and the registry have it).
    float occlusionStrength = 1.0f;
    // lpv.twoSidedOcclusion: a surfel blocks light from both sides.
    bool twoSidedOcclusion = false;
    // lpv.geometrySource = scene: the GV is the scene's own (LpvSceneGeometry),
    // not the RSM's and the camera's surfels; views (false) here for the
    // tests that build settings by hand.
    bool gvFromScene = false;
    bool gvFromCamera = true;
    // lpv.gvCameraStride: the camera G-buffer gives one surfel per stride x
    // stride pixels (the block's middle pixel, stride^2 its area).
    int gvCameraStride = 1;
    LpvVariant variant = LpvVariant::ComputeGather;
    // Directed propagation (docs/lpv.md): a normals volume from the VPLs,
    // dilated this many cells, keeps light from flowing back into its emitter.
    bool directed = false;
    int directedDilation = 1;
    // Multi-bounce (docs/lpv.md): 1 = the VPLs' light only; each further
    // bounce re-injects the last one's light at geometry-volume surfels.
    int bounces = 1;
    float bounceAlbedo = 0.5f;
    // lpv.cascades and rsm.cascades as set: the volumes are as many as there
    // are RSM tiles, and an error about them names both (issue #29).
    int requestedCascades = 4;
    int rsmCascades = 4;
    // lpv.visibilityLookup (docs/lpv.md): distance moments built after the
    // geometry volume, read by the lookup; needs the GV (occlusion or bounces).
    bool visibility = false;

    // The geometry volume runs for occlusion, and for bounces (they reflect at its surfels).
    bool geometryVolumeRuns() const { return occlusion || bounces > 1; }
    // The visibility moments are built from the geometry volume, so only while it runs.
    bool visibilityRuns() const { return visibility && geometryVolumeRuns(); }
    // Whether propagation step `step` reads the GV (lpv.occlusionFirstStep).
    bool occludesStep(int step) const { return occlusion && (step > 0 || occludeFirstStep); }

    // The steps cascade `cascade` propagates.
    int stepsFor(int cascade) const {
        if (!stepsByCellSize || propagationSteps == 0)
            return propagationSteps;
        return std::max(1, propagationSteps >> std::min(cascade, 30));
    }
    // How many cascades, from the finest, still propagate at `step` (never
    // more coarse than fine: stepsFor does not grow with the cascade).
    int cascadesAtStep(int step, int cascades) const {
        int active = 0;
        while (active < cascades && step < stepsFor(active))
            ++active;
        return active;
    }

    static LpvSettings fromParameters(const scene::ParameterSet& params);
};

// What the LPV reads: RSM tiles (2D arrays, layer k = cascade k) and,
// optionally, a camera G-buffer.
struct LpvRsmInput {
    std::vector<LpvCascade> cascades; // one per tile
    std::vector<float> texelArea;     // per tile, world units^2 on a plane facing the sun
    int tileSize = 0;
    GLuint position = 0, normal = 0, flux = 0; // formats as RsmPass writes them
    glm::vec3 towardSun{0.0f, 1.0f, 0.0f};
};
struct LpvCameraInput {
    GLuint depth = 0, normal = 0; // DEPTH_COMPONENT32F, RGBA16F (w > 0 where a surface was seen)
    glm::mat4 inverseViewProj{1.0f};
    glm::vec3 position{0.0f};
    float pixelAngle = 0.0f; // 2 tan(fovY / 2) / height
};

// The scene's geometry volume (lpv.geometrySource = scene; lpvref::SceneGv):
// per cascade, in order, its (N+1)^3 GV cells (lpvref::windowOf), x fastest.
struct LpvSceneGeometry {
    std::vector<glm::vec4> windows;
    // Three bands: band 2 of the same cells, 2 per cell (lpvref::windowBand2Into); empty for two.
    std::vector<glm::vec4> windowsHigh;
    std::size_t surfels = 0; // sampled for the finest level (the note says it)
};

// Sky light injection: a top-down depth map of the scene (SkyHeightPass) and
// the sky's radiance (docs/lpv.md).
struct LpvSkyInput {
    GLuint depth = 0;          // 2D array of 1 layer, DEPTH_COMPONENT32F, size x size; 1 = no surface
    int size = 0;
    glm::vec2 min{0.0f};       // world x, z of texel (0, 0)'s corner
    float texelSize = 1.0f;
    float top = 1.0f, bottom = 0.0f; // world heights of depth 0 and depth 1
    glm::vec3 radiance{0.0f};
};

// VPLs not tied to a cascade (docs/lpv.md "Local lights, emissive surfaces and
// bounces"): spot and point lights' RSM faces (LocalRsmPass) and emissive
// surfaces' samples (EmissiveVplBuffer). Every texel with w = 1 in `position`
// is injected into every cascade that holds it.
struct LpvLocalInput {
    GLuint position = 0, normal = 0, flux = 0; // 2D arrays in RsmPass's formats (or RGBA32F), one layer per face
    int size = 0, layers = 0;
    std::string label; // for the note, e.g. "1 local-light RSM face"
};

// ", 1 local-light RSM face injected, ..." for LpvPass's note.
std::string localNote(const std::vector<LpvLocalInput>& local);

class LpvPass {
  public:
    // Builds no program: each kernel compiles on first use (prepare() builds those the settings select).
    static scene::Expected<LpvPass> create();
    // Kernels compiled so far (tests: a variant never selected is never compiled).
    std::size_t builtKernels() const { return programs_.size(); }

    // The LPV as the frame graph runs it (ForwardRenderer): prepare() fits
    // the volumes to this frame's settings and cascades before the graph
    // runs (an error names the parameter that does not fit); each stage is
    // one graph pass, updating the volumes in place; finish() writes the note.
    scene::Expected<void> prepare(const LpvSettings& settings, const std::vector<LpvCascade>& cascades);
    void injectStage(const LpvRsmInput& rsm, const std::vector<LpvLocalInput>& local, bool directed);
    void skyStage(const LpvSkyInput& sky);
    void normalsStage(int dilation);
    // With `sceneGeometry` the GV is its windows, and the RSM and the camera add nothing.
    void geometryStage(const LpvRsmInput& rsm, const LpvCameraInput* camera,
                       const LpvSceneGeometry* sceneGeometry = nullptr);
    void propagationStage(const LpvSettings& settings);
    void bounceStage(const LpvSettings& settings);
    void finish(const LpvSettings& settings, bool cameraGv, bool sky, const std::vector<LpvLocalInput>& local);
    // Bumped whenever the volumes are (re)allocated or freed: outputs of older generations are gone.
    std::uint64_t volumesGeneration() const { return volumes_.generation(); }

    // All stages at once, outside a graph (tests and tools): the stages of
    // LpvStages.h, each run when its own declaration says so, timed under
    // its pass name.
    // `sky` (may be null): inject sky light as well. `local`: spot and point
    // lights' and emissive surfaces' VPLs as well; with them, `rsm` may hold
    // cascades but no tiles (position 0, tileSize 0): a scene without a sun.
    scene::Expected<void> run(const LpvSettings& settings, const LpvRsmInput& rsm, const LpvCameraInput* camera,
                              GpuTimer& timer, const LpvSkyInput* sky = nullptr,
                              const std::vector<LpvLocalInput>& local = {},
                              const LpvSceneGeometry* sceneGeometry = nullptr);
    // Nothing to inject (no sun): frees the volumes, shading reads no LPV.
    void disable(std::string reason);
    // Nothing the LPV is computed from changed: keep the volumes as they are.
    void reuse();

    bool active() const { return active_; }
    // Whether shading reads the visibility moments this frame (bindForShading sets uLpvVisibility).
    bool visibilityBound() const { return active_ && visibilityActive_ && visibilityReady_; }
    // One line: what ran and why (or why not), e.g. for `lpv render`.
    const std::string& note() const { return note_; }

    // Sets lpv_lookup.glsl's uniforms and binds the three accumulators to units from `nextUnit`.
    void bindForShading(const CachedProgram& program, const scene::ParameterSet& params, const UnitAllocator& nextUnit) const;

    // Read-back for tests and dumps: per channel N^3 SH of cascade k.
    std::array<std::vector<glm::vec4>, 3> readAccumulator(int cascade) const;
    // Three bands (lpv.shBands = 3): per channel N^3 cells of 9 coefficients
    // (ShBands.h's order), and the GV's (N+1)^3 cells of 9; empty otherwise.
    std::array<std::vector<std::array<float, 9>>, 3> readAccumulatorBands(int cascade) const;
    std::vector<std::array<float, 9>> readGeometryVolumeBands(int cascade) const;
    std::vector<glm::vec4> readGeometryVolume(int cascade) const; // (N+1)^3, x fastest
    // The visibility-aware lookup's moments of cascade k, 3N x N x N (empty when off).
    std::vector<glm::vec4> readVisibilityMoments(int cascade) const;
    // "lpv-K-accum" (rgb = DC of each channel per cell, slices side by side) and "lpv-K-gv".
    std::vector<DebugImage> debugImages() const;
    std::size_t allocatedBytes() const { return volumes_.allocatedBytes(); }
    // Names its volumes (LpvVolumes::addGpuMemory) and the visualizers' copy
    // for ForwardRenderer::gpuMemory().
    void addGpuMemory(GpuMemoryLedger& ledger) const;
    // For passes that build on this frame's LPV (LpvSubsurfacePass): its
    // volumes (fixed-point sums and scales) and cascades (empty when inactive).
    const LpvVolumes& volumes() const { return volumes_; }
    const std::vector<LpvCascade>& cascades() const { return cascades_; }

    // The visualizers' read-back: while a request is set, every run() copies
    // that cascade's volumes at that step to the CPU (a GPU stall, so only
    // while a view is open); nullopt stops it and frees the copy.
    void setCapture(std::optional<LpvCaptureRequest> request);
    const std::optional<LpvSnapshot>& snapshot() const { return snapshot_; }
    bool capturing() const { return capture_.has_value(); }
    // The cascades of the last run (empty when inactive).
    std::vector<LpvGridFrame> cascadeFrames() const;

  private:
    LpvPass() = default;
    void inject(const LpvRsmInput& rsm, bool directed, const std::vector<LpvLocalInput>& local);
    // Local lights' share of inject() (LpvPassLocal.cpp): their brightest texel
    // into every cascade's bound, then their VPLs into the fixed-point sums.
    void localFluxMax(const LpvLocalInput& local);
    void injectLocal(const LpvLocalInput& local, bool directed);
    void injectGeometry(const LpvRsmInput& rsm, const LpvCameraInput* camera, const LpvSceneGeometry* sceneGeometry);
    void injectViews(const LpvRsmInput& rsm, const LpvCameraInput* camera);
    // The visibility-aware lookup's moments from the GV (lpv_visibility.comp).
    void buildVisibility();
    void propagate(const LpvSettings& settings);
    // Directed propagation: the injected normal sums to averages, then dilated.
    void buildNormals(int dilation);
    void injectSky(const LpvSkyInput& sky);
    // Bounces 2.. lpv.bounces after the first propagation (LpvBounce.h is the CPU twin).
    void propagateBounces(const LpvSettings& settings);
    void addBounceTotal(bool final);
    // Fixed-point sums to floats into volume `destination` and the accumulator,
    // decoded with the scale of `scaleSlot` (-1: injection); the result's
    // largest coefficient goes to `recordSlot` (lpv_common.glsl).
    void resolveSums(int destination, bool accumulate, int scaleSlot, int recordSlot);
    void setCascadeUniforms(GLuint program) const;
    void bindStepImages(int destination) const;
    void bindStepSources(GLuint program, int source, bool occlusion) const;
    // The compute gather's interleaved[index] into volume[index] (lpv_deinterleave.comp).
    void deinterleave(int index);
    // At the requested step: copies volume `index` (V_step) and the
    // accumulator of the requested cascade on the GPU (no stall inside the
    // timed passes); readCapture() brings the copies and the GV to the CPU
    // once the frame's LPV work is timed.
    void captureIfRequested(int step, int index);
    void readCapture();

    // The LPV's kernels, each a shader variant built on first use (ProgramCache).
    enum class LpvKernel {
        FluxMax, Inject, Resolve, GvFromRsm, GvFromCamera, GvMerge, FaceBlocking, Normals, NormalsDilate,
        SkyInject, BounceInject, BounceAdd, LocalFluxMax, LocalInject,
        ComputeGather, ComputeGatherFirst, // the first step reads per-channel sources (LPV_FIRST_STEP)
        Deinterleave, ComputeScatter, RasterGather, RasterScatter, Visibility,
    };
    // lpv.shBands = 3 where it runs (the compute gather, a full-resolution lookup), else the error.
    static scene::Expected<void> refuseBands(const LpvSettings& settings);
    // With three bands the kernels that hold SH get the LPV_SH_BANDS 3 define.
    ProgramVariant variantOf(LpvKernel kernel) const;
    scene::Expected<void> buildKernel(LpvKernel kernel);
    // The kernels `settings` select, built now so a compile error is prepare()'s error value.
    scene::Expected<void> buildKernelsFor(const LpvSettings& settings);
    // A kernel's program id; one not built yet compiles here (an error throws std::logic_error).
    GLuint kernel(LpvKernel kernel);
    // A uniform's location, looked up once per kernel and name.
    GLint loc(GLuint program, const char* name) const;
    ProgramCache programs_;
    std::map<GLuint, const CachedProgram*> byId_;
    VertexArray emptyVao_;
    LpvVolumes volumes_;
    std::vector<LpvCascade> cascades_;
    bool active_ = false;
    int bands_ = 2;     // lpv.shBands of this frame (prepare)
    int readIndex_ = 0; // volume holding the last step's result
    int normalsIndex_ = -1; // normals texture the propagation reads; -1: undirected
    int scaleSlot_ = 0; // scale slot of the volume at readIndex_ (compute scatter)
    int tileSize_ = 0;  // of this frame's RSM
    int injectedTexels_ = 0; // the sun's tile and every local face: the fixed-point bound counts them
    float injectionOffset_ = 1.0f;
    int gvCameraStride_ = 1;
    std::size_t sceneSurfels_ = 0; // the scene GV's finest-level surfels this frame; 0: the GV came from the views
    bool occlusion_ = true;
    float occlusionStrength_ = 1.0f;
    bool twoSidedOcclusion_ = false;
    int propagationSteps_ = 0;
    bool visibilityActive_ = false; // lpv.visibilityLookup on and a GV to build it from
    bool visibilityReady_ = false;  // the moments hold the current GV's (false after allocation)
    std::optional<LpvCaptureRequest> capture_;
    std::optional<LpvSnapshot> snapshot_;
    std::array<Texture, 6> captureCopy_; // N^3 per channel: V_step (0-2), accumulator (3-5); only while capturing
    int captureGrid_ = 0;
    int capturedStep_ = -1; // -1: nothing copied this frame
    bool bouncing_ = false; // propagating bounce 2 or later: the visualizers capture the first bounce
    std::string note_ = "LPV: not run yet";
    std::string computedNote_; // what the last computed frame ran
};

} // namespace lpv::renderer
