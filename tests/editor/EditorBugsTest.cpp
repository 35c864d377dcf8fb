// Editor bugs found by using it (issue #26 item 6), each with the test that
// showed it: through the real window under xvfb, as EditorGuiTest.cpp.
#include "Autosave.h"
#include "Document.h"
#include "MainWindow.h"
#include "ParameterInspector.h"
#include "EffectsPanel.h"
#include "OutlinerPanel.h"
#include "ProfilerPanel.h"
#include "TestPaths.h"
#include "Viewport.h"
#include "WaitUntil.h"
#include "TestWindow.h"

#include <QAbstractButton>
#include <QApplication>
#include <QDockWidget>
#include <QScreen>
#include <QElapsedTimer>
#include <QFile>
#include <QMessageBox>
#include <QPointer>
#include <QProgressDialog>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStatusBar>
#include <QHeaderView>
#include <QTableWidget>
#include <QTreeWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QUndoStack>

#include <gtest/gtest.h>

#include <set>

using namespace lpv::editor;

namespace {

// A shown window with the Cornell box open; autosaves go to a temporary folder.
struct Window : test::TestWindow {
    Window() { EXPECT_TRUE(openAndShow(test::cornellTemplate(), {1280, 900})); }
    Document& doc() { return *window.document(); }
    // The timing table of the next frame of the current state.
    std::vector<lpv::renderer::PassTiming> nextFrame() {
        Viewport* vp = window.viewport();
        QSignalSpy frames(vp, &Viewport::frameRendered);
        vp->renderAgain();
        EXPECT_TRUE(QTest::qWaitFor([&] { return !frames.isEmpty() && vp->frameUpToDate(); }, 120000));
        return frames.isEmpty() ? std::vector<lpv::renderer::PassTiming>{}
                                : frames.last().at(0).value<std::vector<lpv::renderer::PassTiming>>();
    }
};

} // namespace

// Bug 1: a failed import left its progress dialog up (it was only deleted
// later, after the error box's own event loop), window-modal over the error
// box: the box's OK did nothing until the import's Cancel was pressed. And
// the dialog came up after 4 s, not after its minimum duration of 300 ms.
TEST(EditorBugs, FailedImportLeavesNoProgressDialogOverItsErrorBox) {
    Window w;
    // Vertices and no faces: Assimp reads all 48 MB (1-2 s here), then fails.
    // The dialog shows at once, so even a much faster machine meets it.
    w.window.setImportProgressDelay(0);
    QTemporaryDir dir;
    const QString bad = dir.filePath("nofaces.obj");
    QFile f(bad);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    const QByteArray vertices = QByteArray("v 1 2 3\n").repeated(100000);
    for (int i = 0; i < 60; ++i)
        f.write(vertices);
    f.close();

    // The error box runs its own event loop: watch it from a timer.
    QPointer<QMessageBox> box;
    QElapsedTimer boxShown;
    bool progressBeforeBox = false, progressOverBox = false, clickedOk = false, closedByOk = false;
    QTimer watch;
    watch.setInterval(50);
    QObject::connect(&watch, &QTimer::timeout, [&] {
        if (!boxShown.isValid()) {
            for (QProgressDialog* p : w.window.findChildren<QProgressDialog*>())
                progressBeforeBox |= p->isVisible();
            for (QWidget* top : QApplication::topLevelWidgets())
                if (auto* b = qobject_cast<QMessageBox*>(top); b && b->isVisible())
                    box = b;
            if (box)
                boxShown.start();
            return;
        }
        if (!clickedOk) {
            if (boxShown.elapsed() < 400) // long enough for a stale dialog to show over the box
                return;
            if (!box) {
                watch.stop();
                return;
            }
            for (QProgressDialog* p : w.window.findChildren<QProgressDialog*>())
                progressOverBox |= p->isVisible();
            QTest::mouseClick(box->button(QMessageBox::Ok), Qt::LeftButton);
            clickedOk = true;
            return;
        }
        QMessageBox* open = box.data();
        closedByOk = open == nullptr || !open->isVisible();
        // Before the fix the click was blocked: get out of the box's loop anyway.
        for (QProgressDialog* p : w.window.findChildren<QProgressDialog*>())
            p->cancel();
        if (open != nullptr)
            open->done(QMessageBox::Ok);
        watch.stop();
    });
    watch.start();
    w.window.importFile(bad, true);
    LPV_WAIT_UNTIL(!watch.isActive(), 30000);
    EXPECT_TRUE(clickedOk) << "no error box";
    EXPECT_TRUE(progressBeforeBox) << "the import failed before its progress dialog came up: the case is not tested";
    EXPECT_FALSE(progressOverBox) << "the progress dialog came up over the error box";
    EXPECT_TRUE(closedByOk) << "the error box's OK did not close it";
    EXPECT_FALSE(w.window.importRunning());
    EXPECT_TRUE(w.window.statusBar()->currentMessage().contains("nofaces.obj"));
}

// Bug 2: the timer keeps a row for every pass it ever timed; the profiler
// summed the LPV rows of an earlier frame into a frame that ran no LPV.
TEST(EditorBugs, ProfilerCountsOnlyThePassesThatRanThisFrame) {
    Window w;
    auto names = [](const std::vector<lpv::renderer::PassTiming>& table) {
        std::set<std::string> out;
        for (const auto& t : table)
            out.insert(t.pass);
        return out;
    };
    const auto withLpv = names(w.nextFrame());
    ASSERT_TRUE(withLpv.count("lpvPropagation")) << "the Cornell box runs the LPV";
    w.doc().setParameter("gi.method", lpv::scene::ParameterValue(std::string("off")));
    const auto table = w.nextFrame();
    EXPECT_FALSE(names(table).count("lpvPropagation")) << "a pass that did not run is in the frame";
    EXPECT_FALSE(names(table).count("lpvInjection"));
    EXPECT_TRUE(names(table).count("shading"));
    w.window.profiler()->refreshNow();
    const QTableWidget* rows = w.window.profiler()->table();
    for (int r = 0; r < rows->rowCount(); ++r)
        EXPECT_FALSE(rows->item(r, 0)->text().startsWith("lpv")) << rows->item(r, 0)->text().toStdString();
}

// Bug 2: a project opened anew kept the statistics (median, min, max over
// 120 frames) of the one before, and the first frame's total read 0 ms
// (its timer queries were still in flight), so the Frame row's Min said 0.000.
TEST(EditorBugs, ProfilerStartsAgainWithANewProjectAndNeverReadsZero) {
    Window w;
    for (int i = 0; i < 3; ++i)
        w.nextFrame();
    ASSERT_TRUE(w.window.openProject(test::cornellTemplate(), false));
    QSignalSpy frames(w.window.viewport(), &Viewport::frameRendered);
    LPV_WAIT_UNTIL(!frames.isEmpty(), 120000);
    const auto first = frames.first().at(0).value<std::vector<lpv::renderer::PassTiming>>();
    ASSERT_FALSE(first.empty()) << "the first frame of a project has its times";
    for (const auto& t : first) {
        EXPECT_EQ(t.samples, 1u) << t.pass << ": statistics of the project before";
        EXPECT_GT(t.lastMs, 0.0) << t.pass;
    }
    w.window.profiler()->refreshNow();
    const QTableWidget* rows = w.window.profiler()->table();
    ASSERT_GT(rows->rowCount(), 1);
    const int frameRow = rows->rowCount() - 1;
    ASSERT_TRUE(rows->item(frameRow, 0)->text().startsWith(ProfilerPanel::kFrameName));
    EXPECT_GT(rows->item(frameRow, 3)->text().toDouble(), 0.0) << "the frame's Min";
}

// Bug 3: a spin box with the focus took Ctrl+Z as its own text undo, and the
// project's history never saw it.
TEST(EditorBugs, CtrlZUndoesWhileAnInspectorSpinBoxHasTheFocus) {
    Window w;
    w.window.activateWindow();
    ASSERT_TRUE(QTest::qWaitForWindowActive(&w.window));
    auto* steps = qobject_cast<QSpinBox*>(w.window.inspector()->editorFor("lpv.propagationSteps"));
    ASSERT_NE(steps, nullptr);
    const int before = w.doc().parameters().getInt("lpv.propagationSteps");
    steps->setFocus();
    LPV_WAIT_UNTIL(steps->hasFocus(), 5000);
    // Typed, as a user does: select all, the new value, Enter.
    QTest::keyClick(steps, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(steps, "17");
    QTest::keyClick(steps, Qt::Key_Return);
    ASSERT_EQ(w.doc().parameters().getInt("lpv.propagationSteps"), 17);
    ASSERT_TRUE(steps->hasFocus());
    QTest::keyClick(steps, Qt::Key_Z, Qt::ControlModifier);
    EXPECT_EQ(w.doc().parameters().getInt("lpv.propagationSteps"), before);
    EXPECT_EQ(steps->value(), before) << "the spin box follows the undo";
    QTest::keyClick(steps, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    EXPECT_EQ(w.doc().parameters().getInt("lpv.propagationSteps"), 17);
    EXPECT_EQ(steps->value(), 17);
}

// Bug 4: `lpvstudio bad.lpvproj` exited with "could not open" and no reason;
// now the editor opens and says what is wrong where.
TEST(EditorBugs, ProjectFromTheCommandLineThatCannotBeReadOpensTheEditorWithTheError) {
    QTemporaryDir dir;
    QFile good(test::cornellTemplate());
    ASSERT_TRUE(good.open(QIODevice::ReadOnly));
    QByteArray text = good.readAll();
    const qsizetype at = text.indexOf("\"fovY\": ");
    ASSERT_GE(at, 0);
    text.replace(at, text.indexOf(',', at) - at, "\"fovY\": -1.0");
    const QString bad = dir.filePath("bad.lpvproj");
    QFile out(bad);
    ASSERT_TRUE(out.open(QIODevice::WriteOnly));
    out.write(text);
    out.close();

    test::TemporaryAutosaveRoot autosaveRoot;
    MainWindow window;
    EXPECT_FALSE(window.openFromCommandLine(bad));
    window.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
    QMessageBox* box = nullptr;
    LPV_WAIT_UNTIL((box = window.findChild<QMessageBox*>("openError")) && box->isVisible(), 5000);
    EXPECT_TRUE(box->text().contains("bad.lpvproj")) << box->text().toStdString();
    EXPECT_TRUE(box->text().contains("fovY")) << box->text().toStdString();
    EXPECT_EQ(box->text(), window.lastOpenError());
    EXPECT_TRUE(window.isVisible());
    box->button(QMessageBox::Ok)->click();
    LPV_WAIT_UNTIL(!window.findChild<QMessageBox*>("openError"), 5000);
}

// Bug 7: showing the Visualizers dock grew the window past the screen (its
// controls' minimum height stacked under the inspector's), and closing the
// dock left it so.
TEST(EditorBugs, VisualizersDockKeepsTheWindowOnTheScreen) {
    Window w;
    w.window.resize(1280, 900);
    LPV_WAIT_UNTIL((w.window.height()) == (900), 5000);
    const int screen = w.window.screen()->availableGeometry().height();
    QDockWidget* viz = w.window.dock("visualizers");
    viz->show();
    QTest::qWait(200);
    const int shown = w.window.frameGeometry().height();
    EXPECT_LE(w.window.height(), 900);
    EXPECT_LE(shown, screen);
    viz->hide();
    QTest::qWait(200);
    EXPECT_LE(w.window.height(), 900) << "after closing the dock";
}

// The outliner's dock had no width of its own and showed names cut to one or
// two letters; the Effects panel's "why" text was cut off (rows sized before
// the column had its width, and the column as wide as its one-line text).
TEST(EditorBugs, OutlinerNamesAndEffectsReasonsAreShownWhole) {
    Window w;
    LPV_WAIT_UNTIL(w.window.isVisible(), 5000);
    QTest::qWait(100);
    QTreeWidget* tree = w.window.outliner()->tree();
    int cut = 0, names = 0;
    for (QTreeWidgetItemIterator it(tree); *it; ++it) {
        if (!(*it)->parent())
            continue; // the group headers
        ++names;
        const QRect shown = tree->visualItemRect(*it);
        const int needed = tree->fontMetrics().horizontalAdvance((*it)->text(0));
        // The item's text starts after its indentation and check box.
        cut += shown.left() + needed + 24 > tree->viewport()->width() ? 1 : 0;
    }
    ASSERT_GT(names, 3);
    EXPECT_EQ(cut, 0) << "outliner names cut: the tree is " << tree->viewport()->width() << " px wide";

    QDockWidget* effectsDock = w.window.dock("effects");
    effectsDock->show();
    effectsDock->raise();
    QTest::qWait(200);
    QTableWidget* table = w.window.effects()->table();
    ASSERT_GT(table->rowCount(), 3);
    // QTableView::sizeHintForRow is protected: reach it through a derived class's using-declaration.
    struct Hint : QTableWidget {
        using QTableWidget::sizeHintForRow;
    };
    int (QTableView::*rowHint)(int) const = &Hint::sizeHintForRow;
    EXPECT_LE(table->horizontalHeader()->sectionPosition(3) + table->columnWidth(3), table->viewport()->width() + 1)
        << "the why column runs off the panel: columns " << table->columnWidth(0) << ", " << table->columnWidth(1)
        << ", " << table->columnWidth(2) << ", " << table->columnWidth(3);
    for (int row = 0; row < table->rowCount(); ++row) {
        ASSERT_NE(table->item(row, 3), nullptr);
        // What the row needs at the columns' present widths (the delegate's own wrapping).
        EXPECT_GE(table->rowHeight(row), (table->*rowHint)(row))
            << "row " << row << " cut: " << table->item(row, 3)->text().toStdString();
    }
}

// An imported interior was framed from outside while `lpv import` and `lpv
// render` stand inside it (issue #26 item 6): the editor now shows an imported
// scene from its own camera or scene::framingCamera, as the CLI does.
TEST(EditorBugs, AnImportedInteriorIsSeenFromInsideAsTheCliSeesIt) {
    Window w;
    QTemporaryDir dir;
    const QString room = dir.filePath("room.obj");
    QFile f(room);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    // A closed 10 x 4 x 6 m hall, every face turned inward, and a pillar.
    f.write("v 0 0 0\nv 10 0 0\nv 10 0 6\nv 0 0 6\nv 0 4 0\nv 10 4 0\nv 10 4 6\nv 0 4 6\n"
            "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 4 8 7 3\nf 1 5 8 4\nf 2 3 7 6\n"
            "v 4.8 0 2.8\nv 5.2 0 2.8\nv 5.2 0 3.2\nv 4.8 0 3.2\nv 4.8 4 2.8\nv 5.2 4 2.8\nv 5.2 4 3.2\nv 4.8 4 3.2\n"
            "f 9 10 14 13\nf 10 11 15 14\nf 11 12 16 15\nf 12 9 13 16\n");
    f.close();
    w.window.importFile(room, false);
    LPV_WAIT_UNTIL(!w.window.importRunning(), 30000);
    const glm::vec3 eye = w.window.viewport()->viewCamera().position;
    EXPECT_TRUE(eye.x > 0.0f && eye.x < 10.0f && eye.y > 0.0f && eye.y < 4.0f && eye.z > 0.0f && eye.z < 6.0f)
        << "the view stands at (" << eye.x << ", " << eye.y << ", " << eye.z << "), outside the hall";
}

// Bug 6, second half: the editor's camera was not saved with the project, so
// a reopened project showed its first camera instead of where the user left it.
TEST(EditorBugs, TheViewIsSavedWithTheProjectAndReopensThere) {
    Window w;
    const lpv::scene::Camera first = w.window.viewport()->viewCamera();
    lpv::scene::Camera moved = first;
    moved.position += glm::vec3(0.75f, -0.5f, 1.5f);
    moved.fovY = first.fovY * 0.8f;
    w.window.viewport()->setViewCamera(moved);
    QTemporaryDir dir;
    const QString file = dir.filePath("view.lpvproj");
    ASSERT_TRUE(w.window.saveTo(file, false));
    EXPECT_FALSE(w.doc().isModified()) << "the view is not an edit";
    // Another project in between, then the saved one again.
    ASSERT_TRUE(w.window.openProject(test::cornellTemplate(), false));
    EXPECT_EQ(w.window.viewport()->viewCamera().position, first.position);
    ASSERT_TRUE(w.window.openProject(file, false));
    const lpv::scene::Camera reopened = w.window.viewport()->viewCamera();
    EXPECT_EQ(reopened.position, moved.position);
    EXPECT_EQ(reopened.target, moved.target);
    EXPECT_EQ(reopened.fovY, moved.fovY);
    // The scene's own cameras are unchanged: the CLI still renders from the first.
    auto saved = lpv::scene::loadProject(file.toStdString());
    ASSERT_TRUE(saved) << saved.error().describe();
    ASSERT_FALSE(saved->scene.cameras.empty());
    EXPECT_EQ(saved->scene.cameras.front().position, first.position);
}
