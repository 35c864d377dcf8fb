#pragma once
// One radiosity solve of a scene as the CLI and the editor run it: mesh the
// scene, resume a saved solution when it was solved for this very scene,
// refine where the light changes fast, and package the result for saving.
#include "lpv/radiosity/ProgressiveSolver.h"
#include "lpv/radiosity/SolutionFile.h"
#include "lpv/scene/Error.h"
#include "lpv/scene/Image.h"
#include "lpv/scene/Scene.h"

#include "lpv/scene/ParameterRegistry.h"

#include <atomic>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

namespace lpv::radiosity {

// What RadiositySession::create needs besides the scene.
struct SessionOptions {
    float maxPatchArea = 0.05f;        // radiosity.maxPatchArea
    std::size_t maxPatches = 1000000;  // radiosity.maxPatches
    int lightSamples = 4;              // radiosity.lightSamples: points per patch for the lights' direct light
    const std::atomic<bool>* cancel = nullptr; // stops the direct light (an error value)
};

// The patch area a solve of `scene` uses (issue #41 item 3, docs/radiosity.md):
// radiosity.maxPatchArea when the project sets it (m^2, forced), else a patch
// edge of 1/25 of the largest side of the scene's bounds, so a scene meshes
// into the same patches in centimetres or kilometres (0.05 m^2 in the 5.59 m
// Cornell box, what the registry's default was tuned on).
inline constexpr float kAutoPatchesPerSide = 25.0f;
float patchAreaFor(const scene::Scene& scene, const scene::ParameterSet& parameters);

class RadiositySession {
  public:
    // The checks a solve needs before it meshes, the mesh, and for a fresh
    // solve the lights' direct light as the first shots (issue #27 item 2):
    // an error value when nothing can shoot (no light and no emissive
    // surface, or lights that reach no patch), or when the scene would mesh
    // into more than `maxPatches` patches (counted without storing them, so
    // a 1.4 million patch Sponza is refused before it allocates).
    static scene::Expected<RadiositySession> create(const scene::Scene& scene, const scene::TextureImages& textures,
                                                    const SessionOptions& options,
                                                    std::optional<StoredSolution> saved = std::nullopt);

    // The same with the default light samples.
    static scene::Expected<RadiositySession> create(const scene::Scene& scene, const scene::TextureImages& textures,
                                                    float maxPatchArea, std::size_t maxPatches,
                                                    std::optional<StoredSolution> saved = std::nullopt);

    // The same with the project's radiosity.maxPatches and radiosity.lightSamples,
    // and patchAreaFor's patch area: what `lpv radiosity` and the editor's dock run.
    static scene::Expected<RadiositySession> create(const scene::Scene& scene, const scene::ParameterSet& parameters,
                                                    const scene::TextureImages& textures,
                                                    std::optional<StoredSolution> saved = std::nullopt,
                                                    const std::atomic<bool>* cancel = nullptr);

    // The mesh and solver alone, without the lights' direct light (emissive
    // surfaces shoot; create() adds the lights). `saved` (from loadSolution) is resumed if its scene signature matches
    // the scene meshed with `maxPatchArea`; otherwise the solve starts over and
    // note() says why.
    RadiositySession(const scene::Scene& scene, const scene::TextureImages& textures, float maxPatchArea,
                     std::optional<StoredSolution> saved = std::nullopt);

    const PatchMesh& mesh() const { return *mesh_; }
    ProgressiveSolver& solver() { return *solver_; }
    const ProgressiveSolver& solver() const { return *solver_; }
    bool resumed() const { return resumed_; }
    // Seconds the lights' direct light took (0 when resumed or without lights).
    double directLightSeconds() const { return directLightSeconds_; }
    const std::string& note() const { return note_; }
    // The largest patch area the scene was meshed with (m^2 of the scene's units).
    float maxPatchArea() const { return maxPatchArea_; }

    // Splits patches whose radiosity differs from a neighbour's by more than
    // `threshold` (relative), carrying the solution over. The mesh and solver
    // are replaced (a form factor source built on the old mesh must be rebuilt).
    // Returns how many patches were split.
    std::size_t refine(float threshold);

    StoredSolution stored() const;

  private:
    std::unique_ptr<PatchMesh> mesh_;
    std::unique_ptr<ProgressiveSolver> solver_;
    std::uint64_t signature_ = 0;
    float maxPatchArea_ = 0.0f;
    bool resumed_ = false;
    double directLightSeconds_ = 0.0;
    std::string note_;
};

// The solution saved beside `projectFile` (solutionPath), if one is there and
// loads; a damaged one is ignored and `ignored` (may be null) says why, so a
// solve starts over instead of failing.
std::optional<StoredSolution> loadSavedSolution(const scene::Scene& scene, const std::filesystem::path& projectFile,
                                                std::string* ignored = nullptr);

} // namespace lpv::radiosity
