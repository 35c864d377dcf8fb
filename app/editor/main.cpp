// lpvstudio: the LPV Studio editor. Opens the project given on the command
// line, or the built-in Cornell box.
#include "MainWindow.h"

#include "lpv/scene/CornellBox.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QFileInfo>
#include <QTimer>

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
    window.show();
    // After the window is up, so the question has a parent to sit on.
    QTimer::singleShot(0, &window, [&window] { window.offerRecovery(); });
    return app.exec();
}
