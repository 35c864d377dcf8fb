#pragma once
// The GL state a sweep renders with: a headless context of its own (so a
// sweep runs beside the editor's viewport or on a worker thread) and a
// renderer holding the scene, its textures decoded once.
#include "lpv/importers/SceneTextures.h"
#include "lpv/renderer/ForwardRenderer.h"
#include "lpv/renderer/GlContext.h"
#include "lpv/scene/Error.h"
#include "lpv/scene/Scene.h"

#include <filesystem>
#include <functional>
#include <memory>
#include <string>

namespace lpv::bench {

struct SceneRenderer {
    renderer::HeadlessContext context;
    renderer::ForwardRenderer renderer;
    importers::SceneTextures textures; // relative paths resolved against the project's folder
};

// Opens the context, creates the renderer and uploads `scene`; each texture
// that could not be read is passed to `warning` (drawn as a placeholder).
// On the heap, so nothing moves the renderer once it holds the scene.
inline scene::Expected<std::unique_ptr<SceneRenderer>>
openSceneRenderer(const scene::Scene& scene, const std::filesystem::path& projectDir,
                  const std::function<void(const std::string&)>& warning) {
    auto context = renderer::HeadlessContext::create();
    if (!context)
        return std::unexpected(context.error());
    auto forward = renderer::ForwardRenderer::create();
    if (!forward)
        return std::unexpected(forward.error());
    auto out = std::make_unique<SceneRenderer>(SceneRenderer{
        std::move(*context), std::move(*forward), importers::loadSceneTextures(scene, projectDir)});
    for (const std::string& w : out->textures.warnings)
        if (warning)
            warning(w);
    out->renderer.setScene(scene, out->textures.images);
    return out;
}

} // namespace lpv::bench
