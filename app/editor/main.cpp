// lpvstudio: the LPV Studio editor. Opens the project given on the command
// line, or the built-in Cornell box template as an untitled copy.
#include "MainWindow.h"
#include "ScreenshotDock.h"
#include "Viewport.h"
#include "VisualizerPanel.h"

#include "lpv/app/VersionInfo.h"

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QCommandLineParser>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QIcon>
#include <QSpinBox>
#include <QPainter>
#include <QPixmap>
#include <QTimer>

#include <cstdio>
#include <memory>
#include <optional>

using lpv::editor::DockWait;
using lpv::editor::MainWindow;

int main(int argc, char** argv) {
    QApplication app(argc, argv);
    QApplication::setApplicationName("LPV Studio");
    QApplication::setOrganizationName("LPV Studio");
    const lpv::app::BuildInfo build = lpv::app::buildInfo();
    QApplication::setApplicationVersion(
        QString::fromStdString(build.version + " (revision " + build.revision + ")"));
    // Ties the windows to the installed .desktop entry and icon (packaging/linux/).
    QGuiApplication::setDesktopFileName("org.lpvstudio.lpvstudio");
    QApplication::setWindowIcon(
        QIcon::fromTheme("org.lpvstudio.lpvstudio", QIcon(":/icons/lpvstudio-256.png")));

    QCommandLineParser parser;
    parser.setApplicationDescription("LPV Studio editor: author scenes and tune Light Propagation Volumes");
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument("project", "Project (.lpvproj) to open; default: the built-in Cornell box");
    QCommandLineOption screenshot("screenshot",
                                  "Open the project, wait until its textures are loaded and a frame is drawn, save "
                                  "the main window to FILE (PNG) and quit (docs, smoke tests).",
                                  "FILE");
    QCommandLineOption size("size", "Window size for --screenshot, e.g. 1600x1000 (enlarged to the docks' minimum).", "WxH", "1600x1000");
    parser.addOption(screenshot);
    parser.addOption(size);
    const QCommandLineOption visualizer(
        "visualizer", "Open the Visualizers dock on VIEW: light, gv, leak, backside, rsm or shadow.", "VIEW");
    const QCommandLineOption probes("visualizer-probes",
                                    "With --visualizer: draw the SH probe grid in the view.");
    const QCommandLineOption vizSlice("visualizer-slice",
                                      "With --visualizer: the cascade, axis and slice shown, e.g. 2:y:14.",
                                      "CASCADE:AXIS:INDEX");
    parser.addOption(visualizer);
    parser.addOption(probes);
    const QCommandLineOption vizLog("visualizer-log", "With --visualizer: logarithmic colour scale.");
    parser.addOption(vizSlice);
    parser.addOption(vizLog);
    // For smoke tests of an installed editor (tests/install, packaging/README.md).
    const QCommandLineOption quitAfter(
        "quit-after", "Quit after MS milliseconds, with exit code 1 if the viewport reported an error.",
        "MS");
    parser.addOption(quitAfter);
    // Docs images of docks with results in them (issue #46), made the same way each time.
    const QCommandLineOption dockOption(
        "dock",
        "With --screenshot: raise DOCK and wait until it shows results before the shot. accuracy: trace "
        "the reference of the view and wait for a frame measured against it (--reference-spp); sweeps: "
        "the project's saved sweep, else run the dock's default sweep now (saved beside the project as "
        "the dock does), then hover the Pareto front's most accurate point.",
        "DOCK");
    const QCommandLineOption referenceSpp(
        "reference-spp", "With --dock accuracy: wait for a measurement against at least N samples per pixel "
        "(default 2).",
        "N", "2");
    const QCommandLineOption accuracyOverlay("accuracy-overlay",
                                             "With --dock accuracy: none, heatmap (the FLIP heat map over "
                                             "the view) or split (LPV | reference); default none.",
                                             "OVERLAY", "none");
    const QCommandLineOption dockTimeout(
        "dock-timeout", "With --dock: give up after S seconds (default 600), with a message and exit code 1.",
        "S", "600");
    parser.addOption(dockOption);
    parser.addOption(referenceSpp);
    parser.addOption(accuracyOverlay);
    parser.addOption(dockTimeout);
    parser.process(app);
    int quitAfterMs = -1;
    if (parser.isSet(quitAfter)) {
        bool ok = false;
        quitAfterMs = parser.value(quitAfter).toInt(&ok);
        if (!ok || quitAfterMs < 0) {
            fprintf(stderr, "lpvstudio: --quit-after needs a number of milliseconds\n");
            return 2;
        }
    }

    // The --dock options are checked before the project opens, so a mistake fails at once.
    bool sppOk = false, timeoutOk = false;
    const int spp = parser.value(referenceSpp).toInt(&sppOk);
    const double timeoutS = parser.value(dockTimeout).toDouble(&timeoutOk);
    if (parser.isSet(dockOption)) {
        if (!parser.isSet(screenshot) || !sppOk || spp < 1 || !timeoutOk || timeoutS <= 0) {
            fprintf(stderr, "lpvstudio: --dock needs --screenshot, --reference-spp a count of at least 1 "
                            "and --dock-timeout seconds\n");
            return 2;
        }
        if (auto known = lpv::editor::checkShotDock(parser.value(dockOption), parser.value(accuracyOverlay)); !known) {
            fprintf(stderr, "lpvstudio: %s\n", qPrintable(known.error()));
            return 2;
        }
    }
    lpv::editor::MainWindow window;
    const QStringList args = parser.positionalArguments();
    QString path = args.isEmpty() ? QString() : args.front();
    // Screenshots and smoke tests have nobody to read a dialog: there a project
    // that cannot be read ends the run with its reason and exit code 1.
    const bool unattended = parser.isSet(screenshot) || quitAfterMs >= 0;
    if (args.isEmpty()) {
        // The built-in template, as an untitled copy: nothing is written into the source or install tree.
        path = window.openBuiltInTemplate(); // named by --quit-after: the install test checks which one
    } else if (!unattended) {
        // The editor opens either way; the box over it names file and field.
        if (!window.openFromCommandLine(path))
            fprintf(stderr, "lpvstudio: could not open %s\n", qPrintable(window.lastOpenError()));
    } else if (!window.openProject(path, false)) {
        fprintf(stderr, "lpvstudio: could not open %s\n", qPrintable(window.lastOpenError()));
        return 1;
    }
    if (parser.isSet(visualizer)) {
        const QStringList views{"light", "gv", "leak", "backside", "rsm", "shadow"};
        const int view = views.indexOf(parser.value(visualizer));
        if (view < 0) {
            fprintf(stderr, "lpvstudio: --visualizer must be one of %s\n", qPrintable(views.join(", ")));
            return 2;
        }
        // Tabbed with the inspector, so the picture gets the dock area's full height.
        window.tabifyDockWidget(window.dock("inspector"), window.dock("visualizers"));
        window.dock("visualizers")->show();
        // Raised once the window is up: restoring the layout raises the inspector's tab.
        QTimer::singleShot(0, &window, [&window] { window.dock("visualizers")->raise(); });
        window.visualizers()->setView(lpv::editor::VisualizerPanel::View(view));
        if (parser.isSet(probes))
            window.visualizers()->findChild<QCheckBox*>("vizProbes")->setChecked(true);
        const QStringList slice = parser.value(vizSlice).split(':');
        if (slice.size() == 3) {
            window.visualizers()->findChild<QSpinBox*>("vizCascade")->setValue(slice[0].toInt());
            window.visualizers()->findChild<QComboBox*>("vizAxis")->setCurrentText(slice[1]);
            window.visualizers()->setSlice(slice[2].toInt());
        }
        if (parser.isSet(vizLog))
            window.visualizers()->findChild<QComboBox*>("vizScale")->setCurrentIndex(1);
        window.resizeDocks({window.dock("visualizers")}, {480}, Qt::Horizontal);
    }
    DockWait dockWait{nullptr, [] { return true; }, [] { return true; }, [] { return QString(); }};
    if (parser.isSet(dockOption)) {
        auto wait = lpv::editor::dockForShot(window, parser.value(dockOption), spp, parser.value(accuracyOverlay));
        if (!wait) {
            fprintf(stderr, "lpvstudio: %s\n", qPrintable(wait.error()));
            return 2;
        }
        dockWait = *wait;
    }
    if (parser.isSet(screenshot)) {
        const QStringList wh = parser.value(size).split('x');
        const QSize asked(wh.value(0).toInt() > 0 ? wh.value(0).toInt() : 1600,
                          wh.value(1).toInt() > 0 ? wh.value(1).toInt() : 1000);
        window.resize(asked);
        window.show();
        const QString file = parser.value(screenshot);
        // Poll: textures decode in the background; then two more frames so the LPV and timings settle.
        auto* poll = new QTimer(&window);
        auto frames = std::make_shared<int>(0);
        auto lastMs = std::make_shared<double>(0.0);
        QObject::connect(window.viewport(), &lpv::editor::Viewport::frameRendered, &window,
                         [frames, lastMs](const std::vector<lpv::renderer::PassTiming>& table) {
                             ++*frames;
                             *lastMs = 0.0;
                             for (const auto& t : table)
                                 *lastMs += t.lastMs;
                         });
        auto waited = std::make_shared<QElapsedTimer>();
        waited->start();
        QObject::connect(poll, &QTimer::timeout, &window, [&window, file, asked, frames, lastMs, dockWait,
                                                           waited, timeoutS] {
            auto* view = window.viewport();
            const std::optional<QString> dockError = lpv::editor::dockWaitOver(dockWait, waited->elapsed(), timeoutS);
            if (!dockError)
                return;
            if (!dockError->isEmpty()) {
                fprintf(stderr, "lpvstudio: %s\n", qPrintable(*dockError));
                QApplication::exit(1);
                return;
            }
            if (view->texturesPending() || !view->frameUpToDate() || *frames < 3) {
                if (!view->texturesPending() && view->frameUpToDate())
                    view->renderAgain(); // the same state once more: the LPV and timings settle
                else
                    view->update();
                return;
            }
            if (dockWait.dock && !dockWait.dock->isVisible()) { // another tab raised over it
                fprintf(stderr, "lpvstudio: the %s dock is not visible\n", qPrintable(dockWait.dock->objectName()));
                QApplication::exit(1);
                return;
            }
            // QWidget::grab() leaves out what the viewport paints over its GL image with QPainter
            // (gizmo, camera path, visualizer overlays); its own grabFramebuffer() has them.
            QPixmap shot = window.grab();
            {
                QPainter painter(&shot);
                painter.drawImage(window.viewport()->mapTo(&window, QPoint(0, 0)),
                                  window.viewport()->grabFramebuffer());
            }
            if (shot.size() != asked) // the docks' minimum sizes win over --size: say so
                fprintf(stderr, "lpvstudio: the window could not be %dx%d; the shot is %dx%d\n", asked.width(),
                        asked.height(), shot.width(), shot.height());
            const bool saved = shot.save(file);
            // The viewport's size and GPU time, so a screenshot run doubles as a measurement.
            const auto* vp = window.viewport();
            printf("lpvstudio: viewport %dx%d rendered at %.0f%%, last frame %.1f ms GPU (sum of passes)\n",
                   vp->width(), vp->height(), 100.0 * vp->resolutionScale(), *lastMs);
            if (const QString shown = dockWait.summary(); !shown.isEmpty())
                printf("lpvstudio: %s\n", qPrintable(shown));
            fprintf(saved ? stdout : stderr, saved ? "lpvstudio: saved %s\n" : "lpvstudio: cannot write %s\n",
                    qPrintable(file));
            QApplication::exit(saved ? 0 : 1);
        });
        poll->start(200);
        return app.exec();
    }
    window.show();
    // After the window is up, so the question has a parent to sit on. Not in
    // smoke tests: nobody is there to answer it.
    if (quitAfterMs < 0)
        QTimer::singleShot(0, &window, [&window] { window.offerRecovery(); });
    else
        QTimer::singleShot(quitAfterMs, &app, [&] {
            const QString error = window.viewport()->lastError();
            std::printf("lpvstudio: showed %s; viewport: %s\n",
                        qPrintable(path.isEmpty() ? "the built-in Cornell box" : path),
                        qPrintable(error.isEmpty() ? "rendered without error" : error));
            QCoreApplication::exit(error.isEmpty() ? 0 : 1);
        });
    return app.exec();
}
