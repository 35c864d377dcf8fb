// `lpvstudio --screenshot FILE --dock DOCK` (issue #46): the docs images of
// the Accuracy and Sweeps docks are made by the editor itself, with results
// in the dock. Run end to end as a user runs it: the real lpvstudio on the
// Cornell template, under the test's X server.
#include "TestPaths.h"
#include "TestWindow.h"

#include <QImage>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>

#include <gtest/gtest.h>

namespace {

struct EditorRun {
    int exitCode = -1;
    QString out, err;
};

// lpvstudio with `args`, its output gathered; a run that hangs ends the test's wait.
EditorRun runEditor(const QStringList& args, int timeoutMs) {
    QProcess editor;
    editor.start(QString(lpv::test::kBinaryDir) + "/app/editor/lpvstudio", args);
    EditorRun run;
    if (!editor.waitForFinished(timeoutMs)) {
        editor.kill();
        editor.waitForFinished();
        run.err = "lpvstudio did not finish";
        return run;
    }
    run.exitCode = editor.exitStatus() == QProcess::NormalExit ? editor.exitCode() : -1;
    run.out = QString::fromLocal8Bit(editor.readAllStandardOutput());
    run.err = QString::fromLocal8Bit(editor.readAllStandardError());
    return run;
}

} // namespace

// The shot exists at the requested size, and lpvstudio says the Accuracy
// dock was shown (it refuses a shot with the dock hidden) with a measured
// MARE against a reference of at least the samples asked for.
TEST(ScreenshotDock, AccuracyDockShowsMeasuredFigures) {
    QTemporaryDir dir;
    const QString shot = dir.filePath("accuracy.png");
    const EditorRun run = runEditor({lpv::editor::test::cornellTemplate(), "--screenshot", shot, "--size", "800x600",
                               "--dock", "accuracy", "--reference-spp", "2", "--dock-timeout", "180"},
                              240000);
    ASSERT_EQ(run.exitCode, 0) << run.out.toStdString() << run.err.toStdString();
    const QImage image(shot);
    ASSERT_FALSE(image.isNull()) << "no shot written at " << shot.toStdString();
    EXPECT_EQ(image.size(), QSize(800, 600));
    const auto figures = QRegularExpression(R"(Accuracy dock: MARE ([0-9.]+)%, FLIP ([0-9.]+) against a (\d+) spp)")
                             .match(run.out);
    ASSERT_TRUE(figures.hasMatch()) << run.out.toStdString();
    EXPECT_GT(figures.captured(1).toDouble(), 0.0);
    EXPECT_GE(figures.captured(3).toInt(), 2);
}

// A dock it does not know is refused before anything opens, with the names it knows.
TEST(ScreenshotDock, UnknownDockIsRefused) {
    QTemporaryDir dir;
    const QString shot = dir.filePath("none.png");
    const EditorRun run = runEditor({lpv::editor::test::cornellTemplate(), "--screenshot", shot, "--dock", "profiler"},
                              60000);
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_TRUE(run.err.contains("--dock must be one of accuracy, sweeps")) << run.err.toStdString();
    EXPECT_FALSE(QFile::exists(shot));
}

// Without --screenshot there is nothing to wait for: refused, not ignored.
TEST(ScreenshotDock, DockWithoutScreenshotIsRefused) {
    const EditorRun run = runEditor({lpv::editor::test::cornellTemplate(), "--dock", "accuracy"}, 60000);
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_TRUE(run.err.contains("--dock needs --screenshot")) << run.err.toStdString();
}
