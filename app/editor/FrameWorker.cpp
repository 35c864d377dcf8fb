#include "FrameWorker.h"

#include "BakedRadiosityCache.h"

#include "lpv/renderer/ForwardRenderer.h"
#include "lpv/renderer/GlContext.h"
#include "lpv/renderer/SceneAnalysis.h"

#include <QMetaObject>

#include <chrono>
#include <cstring>

#ifdef __linux__
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace lpv::editor {

namespace {

// The display image of the renderer's last frame (rows top to bottom).
QImage displayImage(const renderer::ForwardRenderer& renderer) {
    const std::vector<std::uint8_t> pixels = renderer.readDisplay();
    const int w = renderer.width(), h = renderer.height();
    if (w <= 0 || h <= 0 || pixels.size() < std::size_t(w) * std::size_t(h) * 4)
        return {};
    QImage image(w, h, QImage::Format_RGBA8888);
    for (int row = 0; row < h; ++row)
        std::memcpy(image.scanLine(row), pixels.data() + std::size_t(row) * std::size_t(w) * 4, std::size_t(w) * 4);
    return image;
}

// The pieces of a scene that are not its meshes, from `rest`, into `into`.
void takeAllButMeshes(scene::Scene& into, const scene::Scene& rest) {
    into.materials = rest.materials;
    into.objects = rest.objects;
    into.lights = rest.lights;
    into.cameras = rest.cameras;
    into.cameraPaths = rest.cameraPaths;
    into.sky = rest.sky;
}

// The rows of the passes that ran in the last frame. The timer keeps a row
// for every pass it ever timed, with its last time: a pass culled or reused
// since (the LPV of the project before, an effect switched off) must not
// count in this frame's total.
std::vector<renderer::PassTiming> timingsOfThisFrame(std::vector<renderer::PassTiming> table,
                                                     const renderer::FrameGraphReport& report) {
    std::erase_if(table, [&](const renderer::PassTiming& t) {
        const renderer::GraphPassReport* pass = report.find(t.pass);
        return t.samples == 0 || !pass || pass->status != renderer::PassStatus::Ran;
    });
    return table;
}

// The frame's HDR image as the Accuracy dock measures it (RGBA floats to RGB).
std::shared_ptr<const HdrFrame> readHdrFrame(const renderer::ForwardRenderer& renderer,
                                             const FrameRequest& request,
                                             const std::vector<renderer::PassTiming>& timings,
                                             const QImage& display) {
    const std::vector<float> rgba = renderer.readHdr();
    auto frame = std::make_shared<HdrFrame>();
    frame->width = renderer.width();
    frame->height = renderer.height();
    const std::size_t n = std::size_t(frame->width) * std::size_t(frame->height);
    if (rgba.size() < n * 4)
        return nullptr;
    frame->pixels.resize(n);
    for (std::size_t i = 0; i < n; ++i)
        frame->pixels[i] = {rgba[i * 4], rgba[i * 4 + 1], rgba[i * 4 + 2]};
    frame->camera = request.camera;
    frame->giMethod = request.parameters.getEnum("gi.method");
    frame->outputView = request.parameters.getEnum("output.view");
    frame->exposure = renderer.displayExposure(request.parameters);
    frame->tonemapper = request.parameters.getEnum("output.tonemapper");
    frame->display = display;
    for (const renderer::PassTiming& t : timings)
        frame->gpuMs += t.lastMs;
    return frame;
}

} // namespace

FrameWorker::FrameWorker(QObject* parent) : QObject(parent), thread_([this] { run(); }) {}

FrameWorker::~FrameWorker() {
    {
        std::lock_guard lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
    thread_.join();
}

quint64 FrameWorker::submit(FrameRequest request) {
    std::lock_guard lock(mutex_);
    if (waiting_) {
        // Not rendered yet: fold the older request's news into this one.
        FrameRequest& old = *waiting_;
        if (!request.meshes)
            request.meshes = std::move(old.meshes);
        request.changes |= old.changes;
        if (!request.forgetTextures) {
            old.newTextures.insert(old.newTextures.end(), request.newTextures.begin(), request.newTextures.end());
            request.newTextures = std::move(old.newTextures);
            request.forgetTextures = old.forgetTextures;
        }
    }
    waiting_ = std::move(request);
    ++serial_;
    wake_.notify_one();
    return serial_;
}

quint64 FrameWorker::lastSerial() const {
    std::lock_guard lock(mutex_);
    return serial_;
}

std::optional<renderer::GlInfo> FrameWorker::glInfo() const {
    std::lock_guard lock(mutex_);
    return glInfo_;
}

// The render thread yields the CPU to the UI thread: on a software
// renderer (llvmpipe) a frame keeps every core busy for seconds, and the
// window must still answer at once. Linux gives each thread its own nice
// value, and the threads the GL driver starts from here inherit it.
void lowerThisThreadsPriority() {
#ifdef __linux__
    (void)setpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)), 10);
#endif
}

void FrameWorker::run() {
    lowerThisThreadsPriority();
    auto post = [this](std::shared_ptr<FrameResult> result) {
        QMetaObject::invokeMethod(this, [this, result] { emit frameReady(result); }, Qt::QueuedConnection);
    };
    auto context = renderer::HeadlessContext::create();
    std::optional<renderer::ForwardRenderer> renderer;
    QString startError;
    if (!context) {
        startError = QString::fromStdString(context.error().describe());
    } else {
        context->makeCurrent();
        renderer::installDebugOutputIfRequested();
        auto created = renderer::ForwardRenderer::create();
        if (created)
            renderer.emplace(std::move(*created));
        else
            startError = QString::fromStdString(created.error().describe());
        const renderer::GlInfo& info = context->info();
        std::lock_guard lock(mutex_);
        glInfo_ = info;
    }

    scene::Scene scene; // the worker's own copy: meshes as last sent, the rest as last sent
    scene::TextureImages textures;
    BakedRadiosityCache baked;
    bool uploaded = false;
    std::optional<std::chrono::steady_clock::time_point> lastFrame;
    // GPU memory: asked of the driver at most once a second, not every frame.
    std::optional<renderer::GpuMemoryInfo> gpuMemory;
    std::optional<std::chrono::steady_clock::time_point> lastMemoryQuery;
    for (;;) {
        FrameRequest request;
        quint64 serial = 0;
        {
            std::unique_lock lock(mutex_);
            wake_.wait(lock, [this] { return stop_ || waiting_; });
            if (stop_)
                break;
            request = std::move(*waiting_);
            waiting_.reset();
            serial = serial_;
        }
        auto result = std::make_shared<FrameResult>();
        result->serial = serial;
        if (!renderer) {
            result->error = startError;
            post(result);
            continue;
        }
        if (request.changes == Changes(Change::Everything))
            renderer->timer().clearHistory(); // another project: its passes' statistics start again
        if (request.forgetTextures)
            textures.clear();
        for (const auto& images : request.newTextures)
            for (const auto& [key, image] : *images)
                textures.insert_or_assign(key, image);
        if (request.meshes)
            scene.meshes = *request.meshes;
        if (request.rest)
            takeAllButMeshes(scene, *request.rest);
        if (!uploaded || request.meshes || (request.changes & Change::Geometry)) {
            renderer->setScene(scene, textures);
            uploaded = true;
        } else {
            if ((request.changes & Change::Materials) || !request.newTextures.empty())
                renderer->updateMaterials(scene, textures);
            if (request.changes & (Change::Transforms | Change::Structure))
                renderer->updateObjects(scene);
        }
        if (request.meshes || request.forgetTextures || !request.newTextures.empty() ||
            (request.changes & (Change::Transforms | Change::Structure | Change::Geometry | Change::Materials |
                                Change::Lights)))
            baked.sceneChanged();
        const bool showsBaked = renderer::showsBakedRadiosity(request.parameters) ||
                                (request.split && (renderer::showsBakedRadiosity(request.split->first) ||
                                                   renderer::showsBakedRadiosity(request.split->second)));
        if (showsBaked && !request.texturesPending) {
            renderer->setBakedRadiosity(
                baked.update(scene, textures, request.projectFile, request.radiosityGeneration));
            result->radiosityNote = QString::fromStdString(baked.message());
            result->radiosityFailed = baked.failed();
        }
        renderer->setLpvCapture(request.visualizers.lpv);
        renderer->setShadowCascadeTint(request.visualizers.shadowTint);
        // Auto exposure adapts over the real time between frames; the split
        // view's halves are two presets through one renderer, so each is
        // metered on its own.
        const auto now = std::chrono::steady_clock::now();
        renderer->setExposureTimeStep(request.split || !lastFrame
                                          ? std::nullopt
                                          : std::optional<double>(std::chrono::duration<double>(now - *lastFrame).count()));
        lastFrame = now;

        const int w = std::max(1, request.width), h = std::max(1, request.height);
        auto renderWith = [&](const scene::ParameterSet& params) {
            auto ok = renderer->render(scene, params, request.camera, w, h);
            if (!ok)
                result->error = QString::fromStdString(ok.error().describe());
            return bool(ok);
        };
        if (request.split) {
            // The same camera twice; each half of the image shows one preset.
            if (renderWith(request.split->first)) {
                result->image = displayImage(*renderer);
                if (renderWith(request.split->second)) {
                    const QImage right = displayImage(*renderer);
                    for (int row = 0; row < h && !result->image.isNull() && !right.isNull(); ++row)
                        std::memcpy(result->image.scanLine(row) + std::size_t(w / 2) * 4,
                                    right.constScanLine(row) + std::size_t(w / 2) * 4, std::size_t(w - w / 2) * 4);
                }
            }
        } else if (renderWith(request.parameters)) {
            result->image = displayImage(*renderer);
        }
        // The read-back above waited for the GPU, so collecting the queries
        // now stalls nothing and the table holds this frame's times.
        renderer->timer().resolveAll();
        result->timings = timingsOfThisFrame(renderer->timer().table(), renderer->graphReport());
        if (!lastMemoryQuery || now - *lastMemoryQuery >= std::chrono::seconds(1)) {
            gpuMemory = renderer::queryGpuMemory();
            lastMemoryQuery = now;
        }
        result->gpuMemory = gpuMemory;
        result->lpvNote = QString::fromStdString(renderer->lpvNote());
        if (result->error.isEmpty() && request.readHdr && !request.split)
            result->hdr = readHdrFrame(*renderer, request, result->timings, result->image);
        if (result->error.isEmpty() && request.visualizers.active()) {
            auto frame = std::make_shared<VisualizerFrame>();
            frame->cascades = renderer->lpvCascadeFrames();
            frame->lpvNote = renderer->lpvNote();
            if (const renderer::LpvSnapshot* snapshot = renderer->lpvSnapshot())
                frame->lpv = *snapshot;
            if (request.visualizers.rsm)
                frame->rsm = renderer->debugImages("rsm");
            if (request.visualizers.shadow)
                frame->shadow = renderer->debugImages("shadowMaps");
            result->visualizers = frame;
        }
        post(result);
    }
    renderer.reset(); // its GL objects, with the context still current
}

} // namespace lpv::editor
