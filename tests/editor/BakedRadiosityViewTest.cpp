// gi.method = radiosity in the editor's viewport (issue #27 item 1): without
// a solution the log says why and the view has direct light only; a solve in
// the Radiosity dock is shown at once; moving the light makes the solution
// another scene's, and undoing the move shows it again.
#include "Autosave.h"
#include "Document.h"
#include "MainWindow.h"
#include "RadiosityPanel.h"
#include "TestPaths.h"
#include "Viewport.h"

#include "lpv/scene/CornellBox.h"
#include "lpv/scene/Project.h"
#include "WaitUntil.h"
#include "TestWindow.h"

#include <QMessageBox>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

#include <gtest/gtest.h>

using namespace lpv::editor;

namespace {

// Mean grey of the ceiling left of the lamp, which only indirect light reaches.
double ceilingGrey(Viewport* vp) {
    const QImage shown = vp->grab().toImage();
    double sum = 0.0;
    int n = 0;
    for (int y = int(0.06 * shown.height()); y < int(0.11 * shown.height()); ++y)
        for (int x = int(0.3 * shown.width()); x < int(0.4 * shown.width()); ++x, ++n)
            sum += qGray(shown.pixel(x, y));
    return n ? sum / n : 0.0;
}

} // namespace

TEST(BakedRadiosityView, ShowsTheSolutionOrSaysWhyNot) {
    QTemporaryDir projectDir;
    lpv::scene::Project project = lpv::scene::makeCornellBoxProject();
    for (const auto& [key, value] :
         {std::pair{"radiosity.maxPatchArea", "0.5"}, std::pair{"radiosity.convergenceThreshold", "0.1"}})
        ASSERT_TRUE(project.parameters.setFromText(key, value, "test").has_value());
    const QString file = projectDir.filePath("cornell.lpvproj");
    ASSERT_TRUE(lpv::scene::saveProject(project, file.toStdString()).has_value());

    test::TestWindow w;
    ASSERT_TRUE(w.openAndShow(file, {800, 600}));
    MainWindow& window = w.window;
    Viewport* vp = window.viewport();
    std::vector<std::pair<QString, bool>> notes;
    QObject::connect(vp, &Viewport::radiosityNoteChanged,
                     [&](const QString& note, bool failed) { notes.emplace_back(note, failed); });
    auto lastNote = [&] { return notes.empty() ? std::string() : notes.back().first.toStdString(); };

    // No solution yet: said in the log, the frame has direct light only.
    window.document()->setParameter("gi.method", lpv::scene::ParameterValue(std::string("radiosity")));
    LPV_WAIT_UNTIL(!notes.empty() && vp->frameUpToDate(), 60000);
    EXPECT_TRUE(notes.back().second);
    EXPECT_NE(lastNote().find("no radiosity solution is saved"), std::string::npos) << lastNote();
    EXPECT_NE(lastNote().find("direct light only"), std::string::npos) << lastNote();
    EXPECT_LT(ceilingGrey(vp), 3.0) << "nothing lights the ceiling without indirect light";

    // A solve in the dock saves the solution; the view shows it.
    QSignalSpy stopped(window.radiosity(), &RadiosityPanel::stopped);
    window.radiosity()->start();
    ASSERT_TRUE(stopped.wait(120000));
    LPV_WAIT_UNTIL(!notes.back().second && vp->frameUpToDate(), 60000);
    EXPECT_NE(lastNote().find("patches"), std::string::npos) << lastNote();
    EXPECT_GT(ceilingGrey(vp), 10.0) << "the solution lights the ceiling";

    // The light moved: the solution is another scene's; undone: it is shown again.
    lpv::scene::Light light = window.document()->scene().lights.front();
    light.position.x -= 0.5f;
    window.document()->setLight(0, light, "move");
    LPV_WAIT_UNTIL(notes.back().second && vp->frameUpToDate(), 60000);
    EXPECT_NE(lastNote().find("another scene"), std::string::npos) << lastNote();
    window.document()->undoStack()->undo();
    LPV_WAIT_UNTIL(!notes.back().second && vp->frameUpToDate(), 60000);
    EXPECT_GT(ceilingGrey(vp), 10.0);
}
