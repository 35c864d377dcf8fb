// lpvstudio: the LPV Studio editor. Opens the project given on the command
// line, or the built-in Cornell box.
#include "MainWindow.h"
#include "Viewport.h"

#include "lpv/scene/CornellBox.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QFileInfo>
#include <QTimer>

#include <memory>

int main(int argc, char** argv) {
    QApplication app(argc, argv);
    QApplication::setApplicationName("LPV Studio");
    QApplication::setOrganizationName("LPV Studio");
    QApplication::setApplicationVersion(LPV_VERSION);

    QCommandLineParser parser;
    parser.setApplicationDescription("LPV Studio editor: author scenes and tune Light Propagation Volumes");
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument("project", "Project (.lpvproj) to open; default: the built-in Cornell box");
    QCommandLineOption screenshot("screenshot",
                                  "Open the project, wait until its textures are loaded and a frame is drawn, save "
                                  "the main window to FILE (PNG) and quit (docs, smoke tests).",
                                  "FILE");
    QCommandLineOption size("size", "Window size for --screenshot, e.g. 1600x1000.", "WxH", "1600x1000");
    parser.addOption(screenshot);
    parser.addOption(size);
    parser.process(app);

    lpv::editor::MainWindow window;
    const QStringList args = parser.positionalArguments();
    const QString path = args.isEmpty() ? QString(LPV_DEFAULT_PROJECT) : args.front();
    if (!args.isEmpty() || QFileInfo::exists(path)) {
        if (!window.openProject(path, false) && !args.isEmpty()) {
            // The error is on the status bar too; a missing file named by the user is worth a non-zero exit.
            fprintf(stderr, "lpvstudio: could not open %s\n", qPrintable(path));
            return 1;
        }
    } else {
        window.showProject(lpv::scene::makeCornellBoxProject(), "built-in Cornell box");
    }
    if (parser.isSet(screenshot)) {
        const QStringList wh = parser.value(size).split('x');
        window.resize(wh.value(0).toInt() > 0 ? wh.value(0).toInt() : 1600, wh.value(1).toInt() > 0 ? wh.value(1).toInt() : 1000);
        window.show();
        const QString file = parser.value(screenshot);
        // Poll: textures decode in the background; then two more frames so the LPV and timings settle.
        auto* poll = new QTimer(&window);
        auto frames = std::make_shared<int>(0);
        QObject::connect(window.viewport(), &lpv::editor::Viewport::frameRendered, &window, [frames] { ++*frames; });
        QObject::connect(poll, &QTimer::timeout, &window, [&window, file, frames] {
            if (window.viewport()->texturesPending() || *frames < 3) {
                window.viewport()->update();
                return;
            }
            const bool saved = window.grab().save(file);
            fprintf(saved ? stdout : stderr, saved ? "lpvstudio: saved %s\n" : "lpvstudio: cannot write %s\n",
                    qPrintable(file));
            QApplication::exit(saved ? 0 : 1);
        });
        poll->start(200);
        return app.exec();
    }
    window.show();
    // After the window is up, so the question has a parent to sit on.
    QTimer::singleShot(0, &window, [&window] { window.offerRecovery(); });
    return app.exec();
}
