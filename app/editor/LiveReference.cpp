#include "LiveReference.h"

#include "lpv/importers/SceneTextures.h"
#include "lpv/reference/EmbreeScene.h"
#include "lpv/reference/Metrics.h"
#include "lpv/reference/PathTracer.h"
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

namespace {

// x / (x + key) per channel, gamma 2.2, key = the image's mean luminance: the
// mapping of `lpv reference --preview`, so a dark interior and a sunlit
// court both show.
QImage displayImage(const reference::ReferenceImage& r) {
    double sum = 0.0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < r.image.size(); ++i)
        if (r.coverage[i] > 0.5f) {
            sum += reference::luminance(r.image[i]);
            ++n;
        }
    const float key = float(std::max(n ? sum / double(n) : 0.0, 1e-6));
    QImage out(r.width, r.height, QImage::Format_RGB888);
    for (int y = 0; y < r.height; ++y) {
        uchar* line = out.scanLine(y);
        for (int x = 0; x < r.width; ++x) {
            const glm::vec3 c = r.image[std::size_t(y) * std::size_t(r.width) + std::size_t(x)];
            for (int k = 0; k < 3; ++k) {
                const float v = std::isfinite(c[k]) ? std::max(c[k], 0.0f) : 0.0f;
                line[3 * x + k] = uchar(std::lround(255.0f * std::pow(v / (v + key), 1.0f / 2.2f)));
            }
        }
    }
    return out;
}

} // namespace

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
                      [this, generation](const reference::ReferenceImage& image) {
                          // Its own noise: the MARE a noiseless copy of itself would show.
                          const reference::ErrorMetrics noise =
                              reference::compareImages({image.width, image.height, &image.image},
                                                       {image.width, image.height, &image.image},
                                                       &image.imageVariance, &image.coverage);
                          const QImage shown = displayImage(image);
                          const int spp = image.samplesPerPixel;
                          const double seconds = image.seconds;
                          QMetaObject::invokeMethod(
                              this,
                              [this, generation, shown, spp, noise, seconds] {
                                  if (generation == generation_)
                                      emit passDone(shown, spp, noise.noiseMare, seconds);
                              },
                              Qt::QueuedConnection);
                      });
    });
}

} // namespace lpv::editor
