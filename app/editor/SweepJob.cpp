#include "SweepJob.h"

#include "lpv/bench/Machine.h"
#include "lpv/bench/Reference.h"
#include "lpv/reference/Preview.h"
#include "lpv/renderer/ReferenceLights.h"
#include "lpv/renderer/SceneAnalysis.h"

#include <QDateTime>
#include <QMetaObject>

#include <chrono>
#include <map>
#include <tuple>

namespace lpv::editor {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
}

QString timeLeft(double seconds) {
    if (seconds < 60.0)
        return QObject::tr("about %1 s left").arg(int(seconds + 0.5));
    return QObject::tr("about %1 min left").arg(int(seconds / 60.0 + 0.5));
}

// Settings measured against one reference: the same lpv.bounces (its layer)
// and the same lights traced (the sky and emissive surfaces, which follow
// what the LPV injects).
struct ReferenceGroup {
    scene::ParameterSet parameters; // of the first run in it, for the trace
    int bounces = 1;
    std::vector<int> runs; // indices into the combinations
};

std::vector<ReferenceGroup> groupByReference(const SweepJobSpec& spec) {
    const renderer::SceneTraits traits = renderer::analyseSceneTraits(spec.project.scene);
    std::map<std::tuple<int, bool, bool>, std::size_t> index;
    std::vector<ReferenceGroup> groups;
    for (std::size_t i = 0; i < spec.combinations.size(); ++i) {
        scene::ParameterSet p = spec.project.parameters;
        for (const auto& [key, value] : spec.combinations[i])
            (void)p.setFromText(key, value, "sweep");
        const int bounces = p.getInt("lpv.bounces");
        const renderer::ReferenceLights lights = renderer::decideReferenceLights(spec.project.scene, traits, p);
        const auto key = std::make_tuple(bounces, lights.sky, lights.emissive);
        auto [it, added] = index.emplace(key, groups.size());
        if (added)
            groups.push_back({p, bounces, {}});
        groups[it->second].runs.push_back(int(i));
    }
    return groups;
}

} // namespace

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
    auto fail = [this](const QString& message, bool cancelled) {
        running_ = false;
        post([this, message, cancelled] { emit failed(message, cancelled); });
    };
    const std::vector<ReferenceGroup> groups = groupByReference(spec);
    const int runCount = int(spec.combinations.size());
    // Progress: the references take the first part of the bar in proportion
    // to what is known of their cost (none yet), so weigh each like a run.
    const double units = double(groups.size() + spec.combinations.size());
    double unitsDone = 0.0;
    auto saved = std::make_shared<bench::SavedSweep>();
    saved->width = spec.width;
    saved->height = spec.height;
    saved->frames = spec.frames;
    saved->warmup = spec.warmup;
    saved->referenceSpp = spec.referenceSpp;
    saved->base = bench::settingsOf(spec.project.parameters);
    saved->createdAt = QDateTime::currentDateTimeUtc().toString(Qt::ISODate).toStdString();
    saved->runs.resize(std::size_t(runCount));
    saved->previews.resize(std::size_t(runCount));
    float key = 0.0f; // every preview exposed alike, by the first reference's mean
    const Clock::time_point runsStart = Clock::now();
    int runsDone = 0;
    for (std::size_t g = 0; g < groups.size(); ++g) {
        const ReferenceGroup& group = groups[g];
        scene::Project traced = spec.project;
        traced.parameters = group.parameters;
        (void)traced.parameters.setFromText("reference.samplesPerPixel", std::to_string(spec.referenceSpp), "sweep");
        (void)traced.parameters.setFromText("reference.bounces", std::to_string(group.bounces), "sweep");
        (void)traced.parameters.setFromText("reference.maxSeconds", "0", "sweep");
        bench::ReferenceCallbacks callbacks;
        const QString label = tr("Reference %1 of %2").arg(g + 1).arg(groups.size());
        callbacks.progress = [&](const reference::TraceProgress& p) {
            const double f = (unitsDone + double(p.samplesDone) / std::max(p.samplesTarget, 1)) / units;
            const QString text = label + tr(": %1/%2 spp, %3 s").arg(p.samplesDone).arg(p.samplesTarget).arg(
                                                 p.seconds, 0, 'f', 1);
            post([this, f, text] { emit progress(f, text); });
            return !cancel_;
        };
        auto reference = bench::traceReference(traced, spec.projectDir, spec.camera,
                                               {spec.width, spec.height, 0, {}}, callbacks);
        if (!reference)
            return fail(QString::fromStdString(reference.error().describe()), false);
        if (cancel_)
            return fail(tr("Stopped while tracing the reference"), true);
        unitsDone += 1.0;
        const reference::ReferenceImage& ref = reference->image;
        const std::vector<glm::vec3>& layer = group.bounces == 1 ? ref.indirectOne : ref.indirectMulti;
        if (g == 0) {
            key = reference::meanLuminance(layer, ref.coverage);
            saved->referencePreview = reference::previewImage(layer, ref.width, 0, 0, ref.width, ref.height, key);
            saved->referenceSeconds = ref.seconds;
        }

        bench::SweepSpec sweep;
        sweep.project = spec.project;
        (void)sweep.project.parameters.setFromText("lpv.reuse", "false", "sweep");
        sweep.projectDir = spec.projectDir;
        sweep.camera = spec.camera;
        sweep.width = spec.width;
        sweep.height = spec.height;
        sweep.frames = spec.frames;
        sweep.warmup = spec.warmup;
        sweep.referenceBounces = group.bounces;
        for (int i : group.runs)
            sweep.combinations.push_back(spec.combinations[std::size_t(i)]);
        if (auto problem = bench::checkSweep(sweep, "the reference"))
            return fail(QString::fromStdString(*problem), false);
        bench::SweepCallbacks sweepCallbacks;
        sweepCallbacks.progress = [&](const bench::SweepProgress& p) {
            if (p.done < p.total) {
                const double f = (unitsDone + p.done) / units;
                QString text = tr("Setting %1 of %2: %3").arg(runsDone + 1).arg(runCount).arg(
                    QString::fromStdString(p.label));
                if (runsDone > 0)
                    text += " (" + timeLeft(secondsSince(runsStart) / runsDone * (runCount - runsDone)) + ")";
                post([this, f, text] { emit progress(f, text); });
            }
            return !cancel_;
        };
        int inGroup = 0;
        sweepCallbacks.runDone = [&](const bench::SweepRun& run) {
            const int index = group.runs[std::size_t(inGroup++)];
            ++runsDone;
            bench::SweepRun kept = run;
            kept.indirectPixels.clear();
            const scene::Image8 preview =
                reference::previewImage(run.indirectPixels, spec.width, 0, 0, spec.width, spec.height, key);
            saved->runs[std::size_t(index)] = kept;
            saved->previews[std::size_t(index)] = preview;
            const QImage image = toQImage(preview);
            post([this, index, kept, image] { emit runFinished(index, kept, image); });
        };
        auto result = bench::runSweep(sweep, ref, sweepCallbacks);
        if (!result) {
            const bool cancelled = result.error().code == scene::ErrorCode::Cancelled;
            return fail(cancelled ? tr("Stopped: %1").arg(QString::fromStdString(result.error().message))
                                  : QString::fromStdString(result.error().describe()),
                        cancelled);
        }
        unitsDone += double(group.runs.size());
        if (g == 0) {
            saved->machine = bench::describeMachine(result->gl.renderer, result->gl.version);
            if (!result->runs.empty())
                saved->referenceNoiseMare = result->runs.front().indirect.noiseMare;
        }
    }
    running_ = false;
    std::shared_ptr<const bench::SavedSweep> done = saved;
    post([this, done] {
        emit progress(1.0, tr("Done: %1 settings").arg(done->runs.size()));
        emit finished(done);
    });
}

} // namespace lpv::editor
