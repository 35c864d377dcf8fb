#pragma once
// The central 3D view. Its frames render on a worker thread (FrameWorker:
// the same renderer library as the CLI, in a headless GL context of its
// own), so no UI event waits for a frame; the widget shows the last finished
// frame, scaled to the view, with the gizmo, camera path and visualizer
// overlays drawn over it at once. It asks for a frame only when something
// changed, never in a busy loop: while flying, a timer runs only as long as
// a movement key is held.
//
// Mouse: left-click selects (ray picking); left-drag orbits (about the
// surface under the cursor), or drags a gizmo handle, or with L held turns
// the sun; middle-drag pans; wheel dollies towards the cursor by a fraction
// of the distance to what is under it; right-drag looks around, and with it
// held W/A/S/D/Q/E fly (Shift: faster). Keys: F frames the selection; Home
// goes back to the opening view; W/E/R pick the gizmo's move/rotate/scale
// mode when not flying.
#include "CameraController.h"
#include "Document.h"
#include "FrameWorker.h"
#include "LiveReference.h"
#include "TransformGizmo.h"
#include "VisualizerOverlay.h"

#include "lpv/renderer/GpuTimer.h"
#include "lpv/scene/Image.h"

#include <QElapsedTimer>
#include <QPointF>
#include <QWidget>
#include <QSet>
#include <QTimer>

class QPainter;

#include <functional>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

class QThread;

namespace lpv::editor {


class Viewport : public QWidget {
    Q_OBJECT
public:
    explicit Viewport(Document* document, QWidget* parent = nullptr);
    ~Viewport() override;

    // Errors from GL set-up or rendering, empty if none.
    const QString& lastError() const { return lastError_; }
    // The driver that renders the frames (the worker's context).
    QString glRenderer() const;
    // The image shown is of the current state: no frame waits or renders
    // (tests wait for this before they look at the view).
    bool frameUpToDate() const;
    // What the widget shows (the last frame with the overlays), as an image.
    QImage grabFramebuffer() { return grab().toImage(); }
    // The driver that renders the frames, once the worker's context exists.
    std::optional<renderer::GlInfo> renderGlInfo() const;
    // GPU memory as the driver reported it with the last frame (nothing where it does not say).
    const std::optional<renderer::GpuMemoryInfo>& gpuMemory() const { return gpuMemory_; }
    // Asks for one more frame of the same state (a benchmark, a screenshot
    // after the exposure settled).
    void renderAgain();
    // Textures are being decoded in the background (tests wait for this).
    bool texturesPending() const { return textureWorker_ != nullptr; }

    // The camera the user moves; starts at the project's first camera (or a
    // framing camera) whenever a project is opened.
    const scene::Camera& viewCamera() const { return controller_.camera(); }
    void setViewCamera(const scene::Camera& camera);
    void frameSelection();
    // The scene's opening view: its first camera, else one that frames its
    // bounds (app::firstView, as `lpv import` and `lpv render` see it).
    scene::Camera homeCamera() const;
    // Back to homeCamera (Home key, View > Home view).
    void homeView();

    GizmoMode gizmoMode() const { return gizmoMode_; }
    void setGizmoMode(GizmoMode mode);
    GizmoPivot gizmoPivotMode() const { return gizmoPivot_; }
    void setGizmoPivot(GizmoPivot pivot);
    // Where the gizmo of the selected object sits (world), and what rotate and scale turn about.
    std::optional<glm::vec3> gizmoPivot() const;
    GizmoSnap& snap() { return snap_; }

    // A/B split: the left half renders `a`, the right half `b` (named in the
    // corners); nothing = the project's own parameters over the whole view.
    void setSplit(std::optional<std::pair<scene::ParameterSet, scene::ParameterSet>> presets, QString labelA = {},
                  QString labelB = {});
    bool splitActive() const { return split_.has_value(); }

    // Renders at this fraction of the widget's pixels (0.1..1) and scales up:
    // keeps a software-rendered (llvmpipe) or slow GPU viewport responsive.
    void setResolutionScale(double scale);
    double resolutionScale() const { return resolutionScale_; }

    // The camera path drawn in the view with its keys as draggable handles (-1 = none).
    void setShownPath(int index);
    int shownPath() const { return shownPath_; }
    // Screen position (logical pixels) of a key of the shown path, if in front of the camera.
    std::optional<QPointF> keyScreenPosition(int key) const;

    // Picks the object under a widget position (logical pixels) and selects it (or clears the selection).
    void selectAt(const QPoint& position);

    // What the Visualizers dock wants from each frame (read-backs) and draws
    // over the view (cascade boxes, slice plane, probes). The default asks
    // for nothing, and then the renderer reads nothing back.
    void setVisualizerRequest(const VisualizerRequest& request);
    const VisualizerRequest& visualizerRequest() const { return vizRequest_; }

    // While a sweep times its settings (the Sweeps dock), the view asks for
    // no frame and its live reference stops: on llvmpipe they would share the
    // cores with the sweep and its timings would not be the settings' own.
    // The last frame stays shown with `why` over it; resuming renders again.
    void setFramesPaused(bool paused, const QString& why = {});
    bool framesPaused() const { return paused_; }

    // The Accuracy dock (issue #26): while on, every frame also reads back
    // its linear HDR image (hdrFrameRendered); off, frames pay nothing for it.
    void setHdrReadback(bool on);
    bool hdrReadback() const { return hdrReadback_; }
    // The FLIP heat map drawn over the frame (a null image: none).
    void setErrorOverlay(const QImage& heatMap);
    bool errorOverlayShown() const { return !errorOverlay_.isNull(); }
    // LPV | reference: the left half of `left` beside the right half of
    // `right` (both the view's images as the Accuracy dock compares them)
    // instead of the frame; null images: the frame as usual.
    void setComparisonSplit(const QImage& left, const QImage& right);
    bool comparisonSplitShown() const { return !comparisonLeft_.isNull() && !comparisonRight_.isNull(); }
    // gi.method = reference: how the live reference is shown (issue #43): through
    // the frame's exposure and tonemapper (the default) or `--preview`'s mapping.
    void setReferenceMapping(ReferenceMapping mapping);
    ReferenceMapping referenceMapping() const { return referenceMapping_; }
    // The live reference's last pass as the view shows it (null before one), and before mapping.
    const QImage& referenceDisplay() const { return referenceImage_; }
    const std::shared_ptr<const LinearImage>& referenceLinear() const { return referenceLinear_; }
    // The last frame as rendered (the GPU's display image, without overlays).
    const QImage& frameImage() const { return shownImage_; }
    // The size frames render at (the widget's pixels times the resolution scale).
    QSize renderSize() const { return {renderWidth(), renderHeight()}; }

  public slots:
    // gi.method = radiosity: the saved solution may have changed (a solve
    // saved it, the project was saved elsewhere): the next frame loads it again.
    void reloadBakedRadiosity();

  signals:
    // After every frame: the renderer's timing table (for the status bar and the profiler).
    void frameRendered(const std::vector<lpv::renderer::PassTiming>& timings);
    // What the LPV did in the last frame and why (the renderer's note), when it changes.
    void lpvNoteChanged(const QString& note);
    // gi.method = radiosity: the solution the frames show, or why there is
    // none (`failed`: they have direct light only), when it changes.
    void radiosityNoteChanged(const QString& note, bool failed);
    void renderFailed(const QString& message);
    void viewCameraChanged();
    // Background texture decoding started (count of materials) or finished (0, with warnings).
    void texturesLoading(int materials);
    void texturesLoaded(const QStringList& warnings);
    // After a frame rendered while a visualizer request is active: what it read back.
    void visualizerFrame(std::shared_ptr<const lpv::editor::VisualizerFrame> frame);
    // gi.method = reference: after every pass of the live path-traced view
    // (samples per pixel, its noise MARE 0..1, seconds since it restarted);
    // spp 0 when it stopped.
    void referenceProgress(int samplesPerPixel, double noiseMare, double seconds);
    // While setHdrReadback is on: each frame's HDR image, camera and GPU time.
    void hdrFrameRendered(std::shared_ptr<const lpv::editor::HdrFrame> frame);

  protected:
    void paintEvent(QPaintEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void keyReleaseEvent(QKeyEvent* event) override;
    void focusOutEvent(QFocusEvent* event) override;

private:
    void onDocumentChanged(Changes changes);
    void prepareSceneChanges();
    // Decodes, on a worker thread, the textures of materials not yet in the
    // cache; until they arrive those materials draw untextured.
    void requestMissingTextures();
    void drawOverlay(QPainter& painter);
    // Where a world point lands in this widget's pixels through `camera` (nullopt: behind it).
    std::function<std::optional<QPointF>(const glm::vec3&)> screenProjection(const scene::Camera& camera) const;
    // Sends the worker a request when the state it renders changed since
    // the last one (camera, parameters, split, size, visualizers, scene).
    void requestFrameIfChanged();
    void onFrameReady(const std::shared_ptr<const FrameResult>& result);
    void flyStep();
    void dragSun(const QPoint& delta);
    // Orbits about orbitPivot_, or turns in place where the eye would pass a surface.
    void orbitStep(const QPoint& delta);
    void dragPathKey(const QPoint& position);
    void drawPath(QPainter& painter);
    // The visible surface under a widget position: its distance along the
    // ray through it (the ray's direction beside it), or, over the sky, the
    // distance to the target capped by the scene's size.
    struct Depth {
        glm::vec3 direction{0.0f, 0.0f, -1.0f};
        float distance = 0.0f;
        std::optional<glm::vec3> hit;
    };
    Depth depthAt(const QPoint& position) const;
    int renderWidth() const;
    int renderHeight() const;
    // gi.method = reference: (re)starts the live path tracer soon (changes
    // during a drag are gathered), or stops it when gi.method is anything else.
    void scheduleReference(bool sceneChanged);
    void restartReference();
    bool showsReference() const;
    // gi.method = radiosity in the view (or a half of the split).
    bool showsBakedRadiosity() const;

    Document* document_;
    FrameWorker* worker_ = nullptr;
    QImage shownImage_;       // the last finished frame
    LiveReference reference_;
    QImage referenceImage_; // the live reference's last pass (gi.method = reference), mapped for display
    std::shared_ptr<const LinearImage> referenceLinear_; // the same pass before mapping
    ReferenceMapping referenceMapping_ = ReferenceMapping::FrameTonemap;
    QTimer referenceTimer_;   // gathers changes before a restart
    bool referenceSceneChanged_ = true;
    std::optional<renderer::GpuMemoryInfo> gpuMemory_;
    quint64 shownSerial_ = 0; // the request it includes
    bool lastFrameFailed_ = false;
    // What the last request held, to tell whether a new one is needed.
    struct Requested {
        scene::Camera camera;
        scene::ParameterSet parameters;
        std::optional<std::pair<scene::ParameterSet, scene::ParameterSet>> split;
        int width = 0, height = 0;
        bool readHdr = false;
        quint64 radiosityGeneration = 0;
        bool resend = false; // the next paint sends a request even if nothing above changed
    };
    std::optional<Requested> requested_;
    std::shared_ptr<const scene::Scene> sceneRest_; // the document's scene without meshes, as last sent
    std::vector<std::shared_ptr<const scene::TextureImages>> texturesToSend_;
    bool forgetTexturesOnSend_ = false;
    CameraController controller_;
    TransformGizmo gizmo_;
    GizmoMode gizmoMode_ = GizmoMode::Move;
    GizmoPivot gizmoPivot_ = GizmoPivot::BoundsCentre;
    GizmoSnap snap_;
    std::optional<std::pair<scene::ParameterSet, scene::ParameterSet>> split_;
    QString splitLabels_[2];

    Changes pending_ = Change::Everything;
    double resolutionScale_ = 1.0;
    std::set<std::string> texturesKnown_; // keys of the images decoded so far (the worker holds the images)
    QThread* textureWorker_ = nullptr;
    bool texturesRequestedAgain_ = false;

    // Mouse state.
    enum class Drag { None, Orbit, Pan, Look, Gizmo, Sun, PathKey };
    Drag drag_ = Drag::None;
    QPoint pressPosition_, lastPosition_;
    bool movedSincePress_ = false;
    int gizmoAxis_ = -1;
    int shownPath_ = -1;
    int draggedKey_ = -1;
    scene::Transform gizmoStart_;
    std::optional<glm::vec3> gizmoDragPivot_; // in the parent's space, fixed for the whole drag
    glm::vec3 orbitPivot_{0.0f};              // the surface under the cursor when the orbit began
    float panDepth_ = 0.0f;                   // its depth along the view when the pan began
    QSet<int> heldKeys_;
    QTimer flyTimer_;
    QElapsedTimer flyClock_;

    bool hdrReadback_ = false;
    bool paused_ = false;
    QString pausedWhy_;
    QImage errorOverlay_;
    QImage comparisonLeft_, comparisonRight_;
    void drawComparisonSplit(QPainter& painter);

    VisualizerRequest vizRequest_;
    std::shared_ptr<const VisualizerFrame> vizFrame_; // the last read-back, for the probe overlay

    QString lastError_;
    QString lastNote_;
    QString lastRadiosityNote_;
    quint64 radiosityGeneration_ = 0; // bumped by reloadBakedRadiosity
};

} // namespace lpv::editor
