#pragma once
// gi.method = radiosity (docs/renderer.md, "Baked radiosity"): the indirect
// light of a baked solution seen from the frame's camera. The patches, each
// corner carrying the smoothed light that reached its patch through form
// factors (irradiance / pi, without the lights' direct light, which shading
// draws itself), are drawn into a screen-sized target that shading reads at
// its own pixel and multiplies by the texel's albedo.
#include "frame/FrameContext.h"
#include "passes/radiosity/PatchVertices.h"
#include "graph/FrameGraph.h"
#include "lpv/renderer/GlHandle.h"
#include "lpv/scene/Error.h"

#include <cstdint>

namespace lpv::radiosity {
struct BakedSolution;
}

namespace lpv::renderer {

class GpuMemoryLedger;

class RadiosityIndirectPass {
  public:
    static scene::Expected<RadiosityIndirectPass> create();

    // Uploads the patches of `solution` with their incident light smoothed to
    // the corners (or flat), unless this solution (`generation`) is already
    // uploaded with this smoothing. Blended materials' patches are left out:
    // shading reads one value per pixel, and behind glass it is the opaque
    // surface's that should win.
    void upload(const radiosity::BakedSolution& solution, std::uint64_t generation, const scene::Scene& scene,
                bool smooth);

    // Draws into radiosity.incident (RGBA16F: rgb the incident light, a = 1
    // where a patch is) with its own radiosity.depth. With `afterPrepass` it
    // reads the pre-pass's camera.depth: a patch counts at a pixel only near
    // the surface shading lights there.
    void render(graph::PassContext& ctx, bool afterPrepass);

    std::size_t patchTriangleVertices() const { return std::size_t(draw_.vertices); }
    // Names its GL objects for ForwardRenderer::gpuMemory().
    void addGpuMemory(GpuMemoryLedger& ledger) const;

  private:
    RadiosityIndirectPass() = default;

    Program program_;
    PatchDraw draw_;
    bool uploaded_ = false;
    std::uint64_t generation_ = 0;
    bool smooth_ = false;
    Framebuffer fbo_;
    GLuint attachedIncident_ = 0, attachedDepth_ = 0;
};

} // namespace lpv::renderer
