#include "LiveReference.h"

#include "lpv/importers/SceneTextures.h"
#include "lpv/reference/EmbreeScene.h"
#include "lpv/reference/Metrics.h"
#include "lpv/reference/PathTracer.h"
#include "lpv/reference/Preview.h"
#include "lpv/renderer/ReferenceLights.h"
#include "lpv/renderer/SceneAnalysis.h"

#include <QMetaObject>

#include <algorithm>
#include <cmath>
#include <thread>

namespace lpv::editor {

struct LiveReference::Prepared {
    scene::Scene scene; // the tracer and Embree point into it
    importers::SceneTextures textures;
    std::optional<reference::EmbreeScene> embree;
};

QImage displayReference(const LinearImage& r, ReferenceMapping mapping,
                        const scene::ParameterSet& parameters) {
    if (r.width <= 0 || r.height <= 0)
        return {};
    const scene::Image8 rgba =
        mapping == ReferenceMapping::Preview
            ? reference::previewImage(r.pixels, r.width, 0, 0, r.width, r.height,
                                      reference::meanLuminance(r.pixels, r.coverage))
            : tonemapImage(r.pixels, r.width, r.height, meteredMapping(r.pixels, parameters));
    return QImage(rgba.pixels.data(), rgba.width, rgba.height, rgba.width * 4, QImage::Format_RGBA8888).copy();
}

LiveReference::LiveReference(QObject* parent) : QObject(parent) {}

LiveReference::~LiveReference() {
    join();
}

void LiveReference::join() {
    cancel_ = true;
    if (worker_.joinable())
        worker_.join();
    cancel_ = false;
}

void LiveReference::stop() {
    join();
    ++generation_;
    prepared_.reset();
}

void LiveReference::restart(const scene::Scene& scene, const scene::ParameterSet& params,
                            const scene::Camera& camera, int width, int height, const QString& projectDir,
                            bool sceneChanged) {
    join();
    const unsigned generation = ++generation_;
    // A scene whose Embree build failed is built again (and fails again, saying so).
    if (sceneChanged || (prepared_ && !prepared_->embree))
        prepared_.reset();
    reference::PathTracerSettings settings;
    settings.width = std::max(1, width);
    settings.height = std::max(1, height);
    settings.samplesPerPixel = 1 << 20; // until the next change
    settings.bounces = params.getInt("reference.bounces");
    // One core stays with the window.
    settings.threads = int(std::max(1u, std::thread::hardware_concurrency() - 1));
    auto prepared = prepared_;
    const bool build = !prepared;
    if (build) {
        prepared = std::make_shared<Prepared>();
        prepared->scene = scene;
    }
    prepared_ = prepared;
    worker_ = std::thread([this, prepared, build, settings, params, camera, generation,
                           dir = projectDir.toStdString()]() mutable {
        if (build) {
            prepared->textures = importers::loadSceneTextures(prepared->scene, dir);
            auto embree = reference::EmbreeScene::build(prepared->scene, prepared->textures.images);
            if (!embree) {
                const QString message = QString::fromStdString(embree.error().describe());
                QMetaObject::invokeMethod(
                    this, [this, message] { emit failed(message); }, Qt::QueuedConnection);
                return;
            }
            prepared->embree.emplace(std::move(*embree));
        }
        if (cancel_)
            return;
        // Like `lpv reference`: the sky and emissive surfaces as the LPV would inject them (auto).
        const renderer::ReferenceLights lights = renderer::decideReferenceLights(
            prepared->scene, renderer::analyseSceneTraits(prepared->scene), params);
        settings.skyLight = lights.sky;
        settings.emissiveLight = lights.emissive;
        const reference::PathTracer tracer(*prepared->embree, prepared->scene, camera, settings);
        tracer.render([this](const reference::TraceProgress&) { return !cancel_; },
                      [this, generation, params](const reference::ReferenceImage& image) {
                          // Its own noise: the MARE a noiseless copy of itself would show.
                          reference::MetricOptions noSsim;
                          noSsim.ssim = false;
                          const reference::ErrorMetrics noise =
                              reference::compareImages({image.width, image.height, &image.image},
                                                       {image.width, image.height, &image.image},
                                                       &image.imageVariance, &image.coverage, noSsim);
                          auto linear = std::make_shared<LinearImage>();
                          linear->width = image.width;
                          linear->height = image.height;
                          linear->pixels = image.image;
                          linear->coverage = image.coverage;
                          const QImage shown = displayReference(*linear, mapping_, params);
                          const int spp = image.samplesPerPixel;
                          const double seconds = image.seconds;
                          std::shared_ptr<const reference::ReferenceImage> copy;
                          if (sendImages_)
                              copy = std::make_shared<const reference::ReferenceImage>(image);
                          QMetaObject::invokeMethod(
                              this,
                              [this, generation, shown, linear = std::shared_ptr<const LinearImage>(linear),
                               spp, noise, seconds, copy] {
                                  if (generation != generation_)
                                      return;
                                  emit passDone(shown, linear, spp, noise.noiseMare, seconds);
                                  if (copy)
                                      emit imageDone(copy);
                              },
                              Qt::QueuedConnection);
                      });
    });
}

} // namespace lpv::editor
