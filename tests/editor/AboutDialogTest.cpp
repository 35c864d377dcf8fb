// Help > About LPV Studio: the menu entry exists and the dialog shows the
// same report as `lpv --version` plus Qt's version and the viewport's driver.
#include "AboutDialog.h"
#include "MainWindow.h"
#include "TestPaths.h"
#include "Viewport.h"

#include <QAction>
#include <QApplication>
#include <QMenu>
#include <QMenuBar>
#include <QTest>

#include <gtest/gtest.h>

using lpv::editor::MainWindow;

namespace {

QAction* findAction(QMenuBar* bar, const QString& menuText, const QString& actionText) {
    for (QAction* menuAction : bar->actions()) {
        if (!menuAction->menu() || menuAction->text().remove('&') != menuText)
            continue;
        for (QAction* action : menuAction->menu()->actions())
            if (action->text().remove('&') == actionText)
                return action;
    }
    return nullptr;
}

} // namespace

TEST(AboutDialog, HelpMenuHasTheEntry) {
    MainWindow window;
    EXPECT_NE(findAction(window.menuBar(), "Help", "About LPV Studio"), nullptr);
}

TEST(AboutDialog, ShowsVersionRevisionQtAndTheViewportsDriver) {
    MainWindow window;
    ASSERT_TRUE(window.openProject(
        QString(lpv::test::kSourceDir) + "/projects/cornell-box/cornell-box.lpvproj", false));
    window.resize(320, 240);
    window.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
    ASSERT_TRUE(QTest::qWaitFor([&] { return window.viewport()->frameUpToDate(); }, 60000));

    lpv::editor::AboutDialog dialog(window.viewport()->renderGlInfo(), &window);
    const QString text = dialog.reportText();
    EXPECT_TRUE(text.startsWith(QString("LPV Studio ") + LPV_TEST_PROJECT_VERSION + "\n"))
        << text.toStdString();
    EXPECT_TRUE(text.contains("\nrevision:  ")) << text.toStdString();
    EXPECT_TRUE(text.contains(QString("\n  Qt "))) << text.toStdString();
    EXPECT_TRUE(text.contains(qVersion())) << text.toStdString();
    for (const char* lib : {"Assimp", "OpenImageIO", "glm", "nlohmann_json", "libepoxy"})
        EXPECT_TRUE(text.contains(QString("\n  ") + lib)) << lib;

    // The driver is the one the viewport's frames render with, as its context reports it.
    const auto info = window.viewport()->renderGlInfo();
    ASSERT_TRUE(info.has_value());
    EXPECT_FALSE(info->renderer.empty());
    EXPECT_TRUE(text.contains(QString("OpenGL:    ") + QString::fromStdString(info->renderer))) << text.toStdString();
    EXPECT_TRUE(text.contains("Qt platform xcb")) << text.toStdString();
    // Issue #45: the GPU, the driver and the platform, each on its own line.
    EXPECT_TRUE(text.contains(QString("\nGPU:       ") + QString::fromStdString(info->renderer))) << text.toStdString();
    EXPECT_TRUE(text.contains(QString("\ndriver:    OpenGL ") + QString::fromStdString(info->version)))
        << text.toStdString();
    EXPECT_TRUE(text.contains(QString("\nplatform:  ") +
                              (info->eglPlatform.empty() ? QString("not EGL")
                                                         : "EGL " + QString::fromStdString(info->eglPlatform))))
        << text.toStdString();
}

TEST(AboutDialog, WithoutAViewportContextSaysSo) {
    const QString text = lpv::editor::aboutReport(std::nullopt);
    EXPECT_TRUE(text.contains("OpenGL:    unavailable: ")) << text.toStdString();
}
