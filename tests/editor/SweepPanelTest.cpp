// The Sweeps dock (issue #26 item 4) in the real window: a small sweep of
// the Cornell box runs in the background, its points are plotted with the
// front and the current setting, hovering a point shows it, clicking it
// applies its settings as one undo step, the cheapest setting under a bound
// is selected, Stop stops, and the sweep is saved with the project and read
// back when it is opened again.
#include "Autosave.h"
#include "Document.h"
#include "MainWindow.h"
#include "AccuracyPanel.h"
#include "SweepPanel.h"
#include "TestPaths.h"
#include "Viewport.h"

#include "lpv/bench/Pareto.h"
#include "lpv/bench/SavedSweep.h"
#include "TestWindow.h"

#include <QChart>
#include <QApplication>
#include <QCheckBox>
#include <QChartView>
#include <QDockWidget>
#include <QProgressBar>
#include <QPushButton>
#include <QSettings>
#include <QLabel>
#include <QMessageBox>
#include <QScatterSeries>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

#include <gtest/gtest.h>

#include <filesystem>

using namespace lpv::editor;

namespace {

// Only the row named `name` checked, with `values`.
void askOnly(QTableWidget* table, const QString& name, const QString& values) {
    for (int row = 0; row < table->rowCount(); ++row) {
        const bool it = table->item(row, 0)->text() == name;
        table->item(row, 0)->setCheckState(it ? Qt::Checked : Qt::Unchecked);
        if (it)
            table->item(row, 1)->setText(values);
    }
}

int steps(const Document* doc) { return doc->parameters().getInt("lpv.propagationSteps"); }

} // namespace

TEST(SweepPanel, ASweepPlotsAppliesSavesAndReopens) {
    QTemporaryDir projectDir;
    test::TestWindow w;
    MainWindow& window = w.window;
    ASSERT_TRUE(window.openProject(test::cornellTemplate(), false));
    const QString saved = projectDir.filePath("room.lpvproj");
    ASSERT_TRUE(window.saveTo(saved, false));
    window.resize(1200, 900);
    window.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
    SweepPanel* panel = window.sweeps();
    ASSERT_NE(panel, nullptr);
    Document* doc = window.document();
    const int currentSteps = steps(doc);
    ASSERT_NE(currentSteps, 0);

    // A bad row is refused with its name, and nothing starts.
    askOnly(panel->questionTable(), "steps", "lpv.propagationSteps=0,many");
    QString error;
    EXPECT_FALSE(panel->plannedCombinations(error).has_value());
    EXPECT_TRUE(error.contains("steps")) << error.toStdString();

    // The current settings first; the current value is not run twice.
    askOnly(panel->questionTable(), "steps", QString("lpv.propagationSteps=0,%1,2").arg(currentSteps));
    auto planned = panel->plannedCombinations(error);
    ASSERT_TRUE(planned.has_value()) << error.toStdString();
    ASSERT_EQ(planned->size(), 3u);
    EXPECT_TRUE(planned->front().empty());

    panel->setSweepSize(64, 36, 1, 1, 16);
    std::vector<QString> texts;
    QObject::connect(panel->findChild<QProgressBar*>(), &QProgressBar::valueChanged, [&](int) {
        texts.push_back(panel->statusText());
    });
    QSignalSpy finished(panel, &SweepPanel::sweepFinished);
    panel->startSweep();
    EXPECT_TRUE(panel->sweepRunning());
    EXPECT_TRUE(window.viewport()->framesPaused()) << "the view waits while the sweep times";
    ASSERT_TRUE(QTest::qWaitFor([&] { return finished.count() == 1; }, 180000));
    EXPECT_FALSE(window.viewport()->framesPaused());
    ASSERT_NE(panel->sweep(), nullptr) << panel->statusText().toStdString();
    // A copy: reopening the project below replaces the panel's sweep.
    const lpv::bench::SavedSweep sweep = *panel->sweep();
    ASSERT_EQ(sweep.runs.size(), 3u);
    EXPECT_TRUE(panel->statusText().contains("interleaved timing rounds"))
        << panel->statusText().toStdString();
    EXPECT_EQ(panel->runsTable()->rowCount(), 3);
    EXPECT_TRUE(panel->runsTable()->item(1, 5)->text().contains("biased")) << "steps=0 has no indirect light";
    EXPECT_TRUE(std::ranges::any_of(texts, [](const QString& t) { return t.contains("Reference"); }));
    EXPECT_TRUE(std::ranges::any_of(texts, [](const QString& t) { return t.contains("left"); }))
        << "an estimate of the time left once a setting has run";
    for (const auto& run : sweep.runs) {
        EXPECT_GT(run.totalMs, 0.0);
        EXPECT_GT(run.indirect.pixels, 0u);
    }
    EXPECT_EQ(panel->currentRuns(), std::vector<int>{0});

    // Every run is a point (steps=0 has no indirect light: biased); the front is
    // the library's on time against the symmetric error.
    int points = 0;
    for (auto* s : panel->chartView()->chart()->series())
        if (auto* scatter = qobject_cast<QScatterSeries*>(s);
            scatter && (scatter->name() == "settings" || scatter->name() == "on the front" ||
                        scatter->name().startsWith("biased")))
            points += scatter->count();
    EXPECT_EQ(points, 3);
    std::vector<lpv::bench::CostPoint> costs;
    for (const auto& run : sweep.runs) {
        costs.push_back(lpv::bench::timeErrorPoint(run));
        EXPECT_GE(run.total.rounds, 3) << "timed in interleaved rounds";
        EXPECT_GT(run.gpuBytes, 0u);
    }
    EXPECT_TRUE(costs[1].biased) << "steps=0: no indirect light at all";
    const std::vector<bool> front = panel->front();
    EXPECT_EQ(front, lpv::bench::paretoFront(costs, lpv::bench::kSameCostFraction));
    EXPECT_TRUE(std::ranges::any_of(front, [](bool b) { return b; }));

    // Hover the steps=0 point with the mouse: its settings and images show.
    QChart* chart = panel->chartView()->chart();
    QScatterSeries* anySeries = nullptr;
    for (auto* s : chart->series())
        if (auto* scatter = qobject_cast<QScatterSeries*>(s); scatter && scatter->name() == "settings")
            anySeries = scatter;
    ASSERT_NE(anySeries, nullptr);
    window.dock("sweeps")->show();
    window.dock("sweeps")->raise();
    QApplication::processEvents();
    ASSERT_TRUE(panel->plottedPoint(1).has_value());
    const QPointF value = *panel->plottedPoint(1);
    const QPoint at = panel->chartView()->mapFromScene(chart->mapToPosition(value, anySeries));
    QTest::mouseMove(panel->chartView()->viewport(), at);
    ASSERT_TRUE(
        QTest::qWaitFor([&] { return panel->detailText()->text().contains("propagationSteps=0"); }, 5000))
        << "hovering the point shows it: " << panel->detailText()->text().toStdString();
    EXPECT_FALSE(panel->detailImage()->pixmap().isNull());

    // A click applies it as one undo step.
    const int undoBefore = doc->undoStack()->count();
    QTest::mouseClick(panel->chartView()->viewport(), Qt::LeftButton, {}, at);
    ASSERT_TRUE(QTest::qWaitFor([&] { return steps(doc) == 0; }, 5000)) << steps(doc);
    EXPECT_EQ(doc->undoStack()->count(), undoBefore + 1);
    EXPECT_EQ(panel->currentRuns(), std::vector<int>{1}) << "the current mark follows the parameters";
    doc->undoStack()->undo();
    EXPECT_EQ(steps(doc), currentSteps);

    // The cheapest unbiased run under a bound every run meets; under none, nothing.
    const auto cheapest = lpv::bench::cheapestWithin(costs, 1e3, lpv::bench::kSameCostFraction);
    EXPECT_EQ(panel->selectCheapestWithin(1e5), cheapest ? int(*cheapest) : -1);
    EXPECT_NE(panel->selectCheapestWithin(1e5), 1) << "steps=0 is biased";
    EXPECT_EQ(panel->selectCheapestWithin(1e-6), -1);

    // Saved with the project, and read back when it is opened again.
    ASSERT_TRUE(window.saveTo(saved, false));
    const auto file = lpv::bench::savedSweepFileOf(saved.toStdString());
    ASSERT_TRUE(std::filesystem::exists(file));
    ASSERT_TRUE(window.openProject(test::cornellTemplate(), false));
    EXPECT_EQ(panel->sweep(), nullptr) << "another project has no sweep";
    ASSERT_TRUE(window.openProject(saved, false));
    ASSERT_NE(panel->sweep(), nullptr);
    ASSERT_EQ(panel->sweep()->runs.size(), 3u);
    EXPECT_DOUBLE_EQ(panel->sweep()->runs[2].indirect.mare, sweep.runs[2].indirect.mare);
    panel->showRun(2);
    EXPECT_FALSE(panel->detailImage()->pixmap().isNull()) << "the previews are saved too";
}

TEST(SweepPanel, StopEndsTheSweepAndTheDockCanRunAgain) {
    test::TestWindow w;
    MainWindow& window = w.window;
    ASSERT_TRUE(window.openProject(test::cornellTemplate(), false));
    SweepPanel* panel = window.sweeps();
    askOnly(panel->questionTable(), "grid", "lpv.gridSize=8,16,24,48,64");
    panel->setSweepSize(64, 36, 2, 1, 8);
    QSignalSpy finished(panel, &SweepPanel::sweepFinished);
    QSignalSpy logged(panel, &SweepPanel::logMessage);
    // The Accuracy dock's trace pauses while the sweep times, and comes back after.
    QCheckBox* trace = window.accuracy()->traceBox();
    trace->setChecked(true);
    panel->startSweep();
    EXPECT_FALSE(trace->isChecked());
    EXPECT_FALSE(trace->isEnabled());
    // Stop once the reference is traced and settings are running.
    ASSERT_TRUE(QTest::qWaitFor([&] { return panel->statusText().startsWith("Setting"); }, 120000));
    panel->stopSweep();
    ASSERT_TRUE(QTest::qWaitFor([&] { return finished.count() == 1; }, 120000));
    EXPECT_FALSE(panel->sweepRunning());
    EXPECT_EQ(panel->sweep(), nullptr);
    EXPECT_TRUE(panel->statusText().startsWith("Stopped")) << panel->statusText().toStdString();
    ASSERT_FALSE(logged.isEmpty());
    EXPECT_FALSE(logged.last().at(1).toBool()) << "a stop the user asked for is not a warning";
    EXPECT_TRUE(panel->findChild<QPushButton*>("sweepRun")->isEnabled());
    EXPECT_TRUE(trace->isChecked());
    EXPECT_TRUE(trace->isEnabled());
    EXPECT_FALSE(window.viewport()->framesPaused());
    trace->setChecked(false);
}
