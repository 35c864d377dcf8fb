#pragma once
// gi.method = radiosity in the viewport: the project's saved radiosity
// solution, kept by the frame worker (its thread loads it: checking a
// solution against a big scene means meshing the scene) and looked at again
// only when what it was checked against may have changed. Qt-free.
#include "lpv/radiosity/BakedSolution.h"
#include "lpv/scene/Image.h"
#include "lpv/scene/Scene.h"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

namespace lpv::editor {

class BakedRadiosityCache {
  public:
    // The scene's geometry, materials, lights or textures changed: the
    // solution may no longer be this scene's.
    void sceneChanged() { sceneChanged_ = true; }

    // The solution saved beside `projectFile` (empty: an unsaved project,
    // which has none) for this scene, or null with message() saying why.
    // Loaded on the first call, for another file or `generation` (bumped
    // when a solve saved one); after a scene change a loaded solution whose
    // signature still matches (meshed at the patch size it was solved with)
    // is kept without reading the file again.
    std::shared_ptr<const radiosity::BakedSolution> update(const scene::Scene& scene,
                                                           const scene::TextureImages& textures,
                                                           const std::filesystem::path& projectFile,
                                                           std::uint64_t generation);

    // What was loaded ("FILE: 438 patches, residual 0.0977") or why nothing was.
    const std::string& message() const { return message_; }
    bool failed() const { return !solution_; }

  private:
    std::shared_ptr<const radiosity::BakedSolution> solution_;
    std::filesystem::path file_;
    std::uint64_t generation_ = 0;
    bool attempted_ = false;
    bool sceneChanged_ = true;
    std::string message_;
};

} // namespace lpv::editor
