// The Sweeps dock as a newcomer meets it (issue #46): a click on the point
// the mouse hovers applies it (hovering used to widen the detail column,
// which shrank the chart and moved the point from under the cursor), and
// the question rows' check boxes come back with the saved sweep when the
// project is opened again (they went back to the defaults).
#include "Autosave.h"
#include "Document.h"
#include "MainWindow.h"
#include "SweepPanel.h"
#include "TestPaths.h"

#include "lpv/bench/SavedSweep.h"
#include "TestWindow.h"

#include <QApplication>
#include <QChart>
#include <QChartView>
#include <QDockWidget>
#include <QLabel>
#include <QMessageBox>
#include <QMouseEvent>
#include <QScatterSeries>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <memory>
#include <ostream>

using namespace lpv::editor;

namespace {

lpv::scene::Image8 flatImage(int width, int height, std::uint8_t value) {
    lpv::scene::Image8 image;
    image.width = width;
    image.height = height;
    image.pixels.assign(std::size_t(width) * std::size_t(height) * 4, value);
    return image;
}

lpv::bench::SweepRun run(std::vector<lpv::bench::Setting> settings, double ms, double symmetricError) {
    lpv::bench::SweepRun r;
    r.settings = std::move(settings);
    r.total = {ms, ms * 0.95, ms * 1.05, ms * 0.9, ms * 1.1, 5};
    r.totalMs = ms;
    r.gpuBytes = 64u << 20;
    r.indirect.pixels = 1000;
    r.indirect.logError = std::log1p(symmetricError);
    r.indirect.noiseLogError = std::log1p(0.02);
    r.indirect.meanReference = 1.0;
    r.indirect.meanTest = 1.0;
    return r;
}

// Three unbiased settings with previews as large as a real sweep's (160x90):
// the previews are what the detail column shows on hover.
std::shared_ptr<lpv::bench::SavedSweep> sweepWithPreviews() {
    auto s = std::make_shared<lpv::bench::SavedSweep>();
    s->createdAt = "2026-12-05T00:00:00Z";
    s->width = 160;
    s->height = 90;
    s->runs = {run({}, 10.0, 0.30), run({{"lpv.propagationSteps", "16"}}, 20.0, 0.12),
               run({{"lpv.propagationSteps", "2"}}, 5.0, 0.60)};
    for (std::size_t i = 0; i < s->runs.size(); ++i)
        s->previews.push_back(flatImage(160, 90, std::uint8_t(60 + 60 * i)));
    s->referencePreview = flatImage(160, 90, 128);
    return s;
}

QScatterSeries* settingsSeries(SweepPanel& panel) {
    for (auto* s : panel.chartView()->chart()->series())
        if (auto* scatter = qobject_cast<QScatterSeries*>(s); scatter && scatter->name() == "settings")
            return scatter;
    return nullptr;
}

// Where run `index`'s point is on the chart view's viewport, in pixels.
QPoint pointOnScreen(SweepPanel& panel, int index) {
    const QPointF value = *panel.plottedPoint(index);
    return panel.chartView()->mapFromScene(
        panel.chartView()->chart()->mapToPosition(value, settingsSeries(panel)));
}

// Mouse events as the window system delivers them to the widget. (QTest's
// mouseMove and mouseClick did not reach the chart's series here: they
// never saw a hover or a click.)
void send(QWidget* widget, QEvent::Type type, QPoint at, Qt::MouseButton button, Qt::MouseButtons held) {
    QMouseEvent event(type, at, widget->mapToGlobal(at), button, held, Qt::NoModifier);
    QApplication::sendEvent(widget, &event);
}
void hover(QWidget* widget, QPoint at) {
    send(widget, QEvent::MouseMove, at, Qt::NoButton, Qt::NoButton);
}
void click(QWidget* widget, QPoint at) {
    send(widget, QEvent::MouseButtonPress, at, Qt::LeftButton, Qt::LeftButton);
    send(widget, QEvent::MouseButtonRelease, at, Qt::LeftButton, Qt::NoButton);
}

struct Row {
    QString name, values;
    Qt::CheckState checked;
    bool operator==(const Row&) const = default;
    friend void PrintTo(const Row& r, std::ostream* out) {
        *out << r.name.toStdString() << (r.checked == Qt::Checked ? " [x] " : " [ ] ")
             << r.values.toStdString();
    }
};

std::vector<Row> rowsOf(QTableWidget* table) {
    std::vector<Row> rows;
    for (int r = 0; r < table->rowCount(); ++r)
        rows.push_back(
            {table->item(r, 0)->text(), table->item(r, 1)->text(), table->item(r, 0)->checkState()});
    return rows;
}

} // namespace

TEST(SweepDock, AClickOnTheHoveredPointAppliesIt) {
    // In the window as a user has it: the dock at the bottom, under the view.
    test::TestWindow w;
    ASSERT_TRUE(w.openAndShow(test::cornellTemplate(), {1400, 900}));
    MainWindow& window = w.window;
    window.dock("sweeps")->show();
    window.dock("sweeps")->raise();
    SweepPanel& panel = *window.sweeps();
    Document& document = *window.document();
    panel.showSweep(sweepWithPreviews());
    QApplication::processEvents();
    ASSERT_NE(settingsSeries(panel), nullptr);
    ASSERT_NE(document.parameters().getInt("lpv.propagationSteps"), 16);

    // The steps=16 point, found as a user finds it: the mouse over it.
    const QPoint at = pointOnScreen(panel, 1);
    const QRectF plotBefore = panel.chartView()->chart()->plotArea();
    for (QPoint step : {QPoint(40, 40), QPoint(3, 3), QPoint(0, 0)}) {
        hover(panel.chartView()->viewport(), at + step);
        QApplication::processEvents();
    }
    // QTest::qWaitFor, not QTRY_*: those return silently under GoogleTest.
    ASSERT_TRUE(
        QTest::qWaitFor([&] { return panel.detailText()->text().contains("propagationSteps=16"); }, 5000))
        << "hovering the point shows it: " << panel.detailText()->text().toStdString();
    ASSERT_FALSE(panel.detailImage()->pixmap().isNull()) << "the previews show on hover";
    QTest::qWait(300); // any layout the hover caused has run

    // The chart keeps its geometry, so the point stays under the cursor...
    EXPECT_EQ(panel.chartView()->chart()->plotArea(), plotBefore)
        << "the plot moved: " << plotBefore.width() << "x" << plotBefore.height() << " -> "
        << panel.chartView()->chart()->plotArea().width() << "x"
        << panel.chartView()->chart()->plotArea().height();
    EXPECT_EQ(pointOnScreen(panel, 1), at);
    // ...and a click without moving applies it.
    click(panel.chartView()->viewport(), at);
    EXPECT_TRUE(
        QTest::qWaitFor([&] { return document.parameters().getInt("lpv.propagationSteps") == 16; }, 5000))
        << "the click applied nothing";
    EXPECT_EQ(panel.selectedRun(), 1);
}

TEST(SweepDock, RowChecksComeBackWithTheSavedSweep) {
    QTemporaryDir projectDir;
    test::TestWindow w;
    MainWindow& window = w.window;
    ASSERT_TRUE(window.openProject(test::cornellTemplate(), false));
    SweepPanel* panel = window.sweeps();
    QTableWidget* table = panel->questionTable();
    const std::vector<Row> defaults = rowsOf(table);
    ASSERT_GE(defaults.size(), 3u);

    // Every check box flipped, one row's values edited, one row added.
    for (int r = 0; r < table->rowCount(); ++r)
        table->item(r, 0)->setCheckState(table->item(r, 0)->checkState() == Qt::Checked ? Qt::Unchecked
                                                                                        : Qt::Checked);
    table->item(0, 1)->setText("lpv.propagationSteps=1,3");
    const int added = table->rowCount();
    table->insertRow(added);
    auto* name = new QTableWidgetItem("custom");
    name->setCheckState(Qt::Checked);
    table->setItem(added, 0, name);
    table->setItem(added, 1, new QTableWidgetItem("lpv.gridSize=24"));
    const std::vector<Row> chosen = rowsOf(table);
    ASSERT_NE(chosen, defaults);

    panel->showSweep(sweepWithPreviews());
    const QString saved = projectDir.filePath("room.lpvproj");
    ASSERT_TRUE(window.saveTo(saved, false));
    ASSERT_TRUE(std::filesystem::exists(lpv::bench::savedSweepFileOf(saved.toStdString())));

    // Another project (no sweep) asks the default questions; this one its own again.
    ASSERT_TRUE(window.openProject(test::cornellTemplate(), false));
    EXPECT_EQ(rowsOf(table), defaults);
    ASSERT_TRUE(window.openProject(saved, false));
    ASSERT_NE(panel->sweep(), nullptr);
    EXPECT_EQ(rowsOf(table), chosen);
}
