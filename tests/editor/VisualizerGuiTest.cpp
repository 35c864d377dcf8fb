// The Visualizers dock in the real window under xvfb (llvmpipe): closed it
// asks nothing of the renderer; open it shows the slice and follows the slice
// and step controls; its picture is the one `lpv dump` would write.
#include "FrontSun.h"
#include "Autosave.h"
#include "Document.h"
#include "MainWindow.h"
#include "TestPaths.h"
#include "Viewport.h"
#include "VisualizerPanel.h"

#include "lpv/renderer/viz/LpvViews.h"
#include "TestWindow.h"

#include <QCheckBox>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QMessageBox>
#include <QSlider>
#include <QTemporaryDir>
#include <QTest>

#include <gtest/gtest.h>

#include <functional>

using namespace lpv::editor;

namespace {

bool waitUntil(const std::function<bool()>& done, int ms = 20000) {
    QElapsedTimer clock;
    clock.start();
    while (!done() && clock.elapsed() < ms)
        QTest::qWait(50);
    return done();
}

// The Cornell box with a sun shining in through its open front, small LPV grids for llvmpipe.
struct LitCornell : test::TestWindow {
    LitCornell() {
        EXPECT_TRUE(window.openProject(test::cornellTemplate(), false));
        Document& doc = *window.document();
        doc.setParameter("lpv.gridSize", lpv::scene::ParameterValue(16));
        doc.setParameter("lpv.cascades", lpv::scene::ParameterValue(2));
        doc.setParameter("rsm.tileSize", lpv::scene::ParameterValue(128));
        doc.editScene("add sun", Change::Lights,
                      [](lpv::scene::Scene& s) { s.lights.push_back(lpv::test::cornellFrontSun()); });
        EXPECT_TRUE(show({1280, 900}));
    }
};

} // namespace

TEST(VisualizerGui, ClosedAsksNothingOpenFollowsSliceAndStep) {
    LitCornell w;
    QTest::qWait(200);
    VisualizerPanel* panel = w.window.visualizers();
    ASSERT_NE(panel, nullptr);
    EXPECT_FALSE(w.window.dock("visualizers")->isVisible()) << "hidden by default";
    EXPECT_FALSE(w.window.viewport()->visualizerRequest().active()) << "closed: no read-back";

    w.window.dock("visualizers")->show();
    ASSERT_TRUE(waitUntil([&] { return panel->active() && !panel->image().isNull(); }))
        << panel->status().toStdString();
    ASSERT_TRUE(w.window.viewport()->visualizerRequest().lpv.has_value());
    // The slice carries its world coordinates and scale bar (issue #46), as `lpv dump` draws them.
    {
        const QImage shown = panel->image().convertToFormat(QImage::Format_RGB32);
        const glm::ivec3 label(glm::round(lpv::renderer::viz::kAxisLabelColour * 255.0f));
        int labelPixels = 0;
        for (int y = 0; y < shown.height(); ++y)
            for (int x = 0; x < shown.width(); ++x) {
                const QRgb p = shown.pixel(x, y);
                labelPixels += glm::ivec3(qRed(p), qGreen(p), qBlue(p)) == label ? 1 : 0;
            }
        EXPECT_GT(labelPixels, 100) << "axis coordinates, the scale bar's length and the plane";
    }

    // The overlays draw over the view: cascade boxes and the slice plane on, then off.
    QTest::qWait(100);
    const QImage withOverlays = w.window.viewport()->grabFramebuffer();
    panel->findChild<QCheckBox*>("vizBounds")->setChecked(false);
    panel->findChild<QCheckBox*>("vizPlane")->setChecked(false);
    const QImage without = w.window.viewport()->grabFramebuffer();
    EXPECT_NE(withOverlays, without) << "cascade boxes and the slice plane must show in the view";
    panel->findChild<QCheckBox*>("vizBounds")->setChecked(true);

    // Another slice: another picture, at once (the frame already holds the volume).
    panel->setSlice(3);
    const QImage sliceA = panel->image();
    panel->setSlice(12);
    const QImage sliceB = panel->image();
    ASSERT_FALSE(sliceA.isNull());
    ASSERT_FALSE(sliceB.isNull());
    EXPECT_NE(sliceA, sliceB) << panel->status().toStdString();
    EXPECT_NE(panel->status().indexOf("z = 12"), -1) << panel->status().toStdString();

    // Step 0 (injection only) and the last step accumulate different light; each needs a new frame.
    panel->setStep(0);
    ASSERT_TRUE(waitUntil([&] { return panel->status().contains("step 0/"); }))
        << panel->status().toStdString();
    const QImage first = panel->image();
    const int steps = w.window.document()->parameters().getInt("lpv.propagationSteps");
    panel->setStep(steps);
    ASSERT_TRUE(waitUntil([&] { return panel->status().contains(QString("step %1/").arg(steps)); }));
    EXPECT_NE(first, panel->image());

    // Live: a parameter edit re-renders, and the panel's step range follows it.
    w.window.document()->setParameter("lpv.propagationSteps", lpv::scene::ParameterValue(3));
    ASSERT_TRUE(waitUntil([&] { return panel->status().contains("step 3/3"); }))
        << panel->status().toStdString();

    // The RSM view shows tiles.
    panel->setView(VisualizerPanel::View::Rsm);
    ASSERT_TRUE(waitUntil([&] { return !panel->image().isNull() && panel->status().isEmpty(); }));
    EXPECT_TRUE(w.window.viewport()->visualizerRequest().rsm);

    w.window.dock("visualizers")->hide();
    ASSERT_TRUE(waitUntil([&] { return !panel->active(); }));
    EXPECT_FALSE(w.window.viewport()->visualizerRequest().active()) << "closed again: nothing read back";
}
