#pragma once
// `lpvstudio --screenshot FILE --dock DOCK` (issue #46): the docs images of the
// Accuracy and Sweeps docks are taken with results in them. This raises the
// dock, starts what fills it (a reference trace, or the saved or a new
// sweep), and tells main's screenshot timer when the shot may be taken.
#include <QString>

#include <expected>
#include <functional>
#include <optional>

class QDockWidget;

namespace lpv::editor {

class MainWindow;

// What a screenshot with --dock waits for: the dock's results, and a line
// saying what it shows (printed with the shot, or as the reason on timeout).
struct DockWait {
    QDockWidget* dock = nullptr; // must be visible (raised) when the shot is taken
    std::function<bool()> ready;     // the wait is over (results, or a failure)
    std::function<bool()> succeeded; // once ready: the dock shows results
    std::function<QString()> summary;
};

// Checked before the project opens, so a misspelt name fails at once.
std::expected<void, QString> checkShotDock(const QString& name, const QString& overlay);

// Raises the dock `name` (accuracy or sweeps) and starts what fills it;
// `spp` and `overlay` are --reference-spp and --accuracy-overlay.
std::expected<DockWait, QString> dockForShot(MainWindow& window, const QString& name, int spp,
                                             const QString& overlay);

// Where the wait for the dock stands: nullopt while it goes on, then an
// empty string when the dock shows results, else why it does not.
std::optional<QString> dockWaitOver(const DockWait& wait, qint64 elapsedMs, double timeoutS);

} // namespace lpv::editor
