#include "lpv/bench/Reference.h"

#include "lpv/importers/SceneTextures.h"
#include "lpv/reference/EmbreeScene.h"
#include "lpv/renderer/SceneAnalysis.h"

namespace lpv::bench {

scene::Expected<TracedReference> traceReference(const scene::Project& project, const std::filesystem::path& projectDir,
                                                const scene::Camera& camera, const ReferenceRequest& request,
                                                const ReferenceCallbacks& callbacks) {
    const auto textures = importers::loadSceneTextures(project.scene, projectDir);
    for (const std::string& w : textures.warnings)
        if (callbacks.warning)
            callbacks.warning(w);
    auto embree = reference::EmbreeScene::build(project.scene, textures.images);
    if (!embree)
        return std::unexpected(embree.error());
    ReferencePlan plan;
    plan.triangles = embree->triangleCount();
    plan.settings.width = request.width;
    plan.settings.height = request.height;
    plan.settings.threads = request.threads;
    plan.settings.shard = request.shard;
    plan.settings.samplesPerPixel = project.parameters.getInt("reference.samplesPerPixel");
    plan.settings.bounces = project.parameters.getInt("reference.bounces");
    plan.settings.maxSeconds = project.parameters.getFloat("reference.maxSeconds");
    plan.lights = renderer::decideReferenceLights(project.scene, renderer::analyseSceneTraits(project.scene),
                                                  project.parameters);
    plan.settings.skyLight = plan.lights.sky;
    plan.settings.emissiveLight = plan.lights.emissive;
    if (callbacks.started)
        callbacks.started(plan);
    const reference::PathTracer tracer(*embree, project.scene, camera, plan.settings);
    auto image = tracer.render(callbacks.progress ? callbacks.progress
                                                  : reference::ProgressCallback([](const auto&) { return true; }));
    return TracedReference{std::move(image), plan.lights, plan.settings.bounces};
}

} // namespace lpv::bench
