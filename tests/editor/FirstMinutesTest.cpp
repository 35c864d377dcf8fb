// The editor's first minutes as a newcomer meets them (issue #46): the
// built-in template, the gizmo's pivot, navigation sized to the scene, the
// default layout, the Visualizers dock, the quit prompt and the status bar.
// Through the real window under xvfb, as EditorGuiTest.cpp.
#include "Autosave.h"
#include "CameraController.h"
#include "Document.h"
#include "MainWindow.h"
#include "TestPaths.h"
#include "TransformGizmo.h"
#include "Viewport.h"

#include "lpv/app/BuiltInProjects.h"
#include "lpv/scene/Picking.h"
#include "TestWindow.h"

#include <QAbstractButton>
#include <QAction>
#include <QApplication>
#include <QCryptographicHash>
#include <QDirIterator>
#include <QDockWidget>
#include <QFile>
#include <QFileDialog>
#include <QLabel>
#include <QMessageBox>
#include <QSettings>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QUndoStack>
#include <QWheelEvent>

#include <gtest/gtest.h>

#include <cstdio>
#include <map>

using namespace lpv::editor;

namespace {

QString cornellPath() { return QString(lpv::test::kSourceDir) + "/projects/cornell-box/cornell-box.lpvproj"; }

// Every file under `dir` with a hash of its bytes: what a run wrote there shows as a difference.
std::map<QString, QByteArray> folderContents(const QString& dir) {
    std::map<QString, QByteArray> out;
    QDirIterator it(dir, QDir::Files | QDir::Hidden, QDirIterator::Subdirectories);
    while (it.hasNext()) {
        const QString file = it.next();
        QFile f(file);
        EXPECT_TRUE(f.open(QIODevice::ReadOnly)) << file.toStdString();
        out[file] = QCryptographicHash::hash(f.readAll(), QCryptographicHash::Sha256);
    }
    return out;
}

// A shown window at the size, with the default layout (no saved one)
// and autosaves in a temporary folder.
struct Window {
    QTemporaryDir autosaveDir;
    MainWindow* window = nullptr;
    Window() {
        QSettings().clear(); // a layout saved by an earlier test would replace the default one
        Autosave::setRootForTests(autosaveDir.path());
        window = new MainWindow;
        window->setUnsavedChangesAnswerForTests(QMessageBox::Discard);
        window->resize(1400, 900);
    }
    ~Window() { delete window; }
    void show() {
        window->show();
        EXPECT_TRUE(QTest::qWaitForWindowExposed(window));
        QTest::qWait(200);
    }
    Document& doc() { return *window->document(); }
};

// Answers the next message box with `button` and keeps its text.
struct MessageBoxAnswer {
    QTimer timer;
    QString text;
    explicit MessageBoxAnswer(QMessageBox::StandardButton button) {
        timer.setInterval(20);
        QObject::connect(&timer, &QTimer::timeout, [this, button] {
            for (QWidget* top : QApplication::topLevelWidgets())
                if (auto* box = qobject_cast<QMessageBox*>(top); box && box->isVisible()) {
                    text = box->text();
                    timer.stop();
                    box->button(button)->click();
                    return;
                }
        });
        timer.start();
    }
};

int objectNamed(const lpv::scene::Scene& s, const std::string& name) {
    for (std::size_t i = 0; i < s.objects.size(); ++i)
        if (s.objects[i].name == name)
            return int(i);
    return -1;
}

// One undoable edit, whatever the project holds: the propagation steps one more.
void edit(Document& doc) {
    doc.setParameter("lpv.propagationSteps",
                     lpv::scene::ParameterValue(doc.parameters().getInt("lpv.propagationSteps") + 1));
    EXPECT_TRUE(doc.isModified());
}

bool inside(const lpv::scene::Bounds& b, const glm::vec3& p) {
    return glm::all(glm::greaterThanEqual(p, b.min)) && glm::all(glm::lessThanEqual(p, b.max));
}

void sendWheel(Viewport* vp, const QPoint& at, int notches) {
    QWheelEvent wheel(QPointF(at), vp->mapToGlobal(QPointF(at)), QPoint(), QPoint(0, 120 * notches),
                      Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(vp, &wheel);
}

} // namespace

// `lpvstudio` with no argument edited projects/cornell-box/cornell-box.lpvproj
// itself: a Save wrote into the source (or install) tree.
TEST(FirstMinutes, TemplateOpensAsAnUntitledCopy) {
    const QString templateDir = QFileInfo(cornellPath()).absolutePath();
    const auto before = folderContents(templateDir);
    ASSERT_FALSE(before.empty());
    {
        Window w;
        w.window->openBuiltInTemplate(); // what main() does without an argument
        w.show();
        // ASSERT: were the template the document's file, the Save below would write into it.
        ASSERT_TRUE(w.doc().path().isEmpty())
            << "the template is the document's file: " << w.doc().path().toStdString();
        EXPECT_EQ(w.doc().displayName(), "Untitled");
        EXPECT_TRUE(w.window->windowTitle().startsWith("Untitled")) << w.window->windowTitle().toStdString();
        // The copy has the template's scene, meshes read from its assets folder.
        const auto fromFile = lpv::scene::loadProject(cornellPath().toStdString());
        ASSERT_TRUE(fromFile.has_value());
        EXPECT_EQ(w.doc().scene().meshes.size(), fromFile->scene.meshes.size());
        EXPECT_TRUE(w.doc().scene().meshes == fromFile->scene.meshes);

        edit(w.doc());
        ASSERT_TRUE(w.doc().isModified());
        // Save asks for a path: cancel the file dialog, nothing is saved.
        bool dialogAsked = false;
        QTimer cancel;
        cancel.setInterval(20);
        QObject::connect(&cancel, &QTimer::timeout, [&] {
            for (QWidget* top : QApplication::topLevelWidgets())
                if (auto* dialog = qobject_cast<QFileDialog*>(top); dialog && dialog->isVisible()) {
                    dialogAsked = true;
                    dialog->reject();
                }
        });
        cancel.start();
        EXPECT_FALSE(w.window->save());
        cancel.stop();
        EXPECT_TRUE(dialogAsked) << "Save did not ask where to write an untitled project";
        EXPECT_TRUE(w.doc().isModified());

        // Saved elsewhere, the copy carries its meshes with it.
        QTemporaryDir out;
        const QString copy = out.filePath("mine.lpvproj");
        ASSERT_TRUE(w.window->saveTo(copy, false));
        const auto saved = lpv::scene::loadProject(copy.toStdString());
        ASSERT_TRUE(saved.has_value()) << saved.error().describe();
        EXPECT_TRUE(saved->scene.meshes == fromFile->scene.meshes);
        EXPECT_EQ(w.doc().path(), copy);
    }
    EXPECT_EQ(folderContents(templateDir), before) << "something was written into the template's folder";
}

// The gizmo sat at tallBlock's translation (0,0,0), the box's front-right
// corner, and rotated it about that corner.
TEST(FirstMinutes, GizmoSitsAtTheBoundsCentreAndRotatesAboutIt) {
    Window w;
    ASSERT_TRUE(w.window->openProject(cornellPath(), false));
    w.show();
    Viewport* vp = w.window->viewport();
    const int tall = objectNamed(w.doc().scene(), "tallBlock");
    ASSERT_GE(tall, 0);
    w.doc().select({Selection::Kind::Object, tall});
    const lpv::scene::Bounds bounds = lpv::scene::objectWorldBounds(w.doc().scene(), tall);
    const glm::vec3 centre = bounds.center();
    const glm::vec3 origin = glm::vec3(w.doc().scene().worldMatrix(tall)[3]);
    ASSERT_GT(glm::length(centre - origin), 0.05f * glm::length(bounds.size())) << "the case is not tested";
    const auto pivot = vp->gizmoPivot();
    ASSERT_TRUE(pivot.has_value());
    EXPECT_LT(glm::length(*pivot - centre), 1e-4f * glm::length(bounds.size()))
        << "the gizmo is at (" << pivot->x << ", " << pivot->y << ", " << pivot->z << ")";

    // Rotate about y: drag across the y handle.
    w.window->findChild<QAction*>("pivotBoundsCentre")->trigger();
    vp->setGizmoMode(GizmoMode::Rotate);
    TransformGizmo gizmo; // placed as the viewport places its own
    gizmo.place(*pivot, vp->viewCamera(), vp->width(), vp->height());
    ASSERT_TRUE(gizmo.visible());
    const glm::vec2 grab = glm::mix(gizmo.pivotScreen(), gizmo.handleEnd(1), 0.7f);
    const glm::vec2 along = glm::normalize(gizmo.handleEnd(1) - gizmo.pivotScreen());
    const glm::vec2 across(-along.y, along.x);
    const QPoint start(int(grab.x), int(grab.y));
    const auto before = w.doc().scene().objects[std::size_t(tall)].transform;
    QTest::mousePress(vp, Qt::LeftButton, {}, start);
    for (int i = 1; i <= 6; ++i)
        QTest::mouseMove(vp,
                         start + QPoint(int(across.x * 10.0f * float(i)), int(across.y * 10.0f * float(i))));
    QTest::mouseRelease(vp, Qt::LeftButton, {}, start + QPoint(int(across.x * 60.0f), int(across.y * 60.0f)));
    const auto after = w.doc().scene().objects[std::size_t(tall)].transform;
    EXPECT_LT(std::abs(glm::dot(after.rotation, before.rotation)), 0.999f) << "the drag did not rotate";
    const glm::vec3 centreAfter = lpv::scene::objectWorldBounds(w.doc().scene(), tall).center();
    EXPECT_LT(glm::length(centreAfter - centre), 1e-3f * glm::length(bounds.size()))
        << "the centre moved by " << glm::length(centreAfter - centre);
    EXPECT_EQ(w.doc().undoStack()->count(), 1);
    w.doc().undoStack()->undo();
    EXPECT_EQ(w.doc().scene().objects[std::size_t(tall)].transform, before);

    // Pivot: origin puts the gizmo back at the translation.
    w.window->findChild<QAction*>("pivotOrigin")->trigger();
    ASSERT_TRUE(vp->gizmoPivot().has_value());
    EXPECT_LT(glm::length(*vp->gizmoPivot() - origin), 1e-5f);
}

// On Sponza a 70-pixel orbit swung the camera out of the building, three
// wheel notches crossed the atrium, and nothing led back to the opening view.
TEST(FirstMinutes, NavigationOnSponzaFitsTheScene) {
    QTemporaryDir dir;
    const QString file = dir.filePath("sponza.lpvproj");
    ASSERT_TRUE(test::importWithCli("sponza/sponza.obj", file));

    Window w;
    ASSERT_TRUE(w.window->openProject(file, false));
    w.show();
    Viewport* vp = w.window->viewport();
    vp->setResolutionScale(0.25); // its frames only slow the test down here
    const lpv::scene::Bounds bounds = w.doc().scene().worldBounds();
    const lpv::scene::Camera opening = vp->viewCamera();
    ASSERT_TRUE(inside(bounds, opening.position)) << "Sponza opens inside the building";

    // One wheel notch over the nearest surface in view (a pillar, the floor
    // at the bottom): a fraction of the way to it, not a fixed stride through it.
    const QPoint centre(vp->width() / 2, vp->height() / 2);
    auto depthAt = [&](const lpv::scene::Camera& camera, const QPoint& at) {
        const auto ray = lpv::scene::cameraRay(camera, float(at.x()) + 0.5f, float(at.y()) + 0.5f,
                                               vp->width(), vp->height());
        const auto hit = lpv::scene::pickObject(w.doc().scene(), ray.origin, ray.direction);
        return hit ? hit->distance : -1.0f;
    };
    QPoint nearest;
    float surface = 0.0f;
    for (int y = 1; y < 8; ++y)
        for (int x = 1; x < 8; ++x) {
            const QPoint at(vp->width() * x / 8, vp->height() * y / 8);
            const float d = depthAt(opening, at);
            if (d > 0.0f && (surface == 0.0f || d < surface)) {
                surface = d;
                nearest = at;
            }
        }
    ASSERT_GT(surface, 0.0f) << "nothing in view";
    {
        // What a notch did before: 15% of the way to the target, wherever the cursor was.
        const float target = glm::length(opening.target - opening.position);
        std::printf(
            "FirstMinutes: nearest surface %.2f m away; a notch used to move %.2f m (target %.2f m)\n",
            double(surface), double(0.15f * target), double(target));
    }
    sendWheel(vp, nearest, 1);
    const float moved = glm::length(vp->viewCamera().position - opening.position);
    std::printf("FirstMinutes: a notch now moves %.2f m\n", double(moved));
    EXPECT_GT(moved, 0.05f * surface);
    EXPECT_LE(moved, 0.25f * surface);
    sendWheel(vp, nearest, 2);
    const float afterThree = glm::length(vp->viewCamera().position - opening.position);
    EXPECT_LT(afterThree, 0.6f * surface) << "three notches went " << afterThree << " m of " << surface;
    EXPECT_TRUE(inside(bounds, vp->viewCamera().position));
    EXPECT_GT(depthAt(vp->viewCamera(), nearest), 0.3f * surface)
        << "the surface under the cursor is still ahead";
    // Back out: the same notches return to the opening view.
    sendWheel(vp, nearest, -3);
    EXPECT_LT(glm::length(vp->viewCamera().position - opening.position), 1e-3f * surface);

    // A middle drag over that surface: it follows the mouse (the pan was sized at the far target).
    vp->homeView();
    const auto grabbedRay = lpv::scene::cameraRay(opening, float(nearest.x()) + 0.5f,
                                                  float(nearest.y()) + 0.5f, vp->width(), vp->height());
    const glm::vec3 grabbed = grabbedRay.origin + grabbedRay.direction * surface;
    const QPoint to = nearest + QPoint(40, 0);
    QTest::mousePress(vp, Qt::MiddleButton, {}, nearest);
    for (int i = 1; i <= 4; ++i)
        QTest::mouseMove(vp, nearest + QPoint(10 * i, 0));
    QTest::mouseRelease(vp, Qt::MiddleButton, {}, to);
    {
        const lpv::scene::Camera& c = vp->viewCamera();
        const glm::vec4 clip =
            c.projection(float(vp->width()) / float(vp->height())) * c.view() * glm::vec4(grabbed, 1.0f);
        const glm::vec2 shown((clip.x / clip.w * 0.5f + 0.5f) * float(vp->width()),
                              (0.5f - clip.y / clip.w * 0.5f) * float(vp->height()));
        std::printf("FirstMinutes: the grabbed point is %.1f px from the cursor after a 40 px pan\n",
                    double(glm::length(shown - glm::vec2(float(to.x()), float(to.y())))));
        EXPECT_LT(glm::length(shown - glm::vec2(float(to.x()), float(to.y()))), 4.0f)
            << "the grabbed surface did not follow the mouse";
    }

    // A 70-pixel orbit stays in the building.
    vp->homeView();
    QTest::mousePress(vp, Qt::LeftButton, {}, centre);
    for (int i = 1; i <= 7; ++i)
        QTest::mouseMove(vp, centre + QPoint(10 * i, 0));
    QTest::mouseRelease(vp, Qt::LeftButton, {}, centre + QPoint(70, 0));
    const glm::vec3 eye = vp->viewCamera().position;
    {
        CameraController old; // about the target, as before
        old.setCamera(opening);
        old.orbitAround(opening.target, 70.0f, 0.0f);
        std::printf("FirstMinutes: a 70 px orbit moved the eye %.2f m (before: %.2f m, %s the building)\n",
                    double(glm::length(eye - opening.position)),
                    double(glm::length(old.camera().position - opening.position)),
                    inside(bounds, old.camera().position) ? "inside" : "outside");
    }
    EXPECT_NE(eye, opening.position) << "the drag did not orbit";
    EXPECT_TRUE(inside(bounds, eye)) << "a 70 px orbit took the eye out of the building";

    // Home (the View menu's action, the Home key) goes back to the opening view.
    QAction* home = w.window->findChild<QAction*>("homeView");
    ASSERT_NE(home, nullptr);
    EXPECT_EQ(home->shortcut(), QKeySequence(Qt::Key_Home));
    home->trigger();
    EXPECT_EQ(vp->viewCamera().position, opening.position);
    EXPECT_EQ(vp->viewCamera().target, opening.target);
    sendWheel(vp, centre, 2);
    vp->setFocus();
    QTest::keyClick(vp, Qt::Key_Home);
    EXPECT_EQ(vp->viewCamera().position, opening.position);
}

// With the default layout the Profiler's chart and table took about a third of a 900 px window.
TEST(FirstMinutes, ViewportDominatesTheDefaultLayout) {
    Window w;
    ASSERT_TRUE(w.window->openProject(cornellPath(), false));
    w.show();
    const int viewport = w.window->viewport()->height();
    const int profiler = w.window->dock("profiler")->height();
    std::printf("FirstMinutes: window %dx%d, viewport %dx%d, profiler dock %d px high\n", w.window->width(),
                w.window->height(), w.window->viewport()->width(), viewport, profiler);
    EXPECT_GE(double(viewport) / double(w.window->height()), 0.6);
    EXPECT_LE(double(profiler) / double(w.window->height()), 0.2);

    // View > Reset layout brings the same back after the strip was dragged taller.
    w.window->resizeDocks({w.window->dock("profiler")}, {450}, Qt::Vertical);
    QTest::qWait(100);
    ASSERT_LT(double(w.window->viewport()->height()) / double(w.window->height()), 0.6) << "not dragged";
    w.window->findChild<QAction*>("resetLayout")->trigger();
    QTest::qWait(200);
    EXPECT_GE(double(w.window->viewport()->height()) / double(w.window->height()), 0.6) << "after Reset layout";
}

// View > Visualizers opened the dock about 60 px tall under the Inspector, two controls visible.
TEST(FirstMinutes, VisualizersDockOpensAtAUsableHeight) {
    Window w;
    ASSERT_TRUE(w.window->openProject(cornellPath(), false));
    w.show();
    QDockWidget* viz = w.window->dock("visualizers");
    ASSERT_FALSE(viz->isVisible());
    viz->toggleViewAction()->trigger(); // View > Visualizers
    QTest::qWait(300);
    ASSERT_TRUE(viz->isVisible());
    std::printf("FirstMinutes: Visualizers dock %dx%d in a %d px window\n", viz->width(), viz->height(),
                w.window->height());
    EXPECT_GE(viz->height(), w.window->height() / 2);
    EXPECT_FALSE(viz->visibleRegion().isEmpty()) << "the dock is shown but covered";
    EXPECT_LE(w.window->height(), 900);
}

// The quit prompt said "untitled - LPV Studio has unsaved changes" (the window title).
TEST(FirstMinutes, QuitPromptNamesTheProject) {
    Window w;
    w.window->openBuiltInTemplate();
    w.show();
    edit(w.doc());
    w.window->setUnsavedChangesAnswerForTests(0); // the real question
    {
        MessageBoxAnswer answer(QMessageBox::Cancel);
        EXPECT_FALSE(w.window->close());
        EXPECT_EQ(answer.text.toStdString(), "Untitled has unsaved changes. Save them?");
    }
    w.window->setUnsavedChangesAnswerForTests(QMessageBox::Discard);
    ASSERT_TRUE(w.window->openProject(cornellPath(), false));
    edit(w.doc());
    w.window->setUnsavedChangesAnswerForTests(0);
    {
        MessageBoxAnswer answer(QMessageBox::Cancel);
        EXPECT_FALSE(w.window->close());
        EXPECT_EQ(answer.text.toStdString(), "cornell-box has unsaved changes. Save them?");
    }
    w.window->setUnsavedChangesAnswerForTests(QMessageBox::Discard);
}

// A long message ran into the GPU-time field and its end (an error's cause) was cut off.
TEST(FirstMinutes, LongStatusMessagesAreElidedWithTheWholeTextInATooltip) {
    Window w;
    ASSERT_TRUE(w.window->openProject(cornellPath(), false));
    w.show();
    const QString message =
        "Render error: " + QString("a long reason, ").repeated(30) + "and the cause at the end";
    w.window->statusBar()->showMessage(message);
    QTest::qWait(100);
    auto* label = w.window->statusBar()->findChild<QLabel*>("statusMessage");
    ASSERT_NE(label, nullptr) << "the status bar has no message field of its own";
    EXPECT_EQ(label->toolTip(), message);
    EXPECT_NE(label->text(), message);
    EXPECT_TRUE(label->text().endsWith(QChar(0x2026))) << label->text().toStdString();
    EXPECT_LE(label->fontMetrics().horizontalAdvance(label->text()), label->contentsRect().width());
    // Clear of every other field of the bar.
    for (QWidget* field : w.window->statusBar()->findChildren<QWidget*>(Qt::FindDirectChildrenOnly)) {
        if (field != label && field->isVisible() && field->width() > 0) {
            EXPECT_FALSE(label->geometry().intersects(field->geometry()))
                << field->metaObject()->className() << " " << field->objectName().toStdString();
        }
    }
    w.window->statusBar()->clearMessage();
    EXPECT_TRUE(label->text().isEmpty());
}

// Flying slows near a wall: at most the distance ahead per second, at least 1% of the scene.
TEST(FirstMinutes, FlySlowsDownNearASurface) {
    CameraController c;
    lpv::scene::Bounds b;
    b.extend(glm::vec3(-20.0f, 0.0f, -5.0f));
    b.extend(glm::vec3(20.0f, 15.0f, 5.0f)); // Sponza's size
    c.setSceneBounds(b);
    lpv::scene::Camera camera;
    camera.position = glm::vec3(0.0f, 2.0f, 0.0f);
    camera.target = glm::vec3(1.0f, 2.0f, 0.0f);
    c.setCamera(camera);
    c.fly(glm::vec3(0.0f, 0.0f, 1.0f), 0.1f, false, 30.0f); // a long nave ahead: full speed
    EXPECT_NEAR(c.camera().position.x, 0.1f * c.flySpeed(), 1e-4f);
    c.setCamera(camera);
    c.fly(glm::vec3(0.0f, 0.0f, 1.0f), 0.1f, false, 2.0f); // a pillar 2 m ahead
    EXPECT_NEAR(c.camera().position.x, 0.2f, 1e-4f);
    c.setCamera(camera);
    c.fly(glm::vec3(0.0f, 0.0f, 1.0f), 0.1f, false, 0.0001f); // against it: still moves, slowly
    EXPECT_NEAR(c.camera().position.x, 0.1f * 0.01f * c.sceneSize(), 1e-5f);
}
