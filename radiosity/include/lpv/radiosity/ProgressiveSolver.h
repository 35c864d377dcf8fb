#pragma once
// Progressive refinement radiosity (Cohen, Chen, Wallace, Greenberg 1988):
// the patches with the most unshot power shoot it to every patch they see,
// N at a time. Values are exitant radiance (radiosity / pi), so emissive
// materials enter as they are and the display needs no scale.
#include "lpv/radiosity/FormFactors.h"
#include "lpv/radiosity/PatchMesh.h"
#include "lpv/radiosity/SurfaceProperties.h"
#include "lpv/scene/Error.h"

#include <cstdint>
#include <vector>

namespace lpv::radiosity {

// Power bookkeeping (radiance x area, per channel): what the emitters put in
// equals what surfaces absorbed, what is still unshot, and what left through
// gaps or hit a back face.
struct EnergyBalance {
    glm::dvec3 emitted{0.0};
    glm::dvec3 absorbed{0.0};
    glm::dvec3 escaped{0.0};
    bool operator==(const EnergyBalance&) const = default;
};

// Everything a resumed solve needs besides the patches and the materials.
struct SolverState {
    std::vector<glm::vec3> radiosity; // per patch, exitant radiance
    std::vector<glm::vec3> unshot;    // per patch, radiance not yet shot
    // Per patch, light that arrived through form factors (irradiance / pi,
    // before reflection): what the renderer shows as radiosity's indirect
    // light, times each texel's albedo (gi.method = radiosity).
    std::vector<glm::vec3> incident;
    // Per patch, the lights' direct light (irradiance / pi) that started the
    // solve (addDirectLight): the renderer draws it itself, so it is kept
    // apart from `incident`.
    std::vector<glm::vec3> direct;
    std::uint64_t shots = 0;
    std::uint64_t batches = 0;
    double seconds = 0.0; // solve time so far, over all sessions
    EnergyBalance balance;
    bool operator==(const SolverState&) const = default;
};

class ProgressiveSolver {
  public:
    // Radiosity and unshot start at the emission.
    ProgressiveSolver(const PatchMesh& mesh, SurfaceProperties surfaces);

    // The lights' direct light as the first bounce (issue #27 item 2):
    // `direct` per patch (irradiance / pi, from the scene's sun, spot, point
    // and area lights with their shadows) is reflected by each patch into
    // its radiosity and unshot radiance. The power it brings counts as
    // emitted, its unreflected part as absorbed, so the balance still holds.
    // Replaces any direct light added before; an error if the sizes differ.
    scene::Expected<void> addDirectLight(std::vector<glm::vec3> direct);

    // Continues from a saved state; an error if it does not fit the mesh.
    scene::Expected<void> restore(SolverState state);

    // Shoots from up to `shooters` patches with the most unshot power. Returns
    // how many shot (0 when nothing is left to shoot).
    scene::Expected<int> step(FormFactorSource& formFactors, int shooters);

    // Unshot power over emitted power (sum of the channels); 0 when nothing emits.
    double residual() const;
    glm::dvec3 unshotPower() const;
    const SolverState& state() const { return state_; }
    SolverState& mutableState() { return state_; }
    const SurfaceProperties& surfaces() const { return surfaces_; }
    const PatchMesh& mesh() const { return mesh_; }

    // Cohen's ambient term: the unshot power spread uniformly and bounced by
    // the average reflectance, per patch (reflectance x ambient radiance). Only
    // for display; the solution itself never contains it.
    std::vector<glm::vec3> ambient() const;

    // Patches whose radiosity differs from an edge neighbour's by more than
    // `threshold` times the larger of the two (sum of channels): where the
    // mesh is too coarse for the light.
    std::vector<std::uint32_t> patchesToRefine(float threshold) const;

  private:
    std::vector<std::uint32_t> pickShooters(int count) const;

    const PatchMesh& mesh_;
    SurfaceProperties surfaces_;
    SolverState state_;
    std::vector<float> factors_; // scratch, shooters x patches
};

// The state of `solver` carried onto a refined mesh: each child inherits its
// parent's radiosity and unshot radiance, so unshot power and the balance
// are unchanged.
SolverState refineState(const SolverState& state, const std::vector<std::uint32_t>& parentOf);

} // namespace lpv::radiosity
