#include "TestWindow.h"

#include "TestPaths.h"

#include <QMessageBox>
#include <QProcess>
#include <QTest>

namespace lpv::editor::test {

QString cornellTemplate() { return QString(lpv::test::kSourceDir) + "/projects/cornell-box/cornell-box.lpvproj"; }

::testing::AssertionResult importWithCli(const QString& sceneUnderShared, const QString& projectFile) {
    QProcess import;
    import.start(lpv::test::kLpvExecutable,
                 {"import", QString(lpv::test::kSharedScenesDir) + "/" + sceneUnderShared, "-o", projectFile});
    if (!import.waitForFinished(300000))
        return ::testing::AssertionFailure() << "lpv import " << sceneUnderShared.toStdString() << " did not finish";
    if (import.exitCode() != 0)
        return ::testing::AssertionFailure() << "lpv import " << sceneUnderShared.toStdString() << " failed: "
                                             << import.readAllStandardError().toStdString();
    return ::testing::AssertionSuccess();
}

TestWindow::TestWindow() { window.setUnsavedChangesAnswerForTests(QMessageBox::Discard); }

::testing::AssertionResult TestWindow::openAndShow(const QString& project, QSize size) {
    if (!window.openProject(project, false))
        return ::testing::AssertionFailure() << "could not open " << project.toStdString() << ": "
                                             << window.lastOpenError().toStdString();
    return show(size);
}

::testing::AssertionResult TestWindow::show(QSize size) {
    window.resize(size);
    window.show();
    if (!QTest::qWaitForWindowExposed(&window))
        return ::testing::AssertionFailure() << "the window was never exposed";
    return ::testing::AssertionSuccess();
}

} // namespace lpv::editor::test
