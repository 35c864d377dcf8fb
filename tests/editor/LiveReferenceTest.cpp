// gi.method = reference in the editor (issue #26 item 2): the view shows the
// path tracer's image, its samples add up while nothing changes, a camera
// move starts it again, and leaving reference stops it. It is shown through
// the frame's exposure and tonemapper (issue #43), `--preview`'s mapping
// being an option of the Accuracy dock.
#include "AccuracyPanel.h"
#include "Autosave.h"
#include "Document.h"
#include "MainWindow.h"
#include "TestPaths.h"
#include "Viewport.h"
#include "WaitUntil.h"
#include "TestWindow.h"

#include <QComboBox>
#include <QLabel>
#include <QMessageBox>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <gtest/gtest.h>

using namespace lpv::editor;

namespace {
} // namespace

TEST(LiveReference, SamplesAddUpRestartOnAMoveAndStopWithAnotherMethod) {
    test::TestWindow w;
    ASSERT_TRUE(w.openAndShow(test::cornellTemplate(), {800, 600}));
    MainWindow& window = w.window;
    Viewport* vp = window.viewport();
    std::vector<int> spp;
    QObject::connect(vp, &Viewport::referenceProgress, [&](int s, double, double) { spp.push_back(s); });

    window.document()->setParameter("gi.method", lpv::scene::ParameterValue(std::string("reference")));
    LPV_WAIT_UNTIL(!spp.empty() && spp.back() >= 3, 60000);
    for (std::size_t i = 1; i < spp.size(); ++i)
        EXPECT_EQ(spp[i], spp[i - 1] + 1) << "one pass at a time, none lost";
    EXPECT_TRUE(window.referenceLabel()->text().contains("spp")) << window.referenceLabel()->text().toStdString();
    // The view shows it: the Cornell box is lit, not black.
    const QImage shown = vp->grab().toImage();
    double sum = 0.0;
    for (int y = 0; y < shown.height(); y += 8)
        for (int x = 0; x < shown.width(); x += 8)
            sum += qGray(shown.pixel(x, y));
    EXPECT_GT(sum / double((shown.height() / 8) * (shown.width() / 8)), 20.0);

    // Mapped as a frame of these parameters would be; the preview's mapping on request.
    ASSERT_TRUE(vp->referenceLinear());
    const lpv::scene::ParameterSet& params = window.document()->parameters();
    const QImage framed = displayReference(*vp->referenceLinear(), ReferenceMapping::FrameTonemap, params);
    EXPECT_EQ(vp->referenceDisplay(), framed);
    const lpv::editor::LinearImage& linear = *vp->referenceLinear();
    const DisplayMapping mapping = meteredMapping(linear.pixels, params);
    const std::size_t middle =
        std::size_t(linear.height / 2) * std::size_t(linear.width) + std::size_t(linear.width / 2);
    const glm::vec3 expected = mapToDisplay(linear.pixels[middle], mapping);
    EXPECT_NEAR(qRed(framed.pixel(linear.width / 2, linear.height / 2)), expected.r * 255.0, 1.0);
    window.accuracy()->mappingBox()->setCurrentIndex(1);
    const QImage preview = displayReference(*vp->referenceLinear(), ReferenceMapping::Preview, params);
    EXPECT_EQ(vp->referenceDisplay(), preview);
    EXPECT_NE(preview, framed);
    window.accuracy()->mappingBox()->setCurrentIndex(0);
    EXPECT_EQ(vp->referenceDisplay(), framed);

    // A camera move starts again from one sample.
    lpv::scene::Camera moved = vp->viewCamera();
    moved.position += glm::vec3(0.3f, 0.1f, 0.2f);
    spp.clear();
    vp->setViewCamera(moved);
    LPV_WAIT_UNTIL(!spp.empty(), 60000);
    EXPECT_EQ(spp.front(), 1);

    // Another method stops it and clears the status bar.
    window.document()->setParameter("gi.method", lpv::scene::ParameterValue(std::string("lpv")));
    LPV_WAIT_UNTIL(window.referenceLabel()->text().isEmpty(), 10000);
    spp.clear();
    QTest::qWait(1500);
    EXPECT_TRUE(spp.empty()) << "no pass after it stopped";
}

// An empty project (nothing to see) neither crashes the live reference nor
// leaves it stuck: it traces, and moves restart it.
TEST(LiveReference, AnEmptyProjectAndMovesDoNotBreakIt) {
    test::TestWindow w;
    MainWindow& window = w.window;
    lpv::scene::Project empty;
    empty.name = "untitled";
    window.showProject(empty, {});
    ASSERT_TRUE(w.show({640, 480}));
    Viewport* vp = window.viewport();
    int passes = 0, failures = 0;
    QObject::connect(vp, &Viewport::referenceProgress, [&](int s, double, double) { passes += s > 0; });
    QObject::connect(vp, &Viewport::renderFailed, [&](const QString&) { ++failures; });
    window.document()->setParameter("gi.method", lpv::scene::ParameterValue(std::string("reference")));
    LPV_WAIT_UNTIL(passes > 0 || failures > 0, 30000);
    for (int i = 0; i < 3; ++i) {
        lpv::scene::Camera moved = vp->viewCamera();
        moved.position += glm::vec3(0.5f, 0.0f, 0.0f);
        const int before = passes + failures;
        vp->setViewCamera(moved);
        LPV_WAIT_UNTIL(passes + failures > before, 30000);
    }
}
