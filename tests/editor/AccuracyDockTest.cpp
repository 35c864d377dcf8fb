// The Accuracy dock (issue #26 item 3) on the built-in Cornell box: tracing
// a reference of the view gives finite figures that change as samples add up
// while the reference's noise falls; a renderer setting leaves the
// reference converging; the heat map lies over the view and goes again; the
// LPV | reference split shows the reference on its right half.
#include "AccuracyPanel.h"
#include "Autosave.h"
#include "Document.h"
#include "MainWindow.h"
#include "TestPaths.h"
#include "Viewport.h"

#include <QCheckBox>
#include <QMessageBox>
#include <QTemporaryDir>
#include <QTest>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

using namespace lpv::editor;

namespace {

QString cornell() {
    return QString(lpv::test::kSourceDir) + "/projects/cornell-box/cornell-box.lpvproj";
}

// A window on the Cornell box, its viewport small (the reference traces at its size).
struct Fixture {
    QTemporaryDir autosaveDir;
    std::unique_ptr<MainWindow> window;
    std::vector<std::shared_ptr<const AccuracySample>> samples;

    bool open() {
        Autosave::setRootForTests(autosaveDir.path());
        window = std::make_unique<MainWindow>();
        window->setUnsavedChangesAnswerForTests(QMessageBox::Discard);
        if (!window->openProject(cornell(), false))
            return false;
        window->resize(700, 560);
        window->viewport()->setResolutionScale(1.0); // frames at the widget's size, whatever QSettings held
        window->show();
        if (!QTest::qWaitForWindowExposed(window.get()))
            return false;
        QObject::connect(
            window->accuracy()->monitor(), &AccuracyMonitor::measured,
            [this](std::shared_ptr<const AccuracySample> s) { samples.push_back(std::move(s)); });
        return true;
    }
};

// Pixels (sampled) where two images differ by more than `tolerance` in any channel, over a region.
int differingPixels(const QImage& a, const QImage& b, const QRect& region, int tolerance) {
    int count = 0;
    for (int y = region.top(); y <= region.bottom(); y += 2)
        for (int x = region.left(); x <= region.right(); x += 2) {
            const QRgb p = a.pixel(x, y), q = b.pixel(x, y);
            if (std::abs(qRed(p) - qRed(q)) > tolerance || std::abs(qGreen(p) - qGreen(q)) > tolerance ||
                std::abs(qBlue(p) - qBlue(q)) > tolerance)
                ++count;
        }
    return count;
}

} // namespace

TEST(AccuracyDock, FiguresChangeAsTheReferenceConvergesAndItsNoiseFalls) {
    Fixture f;
    ASSERT_TRUE(f.open());
    AccuracyPanel* panel = f.window->accuracy();
    panel->traceBox()->setChecked(true);
    // From 2 samples on: one sample has no variance, so no noise figure yet.
    QTRY_VERIFY_WITH_TIMEOUT(!f.samples.empty() && f.samples.back()->samplesPerPixel >= 2, 60000);
    const auto first = f.samples.back();
    QTRY_VERIFY_WITH_TIMEOUT(f.samples.back()->samplesPerPixel >= first->samplesPerPixel + 3, 60000);
    const auto last = f.samples.back();
    for (const auto& s : {first, last}) {
        const lpv::reference::Accuracy& a = s->accuracy;
        EXPECT_TRUE(std::isfinite(a.metrics.mare) && std::isfinite(a.metrics.relMse) &&
                    std::isfinite(a.ssim()))
            << a.metrics.mare << " " << a.metrics.relMse << " " << a.ssim();
        EXPECT_GT(a.flip, 0.0);
        EXPECT_LT(a.flip, 1.0);
        EXPECT_GT(a.metrics.pixels, 1000u) << "the box fills the view";
        EXPECT_GT(s->gpuMs, 0.0) << "the frame's GPU time is beside it";
        EXPECT_EQ(s->heatMap.size(), s->frameDisplay.size());
    }
    EXPECT_LT(last->accuracy.metrics.noiseMare, first->accuracy.metrics.noiseMare) << "the noise falls";
    EXPECT_LT(last->accuracy.noiseFlip, first->accuracy.noiseFlip);
    EXPECT_NE(last->accuracy.metrics.mare, first->accuracy.metrics.mare)
        << "the figures follow the reference";
    EXPECT_NE(last->accuracy.flip, first->accuracy.flip);
    EXPECT_NE(panel->figureText("FLIP", false), "-");
    EXPECT_NE(panel->figureText("MARE", true), "-");
    EXPECT_TRUE(panel->gpuTimeText().endsWith("ms")) << panel->gpuTimeText().toStdString();

    // A renderer setting changes the frame, not the reference: it keeps its samples.
    const int sppBefore = f.samples.back()->samplesPerPixel;
    f.samples.clear();
    f.window->document()->setParameter("lpv.propagationSteps", lpv::scene::ParameterValue(2));
    QTRY_VERIFY_WITH_TIMEOUT(!f.samples.empty(), 60000);
    EXPECT_GE(f.samples.back()->samplesPerPixel, sppBefore);

    // A camera move starts it again; unticking stops it.
    // Passes are quick here (about 30 a second): enough of them that the first
    // measurement after a restart (a few hundred ms in) has clearly fewer.
    QTRY_VERIFY_WITH_TIMEOUT(f.samples.back()->samplesPerPixel >= std::max(40, sppBefore + 4), 60000);
    const int sppBeforeMove = f.samples.back()->samplesPerPixel;
    lpv::scene::Camera moved = f.window->viewport()->viewCamera();
    moved.position += glm::vec3(0.2f, 0.1f, 0.0f);
    f.samples.clear();
    f.window->viewport()->setViewCamera(moved);
    EXPECT_EQ(panel->figureText("FLIP", false), "-") << "the old view's figures go at once";
    QTRY_VERIFY_WITH_TIMEOUT(!f.samples.empty(), 60000);
    EXPECT_LT(f.samples.front()->samplesPerPixel, sppBeforeMove);
    EXPECT_TRUE(f.samples.front()->accuracy.flip > 0.0);
    panel->traceBox()->setChecked(false);
    EXPECT_EQ(panel->figureText("FLIP", false), "-");
    EXPECT_FALSE(f.window->viewport()->hdrReadback()) << "frames read nothing back once it is off";
}

TEST(AccuracyDock, HeatMapAndSplitShowOverTheView) {
    Fixture f;
    ASSERT_TRUE(f.open());
    AccuracyPanel* panel = f.window->accuracy();
    Viewport* vp = f.window->viewport();
    panel->traceBox()->setChecked(true);
    QTRY_VERIFY_WITH_TIMEOUT(!f.samples.empty() && vp->frameUpToDate(), 60000);
    // No event is handled between a toggle, the grab and latest() below, so
    // they see one measurement while the reference goes on.
    const QImage plain = vp->grabFramebuffer();
    const QRect all(0, 40, plain.width() - 1, plain.height() - 41); // below the corner labels

    panel->heatMapBox()->setChecked(true);
    EXPECT_TRUE(vp->errorOverlayShown());
    const QImage heat = vp->grabFramebuffer();
    EXPECT_GT(differingPixels(plain, heat, all, 24), (all.width() / 2) * (all.height() / 2) / 4)
        << "the heat map covers the view";
    panel->heatMapBox()->setChecked(false);
    EXPECT_FALSE(vp->errorOverlayShown());

    panel->splitBox()->setChecked(true);
    ASSERT_TRUE(vp->comparisonSplitShown());
    const auto sample = panel->monitor()->latest();
    ASSERT_TRUE(sample);
    const QImage split = vp->grabFramebuffer().convertToFormat(QImage::Format_RGB32);
    ASSERT_EQ(sample->referenceDisplay.size(), split.size()) << "rendered at the widget's size";
    const QImage reference = sample->referenceDisplay.convertToFormat(QImage::Format_RGB32);
    const QImage frame = sample->frameDisplay.convertToFormat(QImage::Format_RGB32);
    const QRect right(split.width() / 2 + 4, 40, split.width() / 2 - 8, split.height() - 41);
    const QRect left(2, 40, split.width() / 2 - 8, split.height() - 41);
    const int samples = (right.width() / 2) * (right.height() / 2);
    EXPECT_LT(differingPixels(split, reference, right, 3), samples / 50) << "the right half is the reference";
    EXPECT_LT(differingPixels(split, frame, left, 3), samples / 50) << "the left half is the frame";
    EXPECT_GT(differingPixels(frame, reference, right, 3), samples / 20)
        << "and the two differ (the reference's noise at least)";
    panel->splitBox()->setChecked(false);
    EXPECT_FALSE(vp->comparisonSplitShown());
}
