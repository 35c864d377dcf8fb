#pragma once
// Hemicube form factors on the GPU (docs/radiosity.md): for each shooter of a
// batch, the patch IDs (32-bit integers, so any patch count) are rendered
// into the five faces of its hemicube, five viewports of one R32UI target
// that holds the whole batch; a compute shader multiplies every pixel by the
// precomputed delta form factor and sums per (shooter, patch) with integer
// atomics. Only the per-patch sums are read back, never the hemicubes.
#include "lpv/radiosity/FormFactors.h"
#include "lpv/renderer/GlHandle.h"
#include "lpv/scene/Error.h"

#include <memory>
#include <vector>

namespace lpv::renderer {

class GpuHemicube final : public radiosity::FormFactorSource {
  public:
    // `resolution` is the front face's size in pixels (radiosity.hemicubeResolution,
    // rounded up to even); `maxBatch` the most shooters per compute() (radiosity.shootersPerBatch),
    // lowered if the batch would not fit the largest texture. Needs a current GL 4.5 context.
    static scene::Expected<std::unique_ptr<GpuHemicube>> create(const radiosity::PatchMesh& mesh,
                                                                int resolution, int maxBatch);
    ~GpuHemicube() override;

    scene::Expected<void> compute(std::span<const std::uint32_t> shooters,
                                  std::vector<float>& factors) override;
    int preferredBatch() const override { return maxBatch_; }
    const char* name() const override { return "gpu-hemicube"; }
    int resolution() const { return resolution_; }

    // The IDs (patch + 1, 0 = nothing) of the `index`-th shooter of the last
    // batch, 3R x R in the layout of radiosity::HemicubeLayout, rows bottom to
    // top. A debug view, read back on request only.
    std::vector<std::uint32_t> readHemicube(int index) const;

  private:
    GpuHemicube() = default;
    void renderShooter(const radiosity::Patch& shooter, int row) const;

    // Patches are drawn in spatially sorted clusters; a cluster whose bounds
    // lie outside a face's frustum is skipped (a face sees a quarter to a half
    // of the scene, so this saves most of the triangles on big scenes).
    struct Cluster {
        glm::vec3 min{0.0f}, max{0.0f};
        GLint first = 0;
        GLsizei count = 0;
    };
    const radiosity::PatchMesh* mesh_ = nullptr;
    std::vector<Cluster> clusters_;
    mutable std::vector<GLint> firsts_; // scratch of renderShooter
    mutable std::vector<GLsizei> counts_;
    int resolution_ = 0;
    int maxBatch_ = 1;
    int lastBatch_ = 0;
    GLsizei vertexCount_ = 0;
    float near_ = 0.001f;
    float far_ = 100.0f;
    // Patches are drawn relative to this point: the centre of the patches'
    // bounds when they lie farther from the world origin than their size, else
    // 0 (issue #41). 100 km out a float view matrix alone rounds to 8 mm, far
    // above the near plane (1e-5 of the scene); corners minus a nearby centre
    // are exact.
    glm::vec3 frame_{0.0f};
    Buffer vertices_;
    VertexArray vao_;
    Texture ids_;
    Texture depth_;
    Texture deltaFF_;
    Framebuffer fbo_;
    Buffer sums_;
    Program raster_;
    Program accumulate_;
};

} // namespace lpv::renderer
