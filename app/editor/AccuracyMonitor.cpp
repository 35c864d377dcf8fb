#include "AccuracyMonitor.h"

#include "Document.h"
#include "Viewport.h"

#include "lpv/reference/Magma.h"
#include "lpv/renderer/ReferenceLights.h"
#include "lpv/renderer/SceneAnalysis.h"

#include <QThread>

#include <chrono>

namespace lpv::editor {

namespace {

QImage toQImage(const scene::Image8& rgba) {
    if (rgba.width <= 0 || rgba.height <= 0 || rgba.channels != 4)
        return {};
    return QImage(rgba.pixels.data(), rgba.width, rgba.height, rgba.width * 4, QImage::Format_RGBA8888)
        .copy();
}

// What changes the scene the reference traces (a parameter edit or a
// preset does not; the view's cameras list and paths do not either).
constexpr Changes kSceneChanges = Change::Transforms | Change::Structure | Change::Geometry |
                                  Change::Materials | Change::Lights | Change::Sky;

} // namespace

std::shared_ptr<AccuracySample> measureFrame(const HdrFrame& frame, const reference::ReferenceImage& ref) {
    auto sample = std::make_shared<AccuracySample>();
    const auto start = std::chrono::steady_clock::now();
    // Like `lpv compare`: the final image against the reference's image, the
    // LPV's indirect view against its multi-bounce indirect layer.
    const bool indirect = frame.outputView == "indirect";
    sample->layer = indirect ? "indirect" : "image";
    reference::AccuracyOptions options;
    options.keepFlipMap = true;
    options.keepDisplayImages = true;
    reference::Accuracy a = reference::measureAccuracy(
        {frame.width, frame.height, &frame.pixels},
        {ref.width, ref.height, indirect ? &ref.indirectMulti : &ref.image},
        indirect ? &ref.indirectMultiVariance : &ref.imageVariance, &ref.coverage, options);
    sample->heatMap = toQImage(reference::magmaImage(a.flipMap.error, a.flipMap.width, a.flipMap.height));
    sample->frameDisplay = toQImage(a.testDisplay);
    sample->referenceDisplay = toQImage(a.referenceDisplay);
    a.flipMap = {};
    a.testDisplay = a.referenceDisplay = {};
    // The split as the frame is seen: one exposure (the frame's) and one
    // operator for both halves, so equal radiance is an equal pixel.
    const DisplayMapping mapping{frame.exposure, tonemapperOf(frame.tonemapper)};
    sample->frameTonemapped = toQImage(tonemapImage(frame.pixels, frame.width, frame.height, mapping));
    sample->referenceTonemapped =
        toQImage(tonemapImage(indirect ? ref.indirectMulti : ref.image, ref.width, ref.height, mapping));
    sample->accuracy = std::move(a);
    sample->samplesPerPixel = ref.samplesPerPixel;
    sample->referenceSeconds = ref.seconds;
    sample->gpuMs = frame.gpuMs;
    sample->measureMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return sample;
}

AccuracyMonitor::AccuracyMonitor(Document* document, Viewport* viewport, QObject* parent)
    : QObject(parent), document_(document), viewport_(viewport) {
    restartTimer_.setSingleShot(true);
    restartTimer_.setInterval(150);
    connect(&restartTimer_, &QTimer::timeout, this, &AccuracyMonitor::restartReference);
    connect(viewport_, &Viewport::hdrFrameRendered, this, &AccuracyMonitor::onFrame);
    // At once, not when the next frame comes: until then the figures would be of the old view.
    connect(viewport_, &Viewport::viewCameraChanged, this, [this] {
        if (tracing_)
            scheduleRestart();
    });
    connect(viewport_, &Viewport::frameRendered, this, [this] {
        // A split frame is two presets and reads no HDR image back.
        if (tracing_ && viewport_->splitActive())
            setStatus(tr("The A/B split view renders two presets: turn it off to measure the frame."));
    });
    connect(&reference_, &LiveReference::imageDone, this, &AccuracyMonitor::onReferenceImage);
    connect(&reference_, &LiveReference::failed, this,
            [this](const QString& message) { setStatus(tr("The reference cannot be traced: ") + message); });
    connect(document_, &Document::changed, this, &AccuracyMonitor::onDocumentChanged);
}

AccuracyMonitor::~AccuracyMonitor() {
    if (job_) {
        job_->wait(); // it writes only into its own sample, but must end before the process
        delete job_;
    }
}

void AccuracyMonitor::setStatus(const QString& status) {
    if (status == status_)
        return;
    status_ = status;
    emit statusChanged(status_);
}

void AccuracyMonitor::setTracing(bool on) {
    if (tracing_ == on)
        return;
    tracing_ = on;
    reference_.setSendImages(on);
    viewport_->setHdrReadback(on);
    ++generation_;
    image_.reset();
    latest_.reset();
    frame_.reset();
    traced_.reset();
    restartTimer_.stop();
    if (!on) {
        reference_.stop();
        sceneChanged_ = true;
        setStatus({});
    } else {
        setStatus(tr("Waiting for a frame of the view..."));
    }
    showImages();
}

void AccuracyMonitor::setHeatMapShown(bool on) {
    heatMap_ = on;
    showImages();
}

void AccuracyMonitor::setSplitShown(bool on) {
    split_ = on;
    showImages();
}

void AccuracyMonitor::setReferenceMapping(ReferenceMapping mapping) {
    mapping_ = mapping;
    showImages();
}

void AccuracyMonitor::showImages() {
    const bool have = tracing_ && latest_;
    viewport_->setErrorOverlay(have && heatMap_ ? latest_->heatMap : QImage());
    if (have && split_ && mapping_ == ReferenceMapping::Preview)
        viewport_->setComparisonSplit(latest_->frameDisplay, latest_->referenceDisplay);
    else if (have && split_)
        viewport_->setComparisonSplit(latest_->frameTonemapped, latest_->referenceTonemapped);
    else
        viewport_->setComparisonSplit({}, {});
}

std::string AccuracyMonitor::referenceSettings() {
    if (!settingsCache_) {
        const scene::Scene& s = document_->scene();
        const scene::ParameterSet& p = document_->parameters();
        const renderer::ReferenceLights lights =
            renderer::decideReferenceLights(s, renderer::analyseSceneTraits(s), p);
        settingsCache_ = "bounces " + std::to_string(p.getInt("reference.bounces")) + ", sky " +
                         (lights.sky ? "on" : "off") + ", emissive " + (lights.emissive ? "on" : "off");
    }
    return *settingsCache_;
}

void AccuracyMonitor::onDocumentChanged(Changes c) {
    if (c & (kSceneChanges | Change::Parameters))
        settingsCache_.reset();
    if (!tracing_)
        return;
    if (c & kSceneChanges) {
        sceneChanged_ = true;
        scheduleRestart();
    } else if ((c & Change::Parameters) && traced_ && referenceSettings() != tracedSettings_) {
        scheduleRestart();
    }
}

void AccuracyMonitor::scheduleRestart() {
    reference_.invalidate(); // what it traces now is of the old view
    ++generation_;
    image_.reset();
    latest_.reset();
    traced_.reset();
    showImages();
    setStatus(tr("The view changed: its reference starts again..."));
    restartTimer_.start();
}

void AccuracyMonitor::restartReference() {
    if (!tracing_)
        return;
    // The view as it is now; frames of it are on their way.
    traced_ = viewport_->viewCamera();
    tracedWidth_ = viewport_->renderSize().width();
    tracedHeight_ = viewport_->renderSize().height();
    tracedSettings_ = referenceSettings();
    reference_.restart(document_->scene(), document_->parameters(), *traced_, tracedWidth_, tracedHeight_,
                       document_->projectDir(), sceneChanged_);
    sceneChanged_ = false;
    setStatus(tr("Tracing the reference of this view (%1 x %2)...").arg(tracedWidth_).arg(tracedHeight_));
}

void AccuracyMonitor::onFrame(const std::shared_ptr<const HdrFrame>& frame) {
    if (!tracing_ || !frame)
        return;
    frame_ = frame;
    if (frame->giMethod == "reference") {
        // The viewport already shows the path tracer; the rasterised frame
        // is direct light only and not what the user sees.
        if (reference_.running()) {
            reference_.stop();
            sceneChanged_ = true;
        }
        ++generation_;
        image_.reset();
        latest_.reset();
        traced_.reset();
        showImages();
        setStatus(tr("gi.method = reference: the view is the reference itself. Choose another method to "
                     "measure it."));
        return;
    }
    if (frame->outputView == "direct") {
        setStatus(tr("output.view = direct: the reference has no direct-only layer."));
        return;
    }
    // A frame of a view the user has already left: a newer one is coming.
    if (!(frame->camera == viewport_->viewCamera()) ||
        QSize(frame->width, frame->height) != viewport_->renderSize())
        return;
    const bool traced = traced_ && *traced_ == frame->camera && tracedWidth_ == frame->width &&
                        tracedHeight_ == frame->height;
    if (!traced) {
        if (!restartTimer_.isActive())
            scheduleRestart(); // the view changed without a camera move (a resize), or it was off
        return;
    }
    measure();
}

void AccuracyMonitor::onReferenceImage(const std::shared_ptr<const reference::ReferenceImage>& image) {
    if (!tracing_ || !traced_)
        return;
    image_ = image;
    measure();
}

void AccuracyMonitor::measure() {
    if (!frame_ || !image_ || !traced_ || !(*traced_ == frame_->camera) || frame_->width != image_->width ||
        frame_->height != image_->height)
        return;
    if (job_) {
        pending_ = true; // the newest pair is measured once this one is done
        return;
    }
    auto sample = std::make_shared<std::shared_ptr<AccuracySample>>();
    job_ =
        QThread::create([frame = frame_, image = image_, sample] { *sample = measureFrame(*frame, *image); });
    connect(job_, &QThread::finished, this, [this, sample, generation = generation_] {
        job_->deleteLater();
        job_ = nullptr;
        finishMeasurement(*sample, generation);
        if (std::exchange(pending_, false))
            measure();
    });
    job_->start();
}

void AccuracyMonitor::finishMeasurement(std::shared_ptr<AccuracySample> sample, unsigned generation) {
    if (!sample || generation != generation_ || !tracing_)
        return; // the view changed meanwhile
    latest_ = std::move(sample);
    // The reference's samples and time are in the dock's Reference row; the
    // status line said them again (issue #46) and now says what the figures are.
    setStatus(tr("Measured: the latest frame against the reference so far; the figures update as it "
                 "converges."));
    showImages();
    emit measured(latest_);
}

} // namespace lpv::editor
