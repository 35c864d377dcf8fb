#pragma once
// The Sweeps dock (issue #26 item 4): what accuracy costs in time, in the
// editor. The user picks parameters and values (by default the questions of
// `lpv bench report`, each varied alone around the current settings), runs
// them in the background with progress, time left and Stop, and sees each
// setting's indirect-light error (the symmetric one, which does not reward a
// dark LPV, issue #43) against its GPU time (median over interleaved rounds,
// on a log axis with round ticks and the interquartile range as an error
// bar) or its GPU memory, with the Pareto front, the current setting and the
// biased settings (mean light outside 0.8-1.25x the reference's) marked. A
// table lists every run with its time and spread, memory, error and mean.
// Hovering a point shows its settings and its indirect light beside the
// reference's; clicking applies its settings as one undoable edit; "Cheapest
// within" selects the cheapest unbiased setting under an error bound. The
// last sweep is saved beside the project (`Name.assets/sweep.json`) and
// shown again when it is opened.
#include "SweepJob.h"

#include <QPointF>
#include <QWidget>

#include <memory>
#include <optional>
#include <functional>

class QCategoryAxis;
class QChart;
class QChartView;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineSeries;
class QProgressBar;
class QPushButton;
class QScatterSeries;
class QSpinBox;
class QTableWidget;
class QValueAxis;

namespace lpv::editor {

class Document;

class SweepPanel : public QWidget {
    Q_OBJECT
public:
    // `currentView` gives the camera the sweep measures (the viewport's).
    SweepPanel(Document* document, std::function<scene::Camera()> currentView, QWidget* parent = nullptr);
    ~SweepPanel() override;

    // The combinations the question table asks for: {} (the current
    // settings) first, then each checked row's values alone, without those
    // that equal the current settings. nullopt and `error` on a bad row.
    std::optional<std::vector<std::vector<bench::Setting>>> plannedCombinations(QString& error) const;
    void startSweep();
    void stopSweep();
    bool sweepRunning() const;

    // The sweep shown (finished or loaded), or null.
    const bench::SavedSweep* sweep() const { return sweep_.get(); }
    // What a click on run `index`'s point does: its settings become the
    // document's, as one undoable edit.
    void applyRun(int index);
    // What hovering run `index`'s point shows (-1 clears it).
    void showRun(int index);
    // Selects the cheapest unbiased run (on the chart's cost axis) whose
    // indirect symmetric error is at most `maxErrorPercent`; returns its
    // index, or -1 (and says why) when none is.
    int selectCheapestWithin(double maxErrorPercent);
    int selectedRun() const { return selected_; }
    // Runs whose settings are the document's current ones (marked in the plot).
    std::vector<int> currentRuns() const;
    // Runs on the Pareto front of the chart's cost against the symmetric error.
    std::vector<bool> front() const;

    // The chart's x axis: GPU time (ms, the median over the timing rounds) or GPU memory (MiB).
    enum class CostAxis { Time, Memory };
    void setCostAxis(CostAxis axis);
    CostAxis costAxis() const;
    // Run `index`'s cost on that axis (ms or MiB; 0 when not measured).
    double costOf(int index) const;
    // Where run `index` is drawn in the chart's coordinates (x: log10 of its
    // cost, y: symmetric error in %), or nothing when it is not drawn.
    std::optional<QPointF> plottedPoint(int index) const;
    // Shows `sweep` as if it had just been loaded (tests: synthetic runs).
    void showSweep(std::shared_ptr<const bench::SavedSweep> sweep);
    // The question table's rows (name, KEY=V1,..., checked), saved with the
    // sweep and restored with it; the defaults are the report's questions.
    std::vector<bench::SweepQuestionRow> questionRows() const;
    void setQuestionRows(const std::vector<bench::SweepQuestionRow>& rows);
    static std::vector<bench::SweepQuestionRow> defaultQuestionRows();
    // Test access.
    QTableWidget* questionTable() const { return questions_; }
    QChartView* chartView() const { return chartView_; }
    QComboBox* axisBox() const { return axisChoice_; }
    QTableWidget* runsTable() const { return runsTable_; }
    QLabel* detailText() const { return detailText_; }
    QLabel* detailImage() const { return detailImage_; }
    QString statusText() const;
    void setSweepSize(int width, int height, int frames, int warmup, int referenceSpp);

protected:
    // Hover and click on the chart's points (its viewport's mouse events).
    bool eventFilter(QObject* watched, QEvent* event) override;

signals:
    void sweepFinished();
    // A sweep started (true) or ended (false): while it times, other
    // rendering should wait (MainWindow pauses the view and the Accuracy trace).
    void timingChanged(bool timing);
    // A line for the Log dock (saved, failed, stopped).
    void logMessage(const QString& text, bool warning);

private:
    void rebuildChart();
    void onRunFinished(int index, const bench::SweepRun& run, const QImage& preview);
    void onFinished(std::shared_ptr<const bench::SavedSweep> sweep, const QString& timing);
    void onFailed(const QString& message, bool cancelled);
    void onDocumentChanged(bool newProject);
    void saveBesideProject(const QString& projectPath);
    void loadBesideProject();
    // The run whose point is nearest `pos` (chart view viewport pixels) within a marker's radius, or -1.
    int runAtPixel(const QPoint& pos) const;
    // The runs shown: the finished sweep's, or those of the one running (null: not measured yet).
    std::vector<const bench::SweepRun*> shownRuns() const;
    bench::CostPoint costPoint(const bench::SweepRun& run) const;
    double axisCost(const bench::SweepRun& run) const;
    void rebuildRunsTable(const std::vector<const bench::SweepRun*>& runs, const std::vector<bool>& onFront);

    Document* document_;
    std::function<scene::Camera()> currentView_;
    SweepJob job_;
    std::shared_ptr<const bench::SavedSweep> sweep_;
    // While a sweep runs: the runs so far (indices into its combinations).
    std::vector<std::vector<bench::Setting>> runningCombinations_;
    std::vector<std::optional<bench::SweepRun>> partialRuns_;
    std::vector<QImage> previews_;
    QImage referencePreview_;
    int selected_ = -1;
    int pressedRun_ = -1; // the point a left button went down on

    QTableWidget* questions_ = nullptr;
    QSpinBox* width_ = nullptr;
    QSpinBox* height_ = nullptr;
    QSpinBox* frames_ = nullptr;
    QSpinBox* warmup_ = nullptr;
    QSpinBox* spp_ = nullptr;
    QPushButton* run_ = nullptr;
    QPushButton* stop_ = nullptr;
    QProgressBar* progress_ = nullptr;
    QLabel* status_ = nullptr;
    QDoubleSpinBox* maxError_ = nullptr;
    QChart* chart_ = nullptr;
    QChartView* chartView_ = nullptr;
    QScatterSeries* allPoints_ = nullptr;
    QScatterSeries* frontPoints_ = nullptr;
    QLineSeries* frontLine_ = nullptr;
    QScatterSeries* currentPoints_ = nullptr;
    QScatterSeries* selectedPoint_ = nullptr;
    QScatterSeries* biasedPoints_ = nullptr;
    QLineSeries* noiseLine_ = nullptr;
    std::vector<QLineSeries*> spreadBars_;        // one per timed point: its interquartile range
    std::vector<std::optional<QPointF>> plotted_; // per run, in chart coordinates
    QComboBox* axisChoice_ = nullptr;
    QTableWidget* runsTable_ = nullptr;
    QCategoryAxis* axisX_ = nullptr;
    QValueAxis* axisY_ = nullptr;
    QLabel* detailText_ = nullptr;
    QLabel* detailImage_ = nullptr;
};

} // namespace lpv::editor
