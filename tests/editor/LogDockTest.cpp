// The Log dock (issue #26 item 5): what the editor did and what went wrong,
// each with its time and source; the status bar counts the warnings and
// errors not yet seen and leads to the dock. Through the real window under xvfb.
#include "Autosave.h"
#include "EventLog.h"
#include "LogPanel.h"
#include "MainWindow.h"
#include "TestPaths.h"
#include "WaitUntil.h"
#include "TestWindow.h"

#include <QDockWidget>
#include <QFile>
#include <QMessageBox>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QToolButton>

#include <gtest/gtest.h>

#include <thread>

using namespace lpv::editor;

namespace {


bool hasEntry(const EventLog& log, EventLog::Severity severity, const QString& source, const QString& part) {
    for (const EventLog::Entry& e : log.entries())
        if (e.severity == severity && e.source == source && e.text.contains(part) && e.time.isValid())
            return true;
    return false;
}

void writeFile(const QString& path, const QByteArray& bytes) {
    QFile f(path);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write(bytes);
}

} // namespace

TEST(LogDock, ImportsOpensAndSavesAreLoggedAndTheStatusBarLeadsToThem) {
    QTemporaryDir dir;
    test::TestWindow w;
    ASSERT_TRUE(w.openAndShow(test::cornellTemplate(), {1280, 900}));
    MainWindow& window = w.window;
    EventLog& log = *window.eventLog();
    EXPECT_TRUE(hasEntry(log, EventLog::Severity::Info, "Open", "cornell-box.lpvproj"));
    EXPECT_TRUE(hasEntry(log, EventLog::Severity::Info, "OpenGL", "GL debug messages"));
    LPV_WAIT_UNTIL(window.logButton()->isHidden(), 5000); // nothing to see yet

    // A scene file that cannot be read: an error, counted in the status bar.
    const QString broken = dir.filePath("broken.gltf");
    writeFile(broken, "{ not json");
    window.importFile(broken, false);
    LPV_WAIT_UNTIL(!window.importRunning(), 30000);
    EXPECT_TRUE(hasEntry(log, EventLog::Severity::Error, "Import", "broken.gltf"));
    LPV_WAIT_UNTIL(window.logButton()->isVisible(), 5000);
    EXPECT_TRUE(window.logButton()->text().contains("1 error")) << window.logButton()->text().toStdString();

    // A scene whose texture is missing: its summary and the warning.
    writeFile(dir.filePath("box.mtl"), "newmtl painted\nKd 0.8 0.8 0.8\nmap_Kd missing-texture.png\n");
    writeFile(dir.filePath("box.obj"), "mtllib box.mtl\nusemtl painted\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                       "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1 2/2 3/3 4/4\n");
    window.importFile(dir.filePath("box.obj"), false);
    LPV_WAIT_UNTIL(!window.importRunning(), 30000);
    EXPECT_TRUE(hasEntry(log, EventLog::Severity::Info, "Import", "box.obj"));
    LPV_WAIT_UNTIL(hasEntry(log, EventLog::Severity::Warning, "Import", "missing-texture.png") ||
                                 hasEntry(log, EventLog::Severity::Warning, "Textures", "missing-texture.png"), 30000);
    EXPECT_TRUE(window.logButton()->text().contains("warning")) << window.logButton()->text().toStdString();

    // The status bar's count opens the dock and starts again from zero.
    QDockWidget* dock = window.dock("log");
    ASSERT_NE(dock, nullptr);
    QTest::mouseClick(window.logButton(), Qt::LeftButton);
    LPV_WAIT_UNTIL(dock->isVisible(), 5000);
    EXPECT_TRUE(window.logButton()->isHidden());
    QTableWidget* table = window.logPanel()->table();
    ASSERT_GE(table->rowCount(), 4);
    bool errorRow = false;
    for (int r = 0; r < table->rowCount(); ++r) {
        EXPECT_FALSE(table->item(r, 0)->text().isEmpty()) << "every row has its time";
        errorRow = errorRow || (table->item(r, 1)->text() == "error" && table->item(r, 2)->text() == "Import");
    }
    EXPECT_TRUE(errorRow);
    // Errors only: the failed import's row alone.
    window.logPanel()->setMinimumSeverity(2);
    EXPECT_EQ(table->rowCount(), 1);
    window.logPanel()->setMinimumSeverity(0);

    // A save, and a save that cannot be written.
    ASSERT_TRUE(window.saveTo(dir.filePath("saved.lpvproj"), false));
    EXPECT_TRUE(hasEntry(log, EventLog::Severity::Info, "Save", "saved.lpvproj"));
    writeFile(dir.filePath("a-file"), "not a folder");
    EXPECT_FALSE(window.saveTo(dir.filePath("a-file/x.lpvproj"), false));
    EXPECT_TRUE(hasEntry(log, EventLog::Severity::Error, "Save", "a-file")) << log.entries().back().text.toStdString();
    // A project that cannot be opened.
    EXPECT_FALSE(window.openProject(dir.filePath("absent.lpvproj"), false));
    EXPECT_TRUE(hasEntry(log, EventLog::Severity::Error, "Open", "absent.lpvproj"));
}

TEST(LogDock, KeepsAtMostItsLimitAndPostsFromOtherThreads) {
    EventLog log;
    for (std::size_t i = 0; i < EventLog::kMaxEntries + 5; ++i)
        log.add(EventLog::Severity::Info, "test", QString::number(i));
    EXPECT_LE(log.entries().size(), EventLog::kMaxEntries);
    EXPECT_EQ(log.entries().back().text, QString::number(EventLog::kMaxEntries + 4)) << "the newest stay";
    log.clear();
    std::thread other([&] { log.post(EventLog::Severity::Warning, "OpenGL", "from the render thread"); });
    other.join();
    EXPECT_TRUE(log.entries().empty()) << "queued to the log's thread";
    LPV_WAIT_UNTIL((int(log.entries().size())) == (1), 5000);
    EXPECT_EQ(log.unseenWarnings(), 1);
}
