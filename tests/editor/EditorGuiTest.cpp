// The editor through its real window under xvfb (OpenGL 4.5 on llvmpipe):
// open, render, edit, undo/redo, save/reopen, import, pick, create, autosave.
#include "Autosave.h"
#include "CameraPathPanel.h"
#include "VideoExportDialog.h"
#include "Document.h"
#include "MainWindow.h"
#include "EffectsPanel.h"
#include "OutlinerPanel.h"
#include "ParameterInspector.h"
#include "TestPaths.h"
#include "TransformGizmo.h"
#include "Viewport.h"

#include "lpv/scene/Picking.h"
#include "WaitUntil.h"
#include "TestWindow.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QLineEdit>
#include <QSpinBox>
#include <QTableWidget>
#include <QDir>
#include <QFileInfo>
#include <QImage>
#include <QMessageBox>
#include <QSettings>
#include <QSpinBox>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QTreeWidget>
#include <QUndoStack>

#include <gtest/gtest.h>

using namespace lpv::editor;

namespace {

QString cornellPath() { return test::cornellTemplate(); }

// A shown window with the Cornell box open; autosaves go to a temporary folder.
struct OpenWindow : test::TestWindow {
    explicit OpenWindow(const QString& project = cornellPath()) {
        EXPECT_TRUE(openAndShow(project, {1280, 900}));
        QTest::qWait(100);
    }
    Document& doc() { return *window.document(); }
};

// The view once it shows a frame of the current state: frames render on the
// viewport's worker thread, and the widget shows the last finished one.
QImage upToDateFrame(Viewport* vp) {
    vp->update();
    EXPECT_TRUE(QTest::qWaitFor([&] { return vp->frameUpToDate(); }, 120000)) << "no frame of the current state";
    return vp->grabFramebuffer();
}

// Fraction of pixels that are not (nearly) black.
double litFraction(const QImage& image) {
    long lit = 0;
    for (int y = 0; y < image.height(); y += 4)
        for (int x = 0; x < image.width(); x += 4) {
            const QColor c = image.pixelColor(x, y);
            lit += c.red() + c.green() + c.blue() > 60 ? 1 : 0;
        }
    return double(lit) / double((image.height() / 4) * (image.width() / 4));
}

} // namespace

TEST(EditorGui, OpensCornellBoxAndViewportRendersIt) {
    OpenWindow w;
    const QImage frame = upToDateFrame(w.window.viewport());
    ASSERT_FALSE(frame.isNull());
    ASSERT_TRUE(w.window.viewport()->lastError().isEmpty()) << w.window.viewport()->lastError().toStdString();
    // Clearly red pixels (the left wall) lie in the left half, clearly green ones (the right wall) in the right half.
    long redLeft = 0, redRight = 0, greenLeft = 0, greenRight = 0;
    for (int y = 0; y < frame.height(); y += 2)
        for (int x = 0; x < frame.width(); x += 2) {
            const QColor c = frame.pixelColor(x, y);
            const bool left = x < frame.width() / 2;
            if (c.red() > 60 && c.red() > 2 * c.green())
                (left ? redLeft : redRight)++;
            // The lamp's warm light (17, 12, 4) and the tonemapper leave the green wall at about 1.5x green over red.
            if (c.green() > 60 && c.green() > 1.3 * c.red() && c.green() > 2 * c.blue())
                (left ? greenLeft : greenRight)++;
        }
    EXPECT_GT(litFraction(frame), 0.15) << "the viewport frame is (nearly) black";
    EXPECT_GT(redLeft, 100);
    EXPECT_GT(greenRight, 100);
    EXPECT_LT(redRight, redLeft / 10);
    EXPECT_LT(greenLeft, greenRight / 10);
    EXPECT_EQ(w.window.windowTitle(), "cornell-box.lpvproj[*] - LPV Studio");
    EXPECT_FALSE(w.window.isWindowModified());
}

TEST(EditorGui, BadProjectShowsErrorAndKeepsCurrent) {
    OpenWindow w;
    EXPECT_FALSE(w.window.openProject("/nonexistent/broken.lpvproj", false));
    EXPECT_EQ(w.doc().project().name, "cornell-box");
    EXPECT_TRUE(w.window.statusBar()->currentMessage().contains("/nonexistent/broken.lpvproj"));
}

TEST(EditorGui, ParameterEditThroughTheInspectorUndoRedoSaveReopen) {
    OpenWindow w;
    Document& doc = w.doc();
    auto* steps = qobject_cast<QSpinBox*>(w.window.inspector()->editorFor("lpv.propagationSteps"));
    ASSERT_NE(steps, nullptr);
    const int before = doc.parameters().getInt("lpv.propagationSteps");
    ASSERT_EQ(steps->value(), before);
    steps->setValue(16); // as the arrows or the slider do
    EXPECT_EQ(doc.parameters().getInt("lpv.propagationSteps"), 16);
    EXPECT_TRUE(w.window.isWindowModified());
    EXPECT_TRUE(w.window.windowTitle().contains("[*]"));
    doc.undoStack()->undo();
    EXPECT_EQ(doc.parameters().getInt("lpv.propagationSteps"), before);
    EXPECT_EQ(steps->value(), before) << "the inspector follows undo";
    EXPECT_FALSE(w.window.isWindowModified());
    doc.undoStack()->redo();
    EXPECT_EQ(doc.parameters().getInt("lpv.propagationSteps"), 16);
    EXPECT_EQ(steps->value(), 16);

    QTemporaryDir dir;
    const QString path = dir.filePath("edited.lpvproj");
    ASSERT_TRUE(w.window.saveTo(path, false));
    EXPECT_FALSE(w.window.isWindowModified());
    const lpv::scene::Project saved = doc.project();
    MainWindow reopened;
    ASSERT_TRUE(reopened.openProject(path, false));
    EXPECT_EQ(reopened.document()->project(), saved);
    EXPECT_EQ(reopened.document()->parameters().getInt("lpv.propagationSteps"), 16);
}

TEST(EditorGui, PresetsSaveApplyAndSplitTheView) {
    OpenWindow w;
    Document& doc = w.doc();
    doc.setParameter("lpv.intensity", 0.0);
    doc.savePreset("no LPV");
    doc.setParameter("lpv.intensity", 2.0);
    doc.savePreset("bright LPV");
    ASSERT_EQ(doc.project().presets.size(), 2u);
    doc.applyPreset(0);
    EXPECT_FLOAT_EQ(doc.parameters().getFloat("lpv.intensity"), 0.0f);
    doc.undoStack()->undo();
    EXPECT_FLOAT_EQ(doc.parameters().getFloat("lpv.intensity"), 2.0f);

    // A/B: exposure -6 EV on the left half, +3 EV on the right: the right half is brighter.
    doc.setParameter("output.exposure", -6.0);
    doc.savePreset("dark");
    doc.setParameter("output.exposure", 3.0);
    doc.savePreset("bright");
    w.window.setSplit(2, 3);
    EXPECT_TRUE(w.window.viewport()->splitActive());
    QTest::qWait(100);
    const QImage frame = upToDateFrame(w.window.viewport());
    QImage left = frame.copy(0, 0, frame.width() / 2, frame.height());
    QImage right = frame.copy(frame.width() / 2, 0, frame.width() - frame.width() / 2, frame.height());
    EXPECT_GT(litFraction(right), litFraction(left) + 0.2);
    EXPECT_LT(litFraction(left), 0.1);
    w.window.setSplit(-2, -2);
    EXPECT_FALSE(w.window.viewport()->splitActive());

    // Presets travel with the project.
    QTemporaryDir dir;
    ASSERT_TRUE(w.window.saveTo(dir.filePath("presets.lpvproj"), false));
    auto reopened = lpv::scene::loadProject(dir.filePath("presets.lpvproj").toStdString());
    ASSERT_TRUE(reopened);
    EXPECT_EQ(reopened->presets, doc.project().presets);
}

TEST(EditorGui, SliderDragMergesIntoOneUndoStep) {
    OpenWindow w;
    Document& doc = w.doc();
    const lpv::scene::ParameterSet before = doc.parameters();
    for (double v : {1.1, 1.2, 1.3, 1.4})
        doc.setParameter("output.exposure", v);
    EXPECT_EQ(doc.undoStack()->count(), 1);
    EXPECT_DOUBLE_EQ(doc.parameters().getFloat("output.exposure"), 1.4f);
    doc.undoStack()->undo();
    EXPECT_EQ(doc.parameters(), before);
}

TEST(EditorGui, ClickSelectsTheObjectUnderTheMouseAndOutlinerFollows) {
    OpenWindow w;
    Viewport* vp = w.window.viewport();
    // Find a pixel whose ray hits an object, the way the viewport computes it.
    const lpv::scene::Ray ray = lpv::scene::cameraRay(vp->viewCamera(), vp->width() / 2.0f + 0.5f,
                                                      vp->height() / 2.0f + 0.5f, vp->width(), vp->height());
    const auto expected = lpv::scene::pickObject(w.doc().scene(), ray.origin, ray.direction);
    ASSERT_TRUE(expected);
    QTest::mouseClick(vp, Qt::LeftButton, {}, QPoint(vp->width() / 2, vp->height() / 2));
    EXPECT_EQ(w.doc().selection(), (Selection{Selection::Kind::Object, expected->object}));
    const auto selected = w.window.outliner()->tree()->selectedItems();
    ASSERT_EQ(selected.size(), 1);
    EXPECT_EQ(selected.front()->text(0).toStdString(), w.doc().scene().objects[std::size_t(expected->object)].name);
}

TEST(EditorGui, GizmoDragMovesTheSelectionInOneUndoStep) {
    OpenWindow w;
    Viewport* vp = w.window.viewport();
    w.doc().select({Selection::Kind::Object, 0});
    QTest::qWait(50);
    const auto before = w.doc().scene().objects[0].transform;
    // The gizmo's x handle starts at the pivot (the selection's bounds centre); drag along it.
    ASSERT_TRUE(vp->gizmoPivot().has_value());
    TransformGizmo gizmo;
    gizmo.place(*vp->gizmoPivot(), vp->viewCamera(), vp->width(), vp->height());
    ASSERT_TRUE(gizmo.visible());
    const glm::vec2 grab = glm::mix(gizmo.pivotScreen(), gizmo.handleEnd(0), 0.7f);
    const glm::vec2 dir = glm::normalize(gizmo.handleEnd(0) - gizmo.pivotScreen());
    const QPoint start(int(grab.x), int(grab.y));
    QTest::mousePress(vp, Qt::LeftButton, {}, start);
    for (int i = 1; i <= 5; ++i)
        QTest::mouseMove(vp, start + QPoint(int(dir.x * 12.0f * float(i)), int(dir.y * 12.0f * float(i))));
    QTest::mouseRelease(vp, Qt::LeftButton, {}, start + QPoint(int(dir.x * 60.0f), int(dir.y * 60.0f)));
    const auto after = w.doc().scene().objects[0].transform;
    EXPECT_GT(after.translation.x, before.translation.x + 1e-3f);
    EXPECT_FLOAT_EQ(after.translation.y, before.translation.y);
    EXPECT_EQ(w.doc().undoStack()->count(), 1);
    w.doc().undoStack()->undo();
    EXPECT_EQ(w.doc().scene().objects[0].transform, before);
}

TEST(EditorGui, CreateDeleteDuplicateAreUndoable) {
    OpenWindow w;
    Document& doc = w.doc();
    const auto original = doc.project();
    w.window.createPrimitive("sphere");
    ASSERT_EQ(doc.scene().objects.size(), original.scene.objects.size() + 1);
    EXPECT_EQ(doc.scene().meshes.size(), original.scene.meshes.size() + 1);
    EXPECT_TRUE(doc.selection().isObject());
    w.window.outliner()->duplicateSelected();
    EXPECT_EQ(doc.scene().objects.size(), original.scene.objects.size() + 2);
    w.window.outliner()->deleteSelected();
    EXPECT_EQ(doc.scene().objects.size(), original.scene.objects.size() + 1);
    w.window.createLight(lpv::scene::LightType::Spot);
    EXPECT_EQ(doc.scene().lights.size(), original.scene.lights.size() + 1);
    upToDateFrame(w.window.viewport()); // the viewport draws the new scene
    EXPECT_TRUE(w.window.viewport()->lastError().isEmpty()) << w.window.viewport()->lastError().toStdString();
    while (doc.undoStack()->canUndo())
        doc.undoStack()->undo();
    EXPECT_EQ(doc.project(), original);
    while (doc.undoStack()->canRedo())
        doc.undoStack()->redo();
    EXPECT_EQ(doc.scene().objects.size(), original.scene.objects.size() + 1);
}

TEST(EditorGui, Import4dsThroughTheImportActionIsOneUndoStep) {
    OpenWindow w;
    lpv::scene::Project untitled;
    untitled.name = "untitled";
    w.window.showProject(untitled, {}); // File > New
    Document& doc = w.doc();
    const std::size_t objects = doc.scene().objects.size();
    w.window.importFile(QString(lpv::test::kSharedScenesDir) + "/4ds/white_box.4ds", false);
    EXPECT_TRUE(w.window.importRunning());
    LPV_WAIT_UNTIL(!w.window.importRunning(), 60000);
    EXPECT_GT(doc.scene().objects.size(), objects) << w.window.statusBar()->currentMessage().toStdString();
    EXPECT_TRUE(w.window.statusBar()->currentMessage().contains("Imported")) <<
        w.window.statusBar()->currentMessage().toStdString();
    LPV_WAIT_UNTIL(!w.window.viewport()->texturesPending(), 60000);
    QTest::qWait(100);
    EXPECT_GT(litFraction(upToDateFrame(w.window.viewport())), 0.05);
    EXPECT_EQ(doc.undoStack()->text(doc.undoStack()->index() - 1), "Import white_box.4ds");
    EXPECT_EQ(doc.scene().lights.size(), 1u) << "an unlit import gets a sun, as with lpv import";
    doc.undoStack()->undo();
    EXPECT_EQ(doc.scene().objects.size(), objects);
    EXPECT_TRUE(doc.scene().lights.empty());
}

TEST(EditorGui, FailedImportShowsTheImportersErrorAndChangesNothing) {
    OpenWindow w;
    const auto before = w.doc().project();
    QTemporaryDir dir;
    const QString bad = dir.filePath("broken.4ds");
    QFile f(bad);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write("4DS\0garbage", 11);
    f.close();
    w.window.importFile(bad, false);
    LPV_WAIT_UNTIL(!w.window.importRunning(), 30000);
    EXPECT_TRUE(w.window.statusBar()->currentMessage().contains("broken.4ds"))
        << w.window.statusBar()->currentMessage().toStdString();
    EXPECT_EQ(w.doc().project(), before);
    EXPECT_EQ(w.doc().undoStack()->count(), 0);
}

TEST(EditorGui, AutosaveIsOfferedBackAfterACrash) {
    test::TemporaryAutosaveRoot autosaveRoot;
    {
        MainWindow window;
        ASSERT_TRUE(window.openProject(cornellPath(), false));
        window.document()->setParameter("lpv.propagationSteps", 12);
        window.autosave()->saveNow();
        window.autosave()->waitForSave();
        // No close: as if the editor crashed here.
    }
    const auto left = Autosave::leftBehind();
    ASSERT_EQ(left.size(), 1u);
    EXPECT_EQ(left[0].originalPath, QFileInfo(cornellPath()).absoluteFilePath());
    auto recovered = lpv::scene::loadProject(left[0].autosaveFile.toStdString());
    ASSERT_TRUE(recovered);
    EXPECT_EQ(recovered->parameters.getInt("lpv.propagationSteps"), 12);
    Autosave::remove(left[0]);
    EXPECT_TRUE(Autosave::leftBehind().empty());
}

TEST(EditorGui, ReducedViewportResolutionStillFillsTheView) {
    OpenWindow w;
    Viewport* vp = w.window.viewport();
    vp->setResolutionScale(0.5);
    QTest::qWait(100);
    const QImage frame = upToDateFrame(vp);
    EXPECT_EQ(frame.width(), int(vp->width() * vp->devicePixelRatio()));
    EXPECT_GT(litFraction(frame), 0.15);
    // The right-hand quarter is drawn too (the half-size image is scaled up, not put in a corner).
    EXPECT_GT(litFraction(frame.copy(frame.width() * 3 / 4, 0, frame.width() / 4, frame.height())), 0.05);
    vp->setResolutionScale(1.0);
}

TEST(EditorGui, ClosingWithUnsavedChangesAsksAndCancelKeepsTheWindow) {
    OpenWindow w;
    w.doc().setParameter("lpv.propagationSteps", 20);
    w.window.setUnsavedChangesAnswerForTests(QMessageBox::Cancel);
    EXPECT_FALSE(w.window.close());
    EXPECT_TRUE(w.window.isVisible());
    EXPECT_EQ(w.doc().parameters().getInt("lpv.propagationSteps"), 20);
    w.window.setUnsavedChangesAnswerForTests(QMessageBox::Discard);
    EXPECT_TRUE(w.window.close());
}

TEST(EditorGui, EffectsPanelExplainsAndOverrides) {
    OpenWindow w;
    // The dock shares its place with the inspector: bring it up, and let the
    // scene analysis that follows opening a project (250 ms later) run.
    w.window.dock("effects")->raise();
    QTest::qWait(400);
    ASSERT_TRUE(w.window.effects()->isVisible());
    const auto& decisions = w.window.effects()->decisions();
    ASSERT_GE(decisions.size(), 6u);
    // The Cornell box's lamp is an area light: injected through its own RSM, so the LPV runs.
    EXPECT_TRUE(decisions.front().runs()) << decisions.front().reason;
    EXPECT_NE(decisions.front().reason.find("area lights light the scene"), std::string::npos)
        << decisions.front().reason;
    QTableWidget* table = w.window.effects()->table();
    int row = -1;
    for (int r = 0; r < table->rowCount(); ++r)
        if (table->item(r, 0)->text() == "Subsurface LPV")
            row = r;
    ASSERT_GE(row, 0);
    auto* combo = qobject_cast<QComboBox*>(table->cellWidget(row, 1));
    ASSERT_NE(combo, nullptr);
    combo->setCurrentText("on");
    EXPECT_EQ(w.doc().parameters().getEnum("effects.subsurface"), "on");
    // Forced on, but the subsurface LPV is injected from the sun's RSM, and without a sun there is none.
    const auto& forced = w.window.effects()->decisions()[std::size_t(row)];
    EXPECT_NE(forced.reason.find("forced on by effects.subsurface"), std::string::npos) << forced.reason;
    EXPECT_NE(forced.reason.find("no directional light lights the scene"), std::string::npos) << forced.reason;
    EXPECT_FALSE(forced.runs());
    w.doc().undoStack()->undo();
    EXPECT_EQ(w.doc().parameters().getEnum("effects.subsurface"), "auto");
}

TEST(EditorGui, CameraPathFromTheViewPlaysBackAndUndoes) {
    OpenWindow w;
    Document& doc = w.doc();
    CameraPathPanel* panel = w.window.cameraPaths();
    Viewport* vp = w.window.viewport();
    const lpv::scene::Camera start = vp->viewCamera();
    panel->addKeyFromView(); // creates "path 1" with a key at 0 s
    ASSERT_EQ(doc.scene().cameraPaths.size(), 1u);
    lpv::scene::Camera moved = start;
    moved.position += glm::vec3(1.0f, 0.0f, 0.0f);
    moved.target += glm::vec3(1.0f, 0.0f, 0.0f);
    vp->setViewCamera(moved);
    panel->addKeyFromView(); // one second later
    const auto& path = doc.scene().cameraPaths[0];
    ASSERT_EQ(path.keyframes.size(), 2u);
    EXPECT_FLOAT_EQ(path.keyframes[1].time, 1.0f);
    EXPECT_EQ(vp->shownPath(), 0);
    // Scrubbing drives the viewport camera along the path.
    panel->setTime(0.0);
    EXPECT_NEAR(glm::length(vp->viewCamera().position - start.position), 0.0f, 1e-4f);
    panel->setTime(0.5);
    EXPECT_NEAR(vp->viewCamera().position.x, start.position.x + 0.5f, 0.05f);
    doc.undoStack()->undo();
    EXPECT_EQ(doc.scene().cameraPaths[0].keyframes.size(), 1u);
    doc.undoStack()->undo();
    EXPECT_TRUE(doc.scene().cameraPaths.empty());
}

TEST(EditorGui, VideoExportFromTheEditorAndCancelLeavesNothing) {
    OpenWindow w;
    Document& doc = w.doc();
    CameraPathPanel* panel = w.window.cameraPaths();
    panel->addKeyFromView();
    lpv::scene::Camera moved = w.window.viewport()->viewCamera();
    moved.position += glm::vec3(0.5f, 0.0f, 0.0f);
    w.window.viewport()->setViewCamera(moved);
    panel->addKeyFromView();
    QTemporaryDir dir;
    VideoExportDialog dialog(&doc, 0, &w.window);
    dialog.outputField()->setText(dir.filePath("path.mp4"));
    dialog.widthField()->setValue(96);
    dialog.heightField()->setValue(64);
    dialog.fpsField()->setValue(10.0);
    EXPECT_EQ(dialog.run(), QString());
    EXPECT_GT(QFileInfo(dir.filePath("path.mp4")).size(), 0);

    VideoExportDialog cancelled(&doc, 0, &w.window);
    cancelled.outputField()->setText(dir.filePath("cancelled.mp4"));
    cancelled.widthField()->setValue(96);
    cancelled.heightField()->setValue(64);
    cancelled.fpsField()->setValue(10.0);
    cancelled.setCancelAfterFramesForTests(3);
    EXPECT_EQ(cancelled.run(), "cancelled");
    EXPECT_FALSE(QFileInfo::exists(dir.filePath("cancelled.mp4")));
    EXPECT_EQ(QDir(dir.path()).entryList(QDir::Files).size(), 1) << "no temporary file left";
}

// Saving collects texture copies no material uses (issue #29), but not while
// the undo history could bring the material's texture back.
TEST(EditorGui, UndoAfterSaveStillFindsTheRemovedTexture) {
    QTemporaryDir dir;
    const QString texture = dir.filePath("brick.png");
    {
        QImage image(4, 4, QImage::Format_RGB32);
        image.fill(Qt::red);
        ASSERT_TRUE(image.save(texture));
    }
    lpv::scene::Project project;
    project.name = "textured";
    lpv::scene::Material m;
    m.name = "brick";
    m.diffuseTexture = texture.toStdString();
    project.scene.materials.push_back(m);
    Document doc;
    doc.reset(project, QString());
    const QString file = dir.filePath("p.lpvproj");
    ASSERT_TRUE(doc.saveAs(file).has_value());
    // Opened again, the material names the project's own copy.
    auto saved = lpv::scene::loadProject(file.toStdString());
    ASSERT_TRUE(saved.has_value()) << saved.error().describe();
    doc.reset(*saved, file);
    const std::string copy = doc.scene().materials[0].diffuseTexture;
    ASSERT_NE(copy, texture.toStdString());
    ASSERT_TRUE(QFileInfo::exists(QString::fromStdString(copy))) << copy;

    lpv::scene::Material without = doc.scene().materials[0];
    without.diffuseTexture.clear();
    doc.setMaterial(0, without, "Remove texture");
    ASSERT_TRUE(doc.saveAs(file).has_value());
    EXPECT_TRUE(QFileInfo::exists(QString::fromStdString(copy))) << "kept: an undo brings it back";
    doc.undoStack()->undo();
    EXPECT_EQ(doc.scene().materials[0].diffuseTexture, copy);
    ASSERT_TRUE(doc.saveAs(file).has_value());
    EXPECT_TRUE(QFileInfo::exists(QString::fromStdString(copy)));

    // With nothing to undo, a save collects what no material names.
    doc.undoStack()->clear();
    doc.setMaterial(0, without, "Remove texture");
    doc.undoStack()->clear();
    ASSERT_TRUE(doc.saveAs(file).has_value());
    EXPECT_FALSE(QFileInfo::exists(QString::fromStdString(copy))) << "an orphan with no undo to need it";
}

// "GI on/off" is one control (issue #22): the toolbar toggle sets gi.method, one undo step.
TEST(EditorGui, GiToggleIsOneUndoableParameterEdit) {
    OpenWindow w;
    auto* gi = w.window.findChild<QAction*>("giToggle");
    ASSERT_NE(gi, nullptr);
    EXPECT_TRUE(gi->isChecked()) << "GI is on by default";
    gi->trigger();
    EXPECT_EQ(w.doc().parameters().getEnum("gi.method"), "off");
    EXPECT_FALSE(gi->isChecked());
    w.doc().undoStack()->undo();
    EXPECT_EQ(w.doc().parameters().getEnum("gi.method"), "lpv");
    EXPECT_TRUE(gi->isChecked()) << "the toggle follows undo";
}
