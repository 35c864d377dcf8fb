#include "BakedRadiosityCache.h"

#include <cstdio>

namespace lpv::editor {

std::shared_ptr<const radiosity::BakedSolution>
BakedRadiosityCache::update(const scene::Scene& scene, const scene::TextureImages& textures,
                            const std::filesystem::path& projectFile, std::uint64_t generation) {
    const bool reload = !attempted_ || projectFile != file_ || generation != generation_;
    if (!reload && !sceneChanged_)
        return solution_;
    // A scene edit that leaves the solution's scene as it was (a move undone,
    // a material's name) keeps it: the signature alone is cheaper than a load.
    // At the patch size it was solved with, which the project's
    // radiosity.maxPatchArea need not equal any more.
    if (!reload && solution_ &&
        radiosity::currentSignature(scene, textures, solution_->maxPatchArea) == solution_->signature) {
        sceneChanged_ = false;
        return solution_;
    }
    attempted_ = true;
    file_ = projectFile;
    generation_ = generation;
    sceneChanged_ = false;
    solution_.reset();
    if (projectFile.empty()) {
        message_ =
            "gi.method = radiosity: an unsaved project has no radiosity solution: save it and solve it "
            "(Radiosity dock); direct light only";
        return nullptr;
    }
    auto loaded = radiosity::loadBakedSolution(scene, textures, projectFile);
    if (!loaded) {
        message_ = loaded.error().describe() + "; direct light only";
        return nullptr;
    }
    char text[96];
    std::snprintf(text, sizeof text, ": %zu patches, residual %.3g", loaded->mesh.size(), loaded->residual);
    message_ = loaded->file.string() + text;
    solution_ = std::make_shared<const radiosity::BakedSolution>(std::move(*loaded));
    return solution_;
}

} // namespace lpv::editor
