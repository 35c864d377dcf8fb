#pragma once
// gi.method = radiosity (docs/renderer.md, "Baked radiosity"): the indirect
// light of a baked solution seen from the frame's camera. The patches, each
// corner carrying the smoothed light that reached its patch through form
// factors (irradiance / pi, without the lights' direct light, which shading
// draws itself), are drawn into a screen-sized target that shading reads at
// its own pixel and multiplies by the texel's albedo.
#include "frame/FramePass.h"
#include "passes/radiosity/PatchVertices.h"
#include "lpv/renderer/GlHandle.h"
#include "lpv/scene/Error.h"

#include <array>
#include <cstdint>
#include <optional>

namespace lpv::radiosity {
struct BakedSolution;
}

namespace lpv::renderer {

class GpuMemoryLedger;

// The pass in the frame's table (PassTable.cpp): it declares itself in
// setup() and draws in execute(); its GL objects exist from its first run
// until a frame culls it. Its name and its outputs are declared here, and
// nowhere else (frame/PassList.h).
class RadiosityIndirectPass final : public GraphPass {
  public:
    static constexpr std::string_view kName = "radiosityIndirect";
    // The incident light (rgb irradiance / pi; a = 1 where a patch is) and
    // the depth it was drawn with, each the size of the frame.
    static constexpr graph::ResourceHandle Incident{"radiosity.incident"};
    static constexpr graph::ResourceHandle Depth{"radiosity.depth"};
    static constexpr std::array kOutputs{Incident, Depth};

    RadiosityIndirectPass() : GraphPass(kName) {}

    std::size_t patchTriangleVertices() const { return gpu_ ? std::size_t(gpu_->draw.vertices) : 0; }
    // Names its GL objects for ForwardRenderer::gpuMemory().
    void addGpuMemory(GpuMemoryLedger& ledger) const override;

  protected:
    // Runs with gi.method = radiosity and a solution; writes Incident and
    // Depth (kept across frames, so a still camera reuses them),
    // after the depth pre-pass whose camera.depth it reads.
    void setup(graph::PassSpec& pass, FrameState& state) override;
    scene::Expected<void> execute(graph::PassContext& ctx, FrameState& state) override;
    void release() override { gpu_.reset(); }

  private:
    struct Gpu {
        Program program;
        PatchDraw draw;
        bool uploaded = false;
        std::uint64_t generation = 0;
        bool smooth = false;
        Framebuffer fbo;
        GLuint attachedIncident = 0, attachedDepth = 0;
    };

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

    std::optional<Gpu> gpu_;
};

} // namespace lpv::renderer
