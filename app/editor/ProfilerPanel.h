#pragma once
// Live GPU timings: a table of every pass (last, median, min, max, share of
// the frame) and a chart of frame and pass times over the last seconds.
// Fed by the viewport after each frame; while the panel is hidden a frame
// only appends a few numbers to the history, nothing is drawn.
#include "lpv/renderer/GpuTimer.h"

#include <QElapsedTimer>
#include <QWidget>

#include <deque>
#include <string>
#include <vector>

class QChart;
class QChartView;
class QLineSeries;
class QTableWidget;
class QTimer;
class QValueAxis;

namespace lpv::editor {

class ProfilerPanel : public QWidget {
    Q_OBJECT
  public:
    // The name of the series and table row that sums the passes.
    static constexpr const char* kFrameName = "Frame";
    // How far back the chart reaches.
    static constexpr double kWindowSeconds = 10.0;

    explicit ProfilerPanel(QWidget* parent = nullptr);
    ~ProfilerPanel() override;

    QTableWidget* table() const { return table_; }
    QChart* chart() const { return chart_; }
    // The chart series of a pass, or of the frame total (kFrameName); nullptr if none yet.
    QLineSeries* series(const QString& name) const;

  public slots:
    // One frame's timing table (GpuTimer::table()), in the order of the passes.
    void addFrame(const std::vector<lpv::renderer::PassTiming>& table);
    // Forgets the history (a new project, a resized viewport).
    void clear();
    // Redraws table and chart now (normally throttled to a few times a second).
    void refreshNow();

  protected:
    void showEvent(QShowEvent* event) override;

  private:
    struct Sample {
        double t; // seconds since the panel started
        double ms;
    };
    struct Track {
        QString name;
        std::deque<Sample> samples;
        QLineSeries* series = nullptr;
    };
    Track& track(const QString& name);
    void updateTable();
    void updateChart();

    QTableWidget* table_ = nullptr;
    QChartView* view_ = nullptr;
    QChart* chart_ = nullptr;
    QValueAxis* axisX_ = nullptr;
    QValueAxis* axisY_ = nullptr;
    QTimer* pending_ = nullptr;
    QElapsedTimer clock_;
    QElapsedTimer sinceDraw_;
    std::vector<renderer::PassTiming> last_;
    std::vector<Track> tracks_; // the frame total first, then passes as first seen
};

} // namespace lpv::editor
