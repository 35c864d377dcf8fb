#include "ScreenshotDock.h"

#include "AccuracyPanel.h"
#include "MainWindow.h"
#include "SweepPanel.h"

#include <QCheckBox>
#include <QDockWidget>
#include <QTimer>

#include <algorithm>
#include <memory>
#include <vector>

namespace lpv::editor {

namespace {

// Shows `dock` raised as a tab of the bottom area, given a large share of
// the window's height so that its results can be read in the shot.
void showDockForShot(MainWindow& window, const QString& name, double heightShare) {
    QDockWidget* dock = window.dock(name);
    dock->show();
    // Raised once the window is up: restoring the layout raises another tab.
    QTimer::singleShot(0, &window, [&window, dock, heightShare] {
        dock->raise();
        window.resizeDocks({dock}, {int(heightShare * window.height())}, Qt::Vertical);
    });
}

// --dock accuracy: trace the reference of the view and wait for a frame
// measured against at least `spp` samples; `overlay` is heatmap, split or none.
std::expected<DockWait, QString> accuracyDockForShot(MainWindow& window, int spp, const QString& overlay) {
    auto* panel = window.accuracy();
    if (!panel)
        return std::unexpected(QString("this editor has no Accuracy dock"));
    showDockForShot(window, "accuracy", 0.32);
    auto measuredSpp = std::make_shared<int>(0);
    QObject::connect(panel->monitor(), &AccuracyMonitor::measured, &window,
                     [measuredSpp](std::shared_ptr<const AccuracySample> sample) {
                         *measuredSpp = std::max(*measuredSpp, sample->samplesPerPixel);
                     });
    panel->traceBox()->setChecked(true);
    panel->heatMapBox()->setChecked(overlay == "heatmap");
    panel->splitBox()->setChecked(overlay == "split");
    return DockWait{window.dock("accuracy"), [measuredSpp, spp] { return *measuredSpp >= spp; }, [] { return true; },
                    [panel, measuredSpp] {
                        return QString("Accuracy dock: MARE %1, FLIP %2 against a %3 spp reference (%4)")
                            .arg(panel->figureText("MARE", false), panel->figureText("FLIP", false))
                            .arg(*measuredSpp)
                            .arg(panel->statusText());
                    }};
}

// The run on the sweep's front with the smallest symmetric error, or -1.
int mostAccurateOnFront(const SweepPanel& panel) {
    const std::vector<bool> front = panel.front();
    int best = -1;
    for (std::size_t i = 0; i < front.size(); ++i)
        if (front[i] && (best < 0 || panel.sweep()->runs[i].indirect.symmetricError() <
                                         panel.sweep()->runs[std::size_t(best)].indirect.symmetricError()))
            best = int(i);
    return best;
}

// --dock sweeps: the project's saved sweep, else a sweep of the dock's rows
// run now (at the dock's default size; saved beside a project that has a
// file, as the dock does), then the front's most accurate point hovered.
std::expected<DockWait, QString> sweepsDockForShot(MainWindow& window) {
    auto* panel = window.sweeps();
    if (!panel)
        return std::unexpected(QString("this editor has no Sweeps dock"));
    showDockForShot(window, "sweeps", 0.5);
    auto done = std::make_shared<bool>(panel->sweep() != nullptr);
    auto hover = [panel, done] {
        *done = true;
        if (panel->sweep())
            panel->showRun(mostAccurateOnFront(*panel));
    };
    if (*done)
        QTimer::singleShot(0, panel, hover);
    else {
        QObject::connect(panel, &SweepPanel::sweepFinished, panel, hover);
        // After the first frames: the sweep measures the viewport's camera.
        QTimer::singleShot(0, panel, [panel, done] {
            panel->startSweep();
            *done = !panel->sweepRunning(); // not started: its status says why
        });
    }
    return DockWait{window.dock("sweeps"), [done] { return *done; }, [panel] { return panel->sweep() != nullptr; },
                    [panel] {
                        if (!panel->sweep())
                            return QString("Sweeps dock: no sweep (%1)").arg(panel->statusText());
                        return QString("Sweeps dock: %1 settings, hovering the table's row %2 (%3)")
                            .arg(panel->sweep()->runs.size())
                            .arg(mostAccurateOnFront(*panel) + 1)
                            .arg(panel->statusText());
                    }};
}

} // namespace

std::optional<QString> dockWaitOver(const DockWait& wait, qint64 elapsedMs, double timeoutS) {
    if (!wait.ready())
        return elapsedMs <= 1000.0 * timeoutS
                   ? std::nullopt
                   : std::optional(QString("the dock showed no results within %1 s: %2").arg(timeoutS).arg(wait.summary()));
    return wait.succeeded() ? QString() : wait.summary();
}

std::expected<void, QString> checkShotDock(const QString& name, const QString& overlay) {
    if (overlay != "none" && overlay != "heatmap" && overlay != "split")
        return std::unexpected(QString("--accuracy-overlay must be one of none, heatmap, split"));
    if (name == "accuracy" || name == "sweeps")
        return {};
    return std::unexpected(QString("--dock must be one of accuracy, sweeps (not \"%1\")").arg(name));
}

std::expected<DockWait, QString> dockForShot(MainWindow& window, const QString& name, int spp,
                                             const QString& overlay) {
    if (auto known = checkShotDock(name, overlay); !known)
        return std::unexpected(known.error());
    return name == "accuracy" ? accuracyDockForShot(window, spp, overlay) : sweepsDockForShot(window);
}

} // namespace lpv::editor
