#pragma once
// Form factors from shooting patches to every patch: the one operation the
// progressive solver needs, implemented on the CPU here (the reference) and
// with GPU hemicubes in lpv_renderer (renderer/GpuHemicube.h).
#include "lpv/radiosity/PatchMesh.h"
#include "lpv/scene/Error.h"

#include <cstdint>
#include <span>
#include <vector>

namespace lpv::radiosity {

class FormFactorSource {
  public:
    virtual ~FormFactorSource() = default;
    // For each shooter s (an index into the patch mesh), fills
    // factors[s * patchCount + j] with the form factor from a differential
    // area at the shooter's centre to patch j, through its front side only
    // (what is seen from behind absorbs nothing and blocks the view).
    virtual scene::Expected<void> compute(std::span<const std::uint32_t> shooters,
                                          std::vector<float>& factors) = 0;
    // How many shooters one compute() call handles best (the GPU batch).
    virtual int preferredBatch() const { return 1; }
    virtual const char* name() const = 0;
};

// Reference: the exact point-to-polygon form factor (Lambert's contour
// formula, receiver clipped to the shooter's front half-space), visible or
// not by one ray from the shooter's centre to the receiver's centre, tested
// against every patch. O(patches^2) per shooter: small meshes only.
class CpuFormFactors final : public FormFactorSource {
  public:
    explicit CpuFormFactors(const PatchMesh& mesh, bool occlusion = true);
    scene::Expected<void> compute(std::span<const std::uint32_t> shooters,
                                  std::vector<float>& factors) override;
    const char* name() const override { return "cpu-reference"; }

  private:
    const PatchMesh& mesh_;
    bool occlusion_;
};

// Form factor from a differential area at `point` with `normal` to a convex
// polygon (any winding), clipped to the half-space in front of `normal`.
double pointToPolygonFormFactor(const glm::dvec3& point, const glm::dvec3& normal,
                                const std::vector<glm::dvec3>& polygon);

} // namespace lpv::radiosity
