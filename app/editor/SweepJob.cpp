#include "SweepJob.h"

#include "lpv/bench/Machine.h"
#include "lpv/bench/MeasuredSweep.h"
#include "lpv/reference/Preview.h"

#include <QDateTime>
#include <QMetaObject>

namespace lpv::editor {

QImage toQImage(const scene::Image8& image) {
    if (image.width <= 0 || image.height <= 0)
        return {};
    const QImage::Format format = image.channels == 3 ? QImage::Format_RGB888 : QImage::Format_RGBA8888;
    return QImage(image.pixels.data(), image.width, image.height, image.width * image.channels, format).copy();
}

SweepJob::SweepJob(QObject* parent) : QObject(parent) {}

SweepJob::~SweepJob() {
    cancel_ = true;
    if (worker_.joinable())
        worker_.join();
}

bool SweepJob::start(SweepJobSpec spec) {
    if (running_)
        return false;
    if (worker_.joinable())
        worker_.join();
    cancel_ = false;
    running_ = true;
    worker_ = std::thread([this, spec = std::move(spec)]() mutable { run(std::move(spec)); });
    return true;
}

void SweepJob::post(std::function<void()> onGui) {
    QMetaObject::invokeMethod(this, std::move(onGui), Qt::QueuedConnection);
}

void SweepJob::run(SweepJobSpec spec) {
    auto saved = std::make_shared<bench::SavedSweep>();
    saved->base = bench::settingsOf(spec.project.parameters); // the user's: what a click applies
    // Timings of every pass every frame, not of the first frame's volumes again.
    (void)spec.project.parameters.setFromText("lpv.reuse", "false", "sweep");

    saved->width = spec.width;
    saved->height = spec.height;
    saved->frames = spec.frames;
    saved->warmup = spec.warmup;
    saved->referenceSpp = spec.referenceSpp;
    saved->createdAt = QDateTime::currentDateTimeUtc().toString(Qt::ISODate).toStdString();
    saved->previews.resize(spec.combinations.size());
    float key = -1.0f; // every preview exposed alike, by the first reference's mean

    bench::MeasuredSweepCallbacks callbacks;
    callbacks.progress = [this](double fraction, const std::string& text) {
        post([this, fraction, text = QString::fromStdString(text)] { emit progress(fraction, text); });
        return !cancel_;
    };
    callbacks.runDone = [&](int index, const bench::SweepRun& run, const std::vector<glm::vec3>& layer,
                            const std::vector<float>& coverage) {
        if (key < 0.0f)
            key = reference::meanLuminance(layer, coverage);
        bench::SweepRun kept = run;
        kept.indirectPixels.clear();
        kept.imagePixels.clear();
        const scene::Image8 preview =
            reference::previewImage(run.indirectPixels, spec.width, 0, 0, spec.width, spec.height, key);
        saved->previews[std::size_t(index)] = preview;
        post([this, index, kept, image = toQImage(preview)] { emit runFinished(index, kept, image); });
    };
    auto result = bench::measureSweep(spec, callbacks);
    running_ = false;
    if (!result) {
        const bool cancelled = result.error().code == scene::ErrorCode::Cancelled;
        const QString message = cancelled ? tr("Stopped: %1").arg(QString::fromStdString(result.error().message))
                                          : QString::fromStdString(result.error().describe());
        post([this, message, cancelled] { emit failed(message, cancelled); });
        return;
    }
    const reference::ReferenceImage& ref = result->reference;
    const std::vector<glm::vec3>& layer = result->referenceBounces == 1 ? ref.indirectOne : ref.indirectMulti;
    saved->referencePreview = reference::previewImage(layer, ref.width, 0, 0, ref.width, ref.height, key);
    saved->referenceSeconds = ref.seconds;
    saved->machine = bench::describeMachine(result->gl.renderer, result->gl.version);
    saved->runs = std::move(result->runs);
    for (bench::SweepRun& r : saved->runs) {
        r.indirectPixels.clear();
        r.imagePixels.clear();
    }
    if (!saved->runs.empty())
        saved->referenceNoiseMare = saved->runs.front().indirect.noiseMare;
    std::shared_ptr<const bench::SavedSweep> done = saved;
    const QString timing =
        tr("%1 interleaved timing rounds (%2); %3")
            .arg(result->rounds)
            .arg(QString::fromStdString(result->stopReason), QString::fromStdString(result->load));
    post([this, done, timing] { emit finished(done, timing); });
}

} // namespace lpv::editor
