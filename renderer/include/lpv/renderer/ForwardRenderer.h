#pragma once
// One frame as a graph of passes (docs/renderer.md): shadow maps, the
// indirect light (RSMs, LPV stages; or a baked radiosity solution drawn from
// the camera, gi.method = radiosity), a forward pass that shades into HDR and
// writes the camera G-buffer (depth, normal, albedo) at the same time, then
// sun rays, exposure and tonemapping to sRGB. Each pass lives in its own
// file (ShadowPass, ...); the graph orders them, culls and reuses them.
#include "lpv/renderer/DrawList.h"
#include "lpv/renderer/FrameGraphReport.h"
#include "lpv/renderer/GpuMemory.h"
#include "lpv/renderer/GpuTimer.h"
#include "lpv/renderer/LpvFit.h"
#include "lpv/renderer/LpvSnapshot.h"
#include "lpv/renderer/SceneAnalysis.h"
#include "lpv/renderer/SceneGpu.h"
#include "lpv/scene/Image.h"
#include "lpv/scene/ParameterRegistry.h"
#include "lpv/scene/Scene.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace lpv::radiosity {
struct BakedSolution;
}

namespace lpv::renderer {

using scene::Expected;

// A float image of one pass's internals (a shadow cascade's depth, an RSM
// tile's flux...), rows top to bottom, for dumps, visualizers and tests.
struct DebugImage {
    std::string name; // e.g. "shadow-cascade-0", "rsm-1-flux"
    int width = 0;
    int height = 0;
    int channels = 0;
    std::vector<float> pixels;
};

class ForwardRenderer {
public:
    // Compiles every program; a shader that does not compile is an error value naming file and line.
    static Expected<ForwardRenderer> create();

    ForwardRenderer(ForwardRenderer&&) noexcept;
    ForwardRenderer& operator=(ForwardRenderer&&) noexcept;
    ~ForwardRenderer();

    // Uploads the scene's geometry, materials and the decoded textures its
    // materials name (a path missing from `textures` draws untextured); call
    // again after the scene changes.
    void setScene(const scene::Scene& scene, const scene::TextureImages& textures = {});

    // Cheaper updates after edits that keep the meshes: objects moved, hid
    // or were renamed (no geometry upload), or materials changed (materials
    // and textures re-uploaded, geometry kept). Both need setScene first.
    void updateObjects(const scene::Scene& scene);
    void updateMaterials(const scene::Scene& scene, const scene::TextureImages& textures = {});

    // gi.method = radiosity: the solution whose indirect light frames show
    // (radiosity::loadBakedSolution, checked against this scene by its
    // caller); null: none, and such frames have direct light only. Kept
    // until replaced; uploaded on the first frame that shows it.
    void setBakedRadiosity(std::shared_ptr<const radiosity::BakedSolution> solution);
    const radiosity::BakedSolution* bakedRadiosity() const;

    // Renders one frame into the internal HDR and display targets.
    Expected<void> render(const scene::Scene& scene, const scene::ParameterSet& params, const scene::Camera& camera,
                          int width, int height);

    // Copies the last display image into `framebuffer` (e.g. a QOpenGLWidget's).
    void blitTo(GLuint framebuffer, int width, int height) const;
    // Copies the rectangle [srcX0, srcX1) x [srcY0, srcY1) of the last display
    // image to [dstX0, dstX1) x [dstY0, dstY1) of `framebuffer`, filtered
    // linearly (the A/B split view's halves; a viewport rendered at reduced resolution).
    void blitRegionTo(GLuint framebuffer, int srcX0, int srcY0, int srcX1, int srcY1, int dstX0, int dstY0, int dstX1,
                      int dstY1) const;

    // Read-backs for tests and PNG output: rows top to bottom, RGBA.
    std::vector<float> readHdr() const;
    std::vector<std::uint8_t> readDisplay() const;
    // The camera G-buffer of the last frame, rows top to bottom: world normal
    // (xyz, w = 1 where geometry, 0 for background), albedo (rgb, a = coverage),
    // and window-space depth (0..1, 1 = background).
    std::vector<float> readGBufferNormal() const;
    std::vector<float> readGBufferAlbedo() const;
    std::vector<float> readDepth() const;
    // Internals of the last frame by the frame graph's names: an output
    // (rsm.flux, camera.depth, lpv.accumulator: per cascade the
    // accumulated DC per channel, slices side by side; shadowMaps: every
    // map and cascade) or a pass (rsm: all it wrote). Unknown, or not
    // produced this frame: empty.
    std::vector<DebugImage> debugImages(const std::string& what) const;
    // Every name debugImages() knows in the last frame: outputs, then passes.
    std::vector<std::string> dumpNames() const;
    // The last frame's graph: passes in execution order, what each read and
    // wrote, whether it ran, was reused or was culled, and why.
    const FrameGraphReport& graphReport() const;
    // The visualizers' LPV read-back (LpvSnapshot.h): while a request is set,
    // each render() copies that cascade's volumes at that propagation step;
    // nullopt (the default) reads nothing.
    void setLpvCapture(std::optional<LpvCaptureRequest> request);
    // The copy of the last frame, or null (no request, LPV off, cascade out of range).
    const LpvSnapshot* lpvSnapshot() const;
    // Where the LPV cascades of the last frame lie (empty when the LPV is off).
    std::vector<LpvGridFrame> lpvCascadeFrames() const;
    // Tints every surface by the sun shadow cascade that shades it (cascade k:
    // the k-th colour of red, green, blue, yellow, magenta, cyan), for the
    // shadow-map visualizer; off by default.
    void setShadowCascadeTint(bool on);
    // Sun shadow cascades the last frame drew (the others kept their layer: their snapped matrix did not move).
    int shadowCascadesDrawn() const;
    // Sun shadow cascades the last frame shaded from a layer drawn for an
    // earlier camera (shadow.farCascadeInterval > 1).
    int shadowCascadesStale() const;
    // Draw items of the last frame's camera pass: in the scene, and culled by the frustum.
    DrawListStats cameraDrawStats() const;
    // What the LPV did in the last frame and why, e.g. "LPV: 4 cascades of 32^3, 8 steps, computeGather, ..."
    // or "LPV: off (gi.method is off: direct light only)", "LPV: off (gi.method
    // is radiosity: the indirect light is the baked solution's, 438 patches, ...)".
    std::string lpvNote() const;
    // The last frame's LPV fit (lpv.cellSize = auto chooses it), and why
    // that LPV delivers almost no light to the view (empty when it does).
    const LpvFit& lpvFit() const;
    const LpvDelivery& lpvDelivery() const;
    // GPU memory of the subsurface LPV's volumes (0 while it does not run).
    std::size_t subsurfaceAllocatedBytes() const;
    // The GPU memory the last frame's resources hold (GpuMemory.h): every
    // frame-graph resource and the LPV's own volumes, each GL object once, at
    // the bytes its format and size give; scene meshes and textures left out.
    GpuMemory gpuMemory() const;
    // The effect decisions of the last frame, each with its reason: directed
    // propagation and sky light injection (when the LPV ran), then sun rays.
    const std::vector<EffectDecision>& frameEffects() const;
    int width() const;
    int height() const;

    // Auto exposure (output.exposureMode = auto, AutoExposure.h). The time
    // since the last frame lets the exposure adapt like an eye (the editor
    // passes its frame interval, `lpv video` 1/fps: the same frames give the
    // same exposures); nullopt (the default) meters every frame on its own.
    void setExposureTimeStep(std::optional<double> seconds);
    // The next frame takes its metered exposure at once (a cut, a new camera).
    void resetExposure();
    // The scale the last frame's display image was exposed with (2^output.exposure
    // times the metered exposure on auto). Reads the GPU back: call after a frame.
    double displayExposure(const scene::ParameterSet& params) const;

    GpuTimer& timer();

private:
    ForwardRenderer();
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace lpv::renderer
