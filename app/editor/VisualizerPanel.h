#pragma once
// The Visualizers dock: an LPV slice viewer (cascade, axis, slice, quantity,
// channel, linear/log false colour with a legend) that steps through the
// propagation iterations one by one, the geometry volume and leak views, the
// RSM tiles and the shadow maps, plus overlays in the viewport. The pictures
// come from renderer/viz, the same code `lpv dump` writes with.
//
// It asks the viewport for read-backs only while it is shown (setActive), so
// a closed dock costs the renderer nothing.
#include "VisualizerOverlay.h"

#include "lpv/renderer/viz/LpvViews.h"

#include <QImage>
#include <QTimer>
#include <QWidget>

#include <memory>

class QCheckBox;
class QComboBox;
class QLabel;
class QSlider;
class QSpinBox;
class QToolButton;

namespace lpv::editor {

class Document;
class FittedImageView;
class Viewport;

class VisualizerPanel : public QWidget {
    Q_OBJECT
  public:
    // What the dock shows.
    enum class View { Light, Geometry, Leak, Backside, Rsm, Shadow };

    VisualizerPanel(Document* document, Viewport* viewport, QWidget* parent = nullptr);

    // Shown: read back every frame; hidden: stop and free the copies.
    void setActive(bool active);
    bool active() const { return active_; }

    // The picture shown (empty before the first frame).
    const QImage& image() const { return image_; }
    // The slice viewer's choices as the CLI takes them (`lpv dump`).
    renderer::viz::LpvViewSpec spec() const;
    // Why there is no picture, or what it shows.
    QString status() const;

    void setView(View view);
    void setSlice(int index);
    void setStep(int step);
    // One propagation step back or forward (wraps at the ends while playing).
    void stepBy(int delta);

  signals:
    // The picture changed (a new frame arrived or a control moved).
    void imageUpdated();

  private:
    void buildControls();
    void onFrame(std::shared_ptr<const VisualizerFrame> frame);
    void pushRequest();
    void rebuildImage();
    void syncRanges();
    View view() const;

    Document* document_;
    Viewport* viewport_;
    bool active_ = false;
    std::shared_ptr<const VisualizerFrame> frame_;
    QImage image_;
    QString status_;
    QTimer playTimer_;

    QComboBox* view_ = nullptr;
    QSpinBox* cascade_ = nullptr;
    QComboBox* axis_ = nullptr;
    QSlider* slice_ = nullptr;
    QLabel* sliceLabel_ = nullptr;
    QComboBox* source_ = nullptr;
    QSlider* step_ = nullptr;
    QLabel* stepLabel_ = nullptr;
    QToolButton* play_ = nullptr;
    QComboBox* quantity_ = nullptr;
    QSpinBox* coefficient_ = nullptr;
    QComboBox* direction_ = nullptr;
    QComboBox* channel_ = nullptr;
    QComboBox* scale_ = nullptr;
    QCheckBox* falseColour_ = nullptr;
    QCheckBox* lockRange_ = nullptr;
    QCheckBox* bounds_ = nullptr;
    QCheckBox* plane_ = nullptr;
    QCheckBox* probes_ = nullptr;
    FittedImageView* picture_ = nullptr;
    QLabel* statusLabel_ = nullptr;
    std::optional<float> lockedMax_;
};

} // namespace lpv::editor
