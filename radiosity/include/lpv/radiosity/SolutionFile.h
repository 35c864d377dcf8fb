#pragma once
// A radiosity solution on disk (`<Name>.assets/radiosity.lpvrad`, see
// docs/project-format.md): header (magic, version, counts, a signature of the
// scene it was solved for, checksum of the payload), then the patches
// (possibly refined), radiosity, unshot radiance and the solver's counters,
// so an unfinished solve resumes after reopening the project.
#include "lpv/radiosity/PatchMesh.h"
#include "lpv/radiosity/ProgressiveSolver.h"
#include "lpv/scene/Error.h"

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>

namespace lpv::radiosity {

// 2: per patch also the incident and the lights' direct light (issue #27).
inline constexpr std::uint32_t kSolutionVersion = 2;

struct StoredSolution {
    PatchMesh mesh; // patches only are stored; adjacency is rebuilt on load
    SolverState state;
    // sceneSignature() of the scene and meshing options it was solved for.
    std::uint64_t sceneSignature = 0;
    float maxPatchArea = 0.0f;
};

// Changes when anything the solution depends on changes: the patches of the
// unrefined mesh, every material's reflectance and emission, and the lights.
std::uint64_t sceneSignature(const PatchMesh& unrefined, const SurfaceProperties& surfaces,
                             std::span<const scene::Light> lights);

// `<dir>/<stem>.assets/radiosity.lpvrad` for `<dir>/<stem>.lpvproj`.
std::filesystem::path solutionPath(const std::filesystem::path& projectFile);

std::string encodeSolution(const StoredSolution& solution);
// `fileName` only names the file in errors; `materialCount` and `objectCount` bound the patches' indices.
scene::Expected<StoredSolution> decodeSolution(std::string_view bytes, const std::string& fileName,
                                               std::size_t materialCount, std::size_t objectCount);

// Atomic (temporary file, flush, rename).
scene::Expected<void> saveSolution(const StoredSolution& solution, const std::filesystem::path& file);
scene::Expected<StoredSolution> loadSolution(const std::filesystem::path& file, std::size_t materialCount,
                                             std::size_t objectCount);

} // namespace lpv::radiosity
