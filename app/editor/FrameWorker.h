#pragma once
// The viewport's frames render on a worker thread in a headless GL context
// of their own (EGL, as `lpv render` does), so no UI event waits for a frame
// (issue #25: a Sponza frame takes seconds on llvmpipe, and the window froze
// for all of it). The viewport sends what a frame needs and shows the last
// finished image; requests sent while a frame renders are merged, so the
// worker renders the newest state next and never falls behind.
#include "Document.h"
#include "VisualizerOverlay.h"

#include "lpv/renderer/GlContext.h"
#include "lpv/renderer/GpuTimer.h"
#include "lpv/scene/ParameterRegistry.h"
#include "lpv/scene/Scene.h"

#include <QImage>
#include <QObject>
#include <QString>

#include <condition_variable>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>
#include <vector>

namespace lpv::editor {

// Everything one frame depends on. The meshes travel only when they changed
// (an import, a new project): a parameter edit or a camera move sends no
// geometry, and the rest of the scene is small.
struct FrameRequest {
    std::shared_ptr<const std::vector<scene::Mesh>> meshes; // null: keep the worker's
    std::shared_ptr<const scene::Scene> rest;               // the scene without its meshes
    Changes changes;                                        // what changed since the last request
    std::vector<std::shared_ptr<const scene::TextureImages>> newTextures; // decoded since, to add
    bool forgetTextures = false; // another project: its files may differ under the same names
    scene::ParameterSet parameters;
    std::optional<std::pair<scene::ParameterSet, scene::ParameterSet>> split; // A | B halves
    scene::Camera camera;
    int width = 1;
    int height = 1;
    VisualizerRequest visualizers;
    // The Accuracy dock's opt-in: read the frame's linear HDR image back
    // (a GPU stall and a copy that normal frames do not pay). Not with a split.
    bool readHdr = false;
    // gi.method = radiosity: the project file whose saved solution frames
    // show (empty: unsaved), a number bumped whenever that solution may have
    // changed (a solve saved it, the project was saved), and whether textures
    // are still decoding (the solution is checked against the scene's
    // reflectances, which they are part of: it waits for them).
    std::string projectFile;
    quint64 radiosityGeneration = 0;
    bool texturesPending = false;
};

// The linear HDR image of a frame (before exposure and tonemapping, what
// `lpv render` writes to EXR) and what it was rendered with, so it is
// compared with a reference of the same view.
struct HdrFrame {
    scene::Camera camera;
    int width = 0;
    int height = 0;
    std::vector<glm::vec3> pixels; // rows top to bottom
    std::string giMethod;          // gi.method of the frame
    std::string outputView;        // output.view: final, indirect or direct
    double gpuMs = 0.0;            // the frame's GPU time: the sum of its passes' times
    // How the frame's display image was mapped (issue #43): a reference shown
    // beside it goes through the same (DisplayMapping.h).
    double exposure = 1.0;  // the scale tonemap.frag applied (renderer::ForwardRenderer::displayExposure)
    std::string tonemapper; // output.tonemapper of the frame
    QImage display;         // the frame as the GPU mapped it (RGBA8)
};

struct FrameResult {
    quint64 serial = 0; // the newest request this frame includes
    QImage image;       // width x height of the request (RGBA8)
    std::vector<renderer::PassTiming> timings;
    QString lpvNote;
    // gi.method = radiosity: the solution shown ("FILE: 438 patches, ...") or
    // why there is none; empty when the frame did not ask for one.
    QString radiosityNote;
    bool radiosityFailed = false;
    QString error; // empty when the frame rendered
    std::optional<renderer::GpuMemoryInfo> gpuMemory; // as the driver reports it, if it does
    std::shared_ptr<const VisualizerFrame> visualizers; // when the request asked for any
    std::shared_ptr<const HdrFrame> hdr;                // when the request asked for it
};

class FrameWorker : public QObject {
    Q_OBJECT
public:
    explicit FrameWorker(QObject* parent = nullptr);
    ~FrameWorker() override; // the thread ends; its GL objects die in it

    // Merges `request` into the one waiting (if any) and wakes the thread.
    // Returns the request's serial, which FrameResult::serial reaches once
    // a frame includes it.
    quint64 submit(FrameRequest request);
    // The serial of the last request submitted.
    quint64 lastSerial() const;
    // The renderer's GL driver (vendor, renderer, version, EGL platform), once the context exists.
    std::optional<renderer::GlInfo> glInfo() const;

signals:
    // On the GUI thread, after every frame (also a failed one: see error).
    void frameReady(std::shared_ptr<const FrameResult> result);

private:
    void run();

    mutable std::mutex mutex_;
    std::condition_variable wake_;
    std::optional<FrameRequest> waiting_;
    quint64 serial_ = 0;
    bool stop_ = false;
    std::optional<renderer::GlInfo> glInfo_;
    std::thread thread_;
};

} // namespace lpv::editor
