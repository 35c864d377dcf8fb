#include "MainWindow.h"
#include "TestPaths.h"
#include "Viewport.h"

#include <QApplication>
#include <QImage>
#include <QStatusBar>
#include <QTest>

#include <gtest/gtest.h>

using lpv::editor::MainWindow;

namespace {
QString cornellPath() { return QString(lpv::test::kSourceDir) + "/projects/cornell-box/cornell-box.lpvproj"; }
} // namespace

TEST(EditorGui, OpensCornellBoxAndViewportRendersIt) {
    MainWindow window;
    ASSERT_TRUE(window.openProject(cornellPath(), false));
    window.resize(640, 480);
    window.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
    QTest::qWait(200);
    const QImage frame = window.viewport()->grabFramebuffer();
    ASSERT_FALSE(frame.isNull());
    ASSERT_TRUE(window.viewport()->lastError().isEmpty()) << window.viewport()->lastError().toStdString();
    // The red wall sits left of centre, the green wall right of it.
    long red = 0, green = 0, lit = 0;
    const int y = frame.height() / 2;
    for (int x = 0; x < frame.width(); ++x) {
        const QColor c = frame.pixelColor(x, y);
        if (x < frame.width() / 2)
            red += c.red() - c.green();
        else
            green += c.green() - c.red();
        lit += c.red() + c.green() + c.blue() > 60 ? 1 : 0;
    }
    EXPECT_GT(lit, frame.width() / 4) << "the viewport frame is (nearly) black";
    EXPECT_GT(red, 0);
    EXPECT_GT(green, 0);
}

TEST(EditorGui, BadProjectShowsErrorAndKeepsCurrent) {
    MainWindow window;
    ASSERT_TRUE(window.openProject(cornellPath(), false));
    EXPECT_FALSE(window.openProject("/nonexistent/broken.lpvproj", false));
    EXPECT_EQ(window.project().name, "cornell-box");
    EXPECT_TRUE(window.statusBar()->currentMessage().contains("/nonexistent/broken.lpvproj"));
}

int main(int argc, char** argv) {
    QApplication app(argc, argv);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
