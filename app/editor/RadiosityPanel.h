#pragma once
// The Radiosity dock: run and pause a progressive radiosity solve of the
// document's scene, with a progress bar (residual towards the target on a
// log scale), a residual-over-time chart and a preview of the solution.
// The solve runs on a worker thread with its own headless EGL context (like
// the video export), so the viewport's context is never shared; a pause
// saves the solution into the project's assets and the next run resumes it.
#include "lpv/radiosity/SolutionFile.h"

#include <QImage>
#include <QWidget>

#include <atomic>
#include <memory>
#include <optional>

class QChart;
class QLabel;
class QLineSeries;
class QLogValueAxis;
class QProgressBar;
class QPushButton;
class QThread;
class QValueAxis;

namespace lpv::editor {

class Document;

class RadiosityPanel : public QWidget {
    Q_OBJECT
  public:
    explicit RadiosityPanel(Document* document, QWidget* parent = nullptr);
    ~RadiosityPanel() override; // pauses and waits for the worker

    bool running() const { return worker_ != nullptr; }
    QPushButton* runButton() const { return run_; }
    QProgressBar* progressBar() const { return progress_; }
    QLineSeries* residualSeries() const { return series_; }
    QLabel* statusLabel() const { return status_; }
    const QImage& previewImage() const { return previewImage_; }

  public slots:
    void start();
    void pause();

  signals:
    // After each stop (converged, paused, failed); `message` says which.
    void stopped(const QString& message);

  private slots:
    void onProgress(double residual, qulonglong shots, double seconds, double perSecond, qulonglong patches);
    void onStopped(const QString& message, const QImage& preview);

  private:
    void updateButton();

    Document* document_;
    QPushButton* run_ = nullptr;
    QProgressBar* progress_ = nullptr;
    QLabel* status_ = nullptr;
    QLabel* preview_ = nullptr;
    QChart* chart_ = nullptr;
    QLineSeries* series_ = nullptr;
    QValueAxis* axisX_ = nullptr;
    QLogValueAxis* axisY_ = nullptr;
    QImage previewImage_;
    QThread* worker_ = nullptr;
    std::shared_ptr<std::atomic<bool>> cancel_;
    // The last solution, for unsaved projects (saved ones resume from disk).
    std::shared_ptr<std::optional<radiosity::StoredSolution>> memory_;
    double target_ = 0.01;
};

} // namespace lpv::editor
