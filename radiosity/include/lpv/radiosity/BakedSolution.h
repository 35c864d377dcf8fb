#pragma once
// A saved radiosity solution checked against the scene it is shown with
// (gi.method = radiosity, issue #27 item 1): the renderer draws the light the
// patches gathered through form factors as the indirect light, times each
// texel's albedo, and draws the lights' direct light itself.
#include "lpv/radiosity/PatchMesh.h"
#include "lpv/scene/Error.h"
#include "lpv/scene/Image.h"
#include "lpv/scene/Scene.h"

#include <cstdint>
#include <filesystem>
#include <vector>

namespace lpv::radiosity {

struct BakedSolution {
    PatchMesh mesh;                  // the solved (possibly refined) patches, with adjacency for smoothing
    std::vector<glm::vec3> incident; // per patch: irradiance / pi that arrived through form factors
    double residual = 0.0;           // unshot / emitted power when it was saved
    std::uint64_t shots = 0;
    double seconds = 0.0;            // solve time over all its sessions
    std::uint64_t signature = 0;     // the scene signature it was solved for
    float maxPatchArea = 0.0f;       // the patch size it was meshed with (what the signature is computed at)
    std::filesystem::path file;      // where it was read from
};

// The solution saved beside `projectFile` (solutionPath), if it was solved
// for this very scene (meshed with the patch size it was solved with, its
// materials and lights; sceneSignature). Error values name the file and say
// what to do: none saved ("run lpv radiosity PROJECT"), damaged, or solved
// for another scene.
scene::Expected<BakedSolution> loadBakedSolution(const scene::Scene& scene, const scene::TextureImages& textures,
                                                 const std::filesystem::path& projectFile);

// The scene signature of `scene` meshed with `maxPatchArea` (what a solution
// solved for it records): for a caller that checks many solutions or caches.
std::uint64_t currentSignature(const scene::Scene& scene, const scene::TextureImages& textures, float maxPatchArea);

} // namespace lpv::radiosity
