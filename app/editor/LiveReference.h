#pragma once
// gi.method = reference in the editor (issue #26 item 2): the CPU path tracer
// (reference/PathTracer.h, Embree, worker threads) renders the current view
// progressively on its own thread; samples accumulate while the view and the
// scene stay still, and any change restarts it. Each pass sends the image so
// far (linear, and mapped for display through the frame's exposure and
// tonemapper, issue #43, or `--preview`'s mapping when asked), its sample
// count and its own noise level (the MARE its variance implies, as `lpv
// compare` reports it).
#include "lpv/renderer/DisplayMapping.h"

#include "lpv/reference/ReferenceImage.h"
#include "lpv/scene/Camera.h"
#include "lpv/scene/ParameterRegistry.h"
#include "lpv/scene/Scene.h"

#include <QImage>
#include <QObject>

#include <atomic>
#include <memory>
#include <thread>

namespace lpv::editor {

// The display mapping lives in the renderer (Qt-free); the editor names it unqualified.
using renderer::DisplayMapping;
using renderer::mapToDisplay;
using renderer::meteredMapping;
using renderer::ReferenceMapping;
using renderer::Tonemapper;
using renderer::tonemapImage;
using renderer::tonemapperOf;

// A pass's image before any display mapping.
struct LinearImage {
    int width = 0, height = 0;
    std::vector<glm::vec3> pixels; // radiance, rows top to bottom
    std::vector<float> coverage;   // per pixel: 1 where the view hits geometry
};

// How the view shows it: through the mapping the renderer would give a frame
// of these parameters (DisplayMapping.h's meteredMapping), or as `lpv
// reference --preview` maps it (x / (x + mean), its own mean).
QImage displayReference(const LinearImage& image, ReferenceMapping mapping,
                        const scene::ParameterSet& parameters);

class LiveReference : public QObject {
    Q_OBJECT
  public:
    explicit LiveReference(QObject* parent = nullptr);
    ~LiveReference() override;

    // Starts again from 0 samples with this view (the traced image is
    // `width` x `height`). `sceneChanged` = false keeps the last scene's
    // Embree scene and textures (only the view moved).
    void restart(const scene::Scene& scene, const scene::ParameterSet& params, const scene::Camera& camera,
                 int width, int height, const QString& projectDir, bool sceneChanged);
    // Passes of the current run are no longer sent (a restart is coming).
    void invalidate() { ++generation_; }
    // Stops tracing (gi.method left reference) and frees the scene.
    void stop();
    bool running() const { return worker_.joinable(); }
    // Also send each pass's linear image with its variance and coverage
    // (imageDone): the Accuracy dock measures against it. Off by default.
    void setSendImages(bool on) { sendImages_ = on; }
    // How passes from now on are mapped for display.
    void setMapping(ReferenceMapping mapping) { mapping_ = mapping; }

  signals:
    // After every pass of the current restart: the display image (mapped with
    // the parameters of the restart), the linear one (to map again when the
    // mapping changes), samples per pixel, the noise MARE of the image (0..1)
    // and the seconds traced.
    void passDone(const QImage& image, std::shared_ptr<const lpv::editor::LinearImage> linear,
                  int samplesPerPixel, double noiseMare, double seconds);
    // With setSendImages: the same pass as traced (right after passDone).
    void imageDone(std::shared_ptr<const lpv::reference::ReferenceImage> image);
    // The scene could not be traced (e.g. no geometry Embree accepts).
    void failed(const QString& message);

  private:
    struct Prepared; // Embree scene and textures, kept while only the view moves
    void join();

    std::thread worker_;
    std::atomic<bool> cancel_{false};
    std::shared_ptr<Prepared> prepared_;
    unsigned generation_ = 0; // passes of an older restart are dropped
    std::atomic<bool> sendImages_{false};
    std::atomic<ReferenceMapping> mapping_{ReferenceMapping::FrameTonemap};
};

} // namespace lpv::editor
