#pragma once
// Form factors by ray casting (Wallace, Elmquist, Haines 1989, "A Ray Tracing
// Algorithm for Progressive Radiosity"), on the CPU with Embree: every patch
// that faces a shooter casts a shadow ray to each of `samples` stratified
// points on it, and adds the disc-approximated factor of each visible point,
//
//     F(dA_j -> A_i) = sum_k  cos_i cos_j (A_i / S) / (pi r^2 + A_i / S),
//
// turned into the fraction of the shooter's power that lands on patch j by
// reciprocity, F(i -> j) = F(dA_j -> A_i) A_j / A_i. The receiver is its
// centre (what the shooter sees of it), the occluders are the scene's own
// triangles (alpha masks included), not the patches. Where llvmpipe spends a
// hemicube's time setting up every patch's triangles five times per
// shooter, this costs one ray per receiver and sample, on all cores.
#include "lpv/radiosity/FormFactors.h"
#include "lpv/scene/Image.h"
#include "lpv/scene/Scene.h"

#include <memory>

namespace lpv::reference {
class EmbreeScene;
}

namespace lpv::radiosity {

class RayCastFormFactors final : public FormFactorSource {
  public:
    // Builds Embree's scene of `scene` (an error if Embree cannot); `mesh`,
    // `scene` and `textures` must outlive the source.
    static scene::Expected<std::unique_ptr<RayCastFormFactors>> create(const PatchMesh& mesh,
                                                                       const scene::Scene& scene,
                                                                       const scene::TextureImages& textures,
                                                                       int samples, int batch);
    ~RayCastFormFactors() override;

    scene::Expected<void> compute(std::span<const std::uint32_t> shooters, std::vector<float>& factors) override;
    int preferredBatch() const override { return batch_; }
    const char* name() const override { return "raycast"; }
    int samples() const { return samples_; }

  private:
    RayCastFormFactors(const PatchMesh& mesh, std::unique_ptr<reference::EmbreeScene> embree, int samples,
                       int batch);
    const PatchMesh& mesh_;
    std::unique_ptr<reference::EmbreeScene> embree_;
    int samples_;
    int batch_;
};

} // namespace lpv::radiosity
