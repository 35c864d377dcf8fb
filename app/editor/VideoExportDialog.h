#pragma once
// Video export of a camera path: MP4 (H.264) or a PNG sequence at a chosen
// size and frame rate, rendered offline at fixed time steps by
// video::renderVideo on a worker thread (its own headless GL context), with
// a progress dialog that shows the time left and can cancel. Optionally side
// by side: the current parameters (A) against a preset (B).
#include "Document.h"

#include <QDialog>

#include <atomic>

class QComboBox;
class QDoubleSpinBox;
class QLineEdit;
class QSpinBox;

namespace lpv::editor {

class VideoExportDialog : public QDialog {
    Q_OBJECT
public:
    VideoExportDialog(Document* document, int pathIndex, QWidget* parent = nullptr);

    QLineEdit* outputField() const { return output_; }
    QSpinBox* widthField() const { return width_; }
    QSpinBox* heightField() const { return height_; }
    QDoubleSpinBox* fpsField() const { return fps_; }
    QComboBox* compareField() const { return compare_; }

    // Renders with the current settings; blocks in a local event loop with
    // the progress dialog (the window keeps drawing). Returns the error text,
    // empty on success; "cancelled" when cancelled.
    QString run();
    // Tests: cancel once this many frames are done (0 = never).
    void setCancelAfterFramesForTests(int frames) { cancelAfterFrames_ = frames; }

signals:
    // After every run(): the output file or folder and run()'s result.
    void exportFinished(const QString& output, const QString& error);

private:
    Document* document_;
    int pathIndex_;
    QLineEdit* output_;
    QSpinBox* width_;
    QSpinBox* height_;
    QDoubleSpinBox* fps_;
    QComboBox* compare_;
    int cancelAfterFrames_ = 0;
};

} // namespace lpv::editor
