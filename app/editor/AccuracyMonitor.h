#pragma once
// What the Accuracy dock measures (issue #26 item 3). While on, it traces
// the reference of the view the viewport shows in the background
// (LiveReference, at the frame's own size), asks the viewport for each
// frame's linear HDR image, and measures the frame against the reference so
// far (reference/Accuracy.h: MARE, relMSE and SSIM on the linear images,
// FLIP on both mapped with one exposure, each beside the reference's noise)
// on a worker thread whenever either changes. The reference restarts when
// the view, its size, the scene or a setting the reference itself depends
// on changes; the renderer's own settings (the ones being tuned) leave it
// converging.
#include "lpv/renderer/DisplayMapping.h"
#include "FrameWorker.h"
#include "LiveReference.h"

#include "lpv/reference/Accuracy.h"
#include "lpv/reference/ReferenceImage.h"

#include <QImage>
#include <QObject>
#include <QTimer>

#include <memory>
#include <optional>
#include <string>

class QThread;

namespace lpv::editor {

// The display mapping's names (DisplayMapping, tonemapImage...) come unqualified from LiveReference.h.

class Document;
class Viewport;

// One measurement of the frame against the reference.
struct AccuracySample {
    reference::Accuracy accuracy; // the figures (its maps and images moved into the QImages below)
    std::string layer;            // the reference layer: "image", or "indirect" for output.view = indirect
    int samplesPerPixel = 0;      // of the reference
    double referenceSeconds = 0.0;
    double gpuMs = 0.0;                    // the frame's GPU time (the sum of its passes)
    double measureMs = 0.0;                // how long the measurement took (off the GUI thread)
    QImage heatMap;                        // FLIP per pixel, magma
    QImage frameDisplay, referenceDisplay; // what FLIP compared: both with the reference's exposure
    // Both through the frame's own exposure and tonemapper (issue #43): the
    // split shows these unless asked for the preview mapping above.
    QImage frameTonemapped, referenceTonemapped;
};

// The frame against the reference so far, with the images the split shows
// (the reference's layer of the frame's output.view). Any thread.
std::shared_ptr<AccuracySample> measureFrame(const HdrFrame& frame,
                                             const reference::ReferenceImage& reference);

class AccuracyMonitor : public QObject {
    Q_OBJECT
  public:
    AccuracyMonitor(Document* document, Viewport* viewport, QObject* parent = nullptr);
    ~AccuracyMonitor() override;

    void setTracing(bool on);
    bool tracing() const { return tracing_; }
    // The FLIP heat map over the view, and the LPV | reference split, from the last measurement.
    void setHeatMapShown(bool on);
    void setSplitShown(bool on);
    // How the split shows the reference (and, the same, the frame).
    void setReferenceMapping(ReferenceMapping mapping);
    ReferenceMapping referenceMapping() const { return mapping_; }
    // The last measurement of the current view (null before the first one and after a change of view).
    const std::shared_ptr<const AccuracySample>& latest() const { return latest_; }
    const QString& status() const { return status_; }

  signals:
    void measured(std::shared_ptr<const lpv::editor::AccuracySample> sample);
    // What it is doing or why it measures nothing ("Tracing the reference...", "gi.method = reference: ...").
    void statusChanged(const QString& status);

  private:
    void onFrame(const std::shared_ptr<const HdrFrame>& frame);
    void onReferenceImage(const std::shared_ptr<const reference::ReferenceImage>& image);
    void onDocumentChanged(Changes changes);
    // The reference traces another view from now on: drop what was measured,
    // and restart soon (changes during a drag are gathered).
    void scheduleRestart();
    void restartReference();
    void measure();
    void finishMeasurement(std::shared_ptr<AccuracySample> sample, unsigned generation);
    void showImages();
    void setStatus(const QString& status);
    // The settings the reference depends on (bounces, the lights it traces).
    std::string referenceSettings();

    Document* document_;
    Viewport* viewport_;
    LiveReference reference_;
    QTimer restartTimer_;
    bool tracing_ = false;
    bool heatMap_ = false;
    bool split_ = false;
    ReferenceMapping mapping_ = ReferenceMapping::FrameTonemap;
    bool sceneChanged_ = true;
    unsigned generation_ = 0; // one per restart: measurements of an older one are dropped
    // What the reference traces now.
    std::optional<scene::Camera> traced_;
    int tracedWidth_ = 0, tracedHeight_ = 0;
    std::string tracedSettings_;
    std::optional<std::string> settingsCache_; // referenceSettings() until the scene or parameters change
    std::shared_ptr<const HdrFrame> frame_;
    std::shared_ptr<const reference::ReferenceImage> image_;
    std::shared_ptr<const AccuracySample> latest_;
    QThread* job_ = nullptr;
    bool pending_ = false; // something changed while a measurement ran
    QString status_;
};

} // namespace lpv::editor
