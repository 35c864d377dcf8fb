#pragma once
// The Accuracy dock (issue #26 item 3): "Trace reference" traces the
// reference of the current view in the background while the viewport keeps
// rendering with the project's settings, and the dock shows the frame's
// error against it (MARE, relMSE, SSIM, FLIP), each beside the error the
// reference's own noise alone would cause, next to the frame's GPU time;
// both update as the reference converges and as settings change. It can
// lay the FLIP heat map over the view and split the view LPV | reference,
// both halves through the frame's exposure and tonemapper (or, as an
// option, `--preview`'s mapping; the live reference view follows the same
// choice).
// The measuring happens in AccuracyMonitor; this only shows it.
#include "AccuracyMonitor.h"

#include <QWidget>

#include <memory>

class QCheckBox;
class QComboBox;
class QLabel;

namespace lpv::editor {

class Document;
class Viewport;

class AccuracyPanel : public QWidget {
    Q_OBJECT
  public:
    AccuracyPanel(Document* document, Viewport* viewport, QWidget* parent = nullptr);

    AccuracyMonitor* monitor() const { return monitor_; }
    QCheckBox* traceBox() const { return trace_; }
    QCheckBox* heatMapBox() const { return heatMap_; }
    QCheckBox* splitBox() const { return split_; }
    // "frame's tonemap" (0) or "preview x/(x+mean)" (1).
    QComboBox* mappingBox() const { return mapping_; }
    // The figure shown for a row ("MARE", "relMSE", "SSIM", "FLIP") in the
    // frame's column (noise = false) or the reference noise's.
    QString figureText(const QString& row, bool noise) const;
    QString gpuTimeText() const;
    QString statusText() const;

  private:
    void showSample(const std::shared_ptr<const AccuracySample>& sample);
    void clearFigures();

    AccuracyMonitor* monitor_;
    QCheckBox* trace_;
    QCheckBox* heatMap_;
    QCheckBox* split_;
    QComboBox* mapping_;
    QLabel* values_[4][2] = {};
    QLabel* gpuTime_;
    QLabel* referenceInfo_;
    QLabel* status_;
};

} // namespace lpv::editor
