// The Accuracy dock (issue #26 item 3) on the built-in Cornell box: tracing
// a reference of the view gives finite figures that change as samples add up
// while the reference's noise falls; a renderer setting leaves the
// reference converging; the heat map lies over the view and goes again; the
// LPV | reference split shows the reference on its right half, both halves
// through the frame's own exposure and tonemapper (issue #43: equal light is
// an equal pixel; the CPU mapping is the GPU's to within one step of 8 bits),
// or `--preview`'s mapping when asked.
#include "AccuracyPanel.h"
#include "Autosave.h"
#include "lpv/renderer/DisplayMapping.h"
#include "Document.h"
#include "MainWindow.h"
#include "TestPaths.h"
#include "Viewport.h"
#include "WcagContrast.h"
#include "TestWindow.h"

#include <QCheckBox>
#include <QComboBox>
#include <QLabel>
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

// A window on the Cornell box, its viewport small (the reference traces at its size).
struct Fixture {
    QTemporaryDir autosaveDir;
    std::unique_ptr<MainWindow> window;
    std::vector<std::shared_ptr<const AccuracySample>> samples;

    bool open() {
        Autosave::setRootForTests(autosaveDir.path());
        window = std::make_unique<MainWindow>();
        window->setUnsavedChangesAnswerForTests(QMessageBox::Discard);
        if (!window->openProject(test::cornellTemplate(), false))
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

// The largest difference of any channel between two images of one size (255 when the sizes differ).
int maxDifference(const QImage& a, const QImage& b) {
    if (a.size() != b.size() || a.isNull())
        return 255;
    const QImage x = a.convertToFormat(QImage::Format_RGBA8888),
                 y = b.convertToFormat(QImage::Format_RGBA8888);
    int most = 0;
    for (int row = 0; row < x.height(); ++row)
        for (int i = 0; i < x.width() * 4; ++i)
            most = std::max(most, std::abs(int(x.constScanLine(row)[i]) - int(y.constScanLine(row)[i])));
    return most;
}

QImage toQImage(const lpv::scene::Image8& image) {
    return QImage(image.pixels.data(), image.width, image.height, image.width * 4, QImage::Format_RGBA8888)
        .copy();
}

} // namespace

TEST(AccuracyDock, FiguresChangeAsTheReferenceConvergesAndItsNoiseFalls) {
    Fixture f;
    ASSERT_TRUE(f.open());
    AccuracyPanel* panel = f.window->accuracy();
    panel->traceBox()->setChecked(true);
    // From 2 samples on: one sample has no variance, so no noise figure yet.
    ASSERT_TRUE(
        QTest::qWaitFor([&] { return !f.samples.empty() && f.samples.back()->samplesPerPixel >= 2; }, 60000));
    const auto first = f.samples.back();
    ASSERT_TRUE(QTest::qWaitFor(
        [&] { return f.samples.back()->samplesPerPixel >= first->samplesPerPixel + 3; }, 60000));
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
    // The reference's samples are given once, in its row (issue #46: the
    // status line under the figures said "Reference: N spp, T s" again).
    int referenceRows = 0;
    for (const QLabel* label : panel->findChildren<QLabel*>())
        referenceRows += label->isVisible() && label->text().contains("spp") ? 1 : 0;
    EXPECT_EQ(referenceRows, 1) << "status: " << panel->statusText().toStdString();

    // A renderer setting changes the frame, not the reference: it keeps its samples.
    const int sppBefore = f.samples.back()->samplesPerPixel;
    f.samples.clear();
    f.window->document()->setParameter("lpv.propagationSteps", lpv::scene::ParameterValue(2));
    ASSERT_TRUE(QTest::qWaitFor([&] { return !f.samples.empty(); }, 60000));
    EXPECT_GE(f.samples.back()->samplesPerPixel, sppBefore);

    // A camera move starts it again; unticking stops it.
    // Passes are quick here (about 30 a second): enough of them that the first
    // measurement after a restart (a few hundred ms in) has clearly fewer.
    ASSERT_TRUE(QTest::qWaitFor(
        [&] { return f.samples.back()->samplesPerPixel >= std::max(40, sppBefore + 4); }, 60000));
    const int sppBeforeMove = f.samples.back()->samplesPerPixel;
    lpv::scene::Camera moved = f.window->viewport()->viewCamera();
    moved.position += glm::vec3(0.2f, 0.1f, 0.0f);
    f.samples.clear();
    f.window->viewport()->setViewCamera(moved);
    EXPECT_EQ(panel->figureText("FLIP", false), "-") << "the old view's figures go at once";
    ASSERT_TRUE(QTest::qWaitFor([&] { return !f.samples.empty(); }, 60000));
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
    ASSERT_TRUE(QTest::qWaitFor([&] { return !f.samples.empty() && vp->frameUpToDate(); }, 60000));
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
    ASSERT_EQ(sample->referenceTonemapped.size(), split.size()) << "rendered at the widget's size";
    // "LPV" and "Reference" read on whatever is under them (issue #46: white
    // on the bright sky could not be read): the text against the brightest
    // pixel of the label's left edge, just before its first letter.
    for (const int x0 : {8, split.width() / 2 + 8}) {
        double text = 0.0, under = 0.0;
        for (int y = 12; y <= 24; ++y) {
            for (int x = x0 + 2; x < x0 + 60; ++x)
                text = std::max(text, lpv::test::wcagLuminance(split.pixel(x, y)));
            under = std::max(under, lpv::test::wcagLuminance(split.pixel(x0 + 2, y)));
        }
        EXPECT_GE(lpv::test::wcagContrast(text, under), 4.5)
            << "the label at x " << x0 << ": text " << text << ", under it " << under;
    }
    // By default both halves go through the frame's exposure and tonemapper.
    const QImage reference = sample->referenceTonemapped.convertToFormat(QImage::Format_RGB32);
    const QImage frame = sample->frameTonemapped.convertToFormat(QImage::Format_RGB32);
    const QRect right(split.width() / 2 + 4, 40, split.width() / 2 - 8, split.height() - 41);
    const QRect left(2, 40, split.width() / 2 - 8, split.height() - 41);
    const int samples = (right.width() / 2) * (right.height() / 2);
    EXPECT_LT(differingPixels(split, reference, right, 3), samples / 50) << "the right half is the reference";
    EXPECT_LT(differingPixels(split, frame, left, 3), samples / 50) << "the left half is the frame";
    EXPECT_GT(differingPixels(frame, reference, right, 3), samples / 20)
        << "and the two differ (the reference's noise at least)";
    EXPECT_LT(differingPixels(plain, frame, left, 3), samples / 50)
        << "the left half is the frame as the view shows it (the GPU's mapping)";

    // The preview mapping, as an option: x / (x + mean) with the reference's mean for both.
    panel->mappingBox()->setCurrentIndex(1);
    const QImage preview = vp->grabFramebuffer().convertToFormat(QImage::Format_RGB32);
    const QImage previewReference = sample->referenceDisplay.convertToFormat(QImage::Format_RGB32);
    EXPECT_LT(differingPixels(preview, previewReference, right, 3), samples / 50);
    EXPECT_GT(differingPixels(preview, split, right, 3), samples / 20) << "another mapping";
    panel->mappingBox()->setCurrentIndex(0);
    panel->splitBox()->setChecked(false);
    EXPECT_FALSE(vp->comparisonSplitShown());
}

// The CPU mapping the split and the live reference use is the frame's own:
// each tonemapper, on auto and on manual exposure, maps the frame's HDR
// read-back to the GPU's display pixels within one step of 8 bits.
TEST(AccuracyDock, CpuTonemapIsTheFramesOwn) {
    Fixture f;
    ASSERT_TRUE(f.open());
    Viewport* vp = f.window->viewport();
    Document* doc = f.window->document();
    std::shared_ptr<const HdrFrame> last;
    QObject::connect(vp, &Viewport::hdrFrameRendered,
                     [&](std::shared_ptr<const HdrFrame> frame) { last = frame; });
    vp->setHdrReadback(true);
    for (const char* mode : {"auto", "manual"})
        for (const char* tonemapper : {"aces", "reinhard", "uncharted2", "linear"}) {
            doc->setParameter("output.exposureMode", lpv::scene::ParameterValue(std::string(mode)));
            doc->setParameter("output.exposure",
                              lpv::scene::ParameterValue(std::string(mode) == "manual" ? 1.5 : 0.5));
            doc->setParameter("output.tonemapper", lpv::scene::ParameterValue(std::string(tonemapper)));
            last.reset();
            ASSERT_TRUE(QTest::qWaitFor(
                [&] { return vp->frameUpToDate() && last && last->tonemapper == tonemapper; }, 60000));
            ASSERT_FALSE(last->display.isNull());
            if (std::string(mode) == "manual") {
                EXPECT_NEAR(last->exposure, std::exp2(1.5), 1e-6);
            }
            const lpv::renderer::DisplayMapping mapping{last->exposure, tonemapperOf(last->tonemapper)};
            const QImage cpu = toQImage(tonemapImage(last->pixels, last->width, last->height, mapping));
            EXPECT_LE(maxDifference(cpu, last->display), 1) << mode << " " << tonemapper;
        }
    vp->setHdrReadback(false);
}

// Identical HDR images in both halves give identical pixels in both halves:
// through the frame's mapping (the default) and through the preview's.
TEST(AccuracyDock, EqualLightShowsAsEqualPixelsInBothHalves) {
    Fixture f;
    ASSERT_TRUE(f.open());
    Viewport* vp = f.window->viewport();
    const QSize size = vp->renderSize();
    HdrFrame frame;
    frame.width = size.width();
    frame.height = size.height();
    frame.outputView = "final";
    frame.exposure = 1.7;
    frame.tonemapper = "aces";
    // Light that changes down the view and not across it (dark to bright, coloured).
    for (int y = 0; y < frame.height; ++y)
        for (int x = 0; x < frame.width; ++x) {
            const float t = float(y) / float(frame.height - 1);
            frame.pixels.push_back(glm::vec3(4.0f * t * t, 2.0f * t, 0.05f + 0.5f * t));
        }
    lpv::reference::ReferenceImage reference;
    reference.resize(frame.width, frame.height);
    reference.samplesPerPixel = 16;
    reference.image = frame.pixels;
    std::fill(reference.coverage.begin(), reference.coverage.end(), 1.0f);
    const std::shared_ptr<AccuracySample> sample = measureFrame(frame, reference);
    ASSERT_TRUE(sample);
    EXPECT_LE(maxDifference(sample->frameTonemapped, sample->referenceTonemapped), 1);
    EXPECT_LE(maxDifference(sample->frameDisplay, sample->referenceDisplay), 1);
    EXPECT_GT(maxDifference(sample->frameTonemapped, sample->frameDisplay), 8) << "two different mappings";
    // The frame's mapping is the CPU twin of tonemap.frag with the frame's exposure.
    const glm::vec3 expected =
        mapToDisplay(frame.pixels[std::size_t(frame.width) * 20], {1.7, Tonemapper::Aces});
    const QRgb got = sample->referenceTonemapped.pixel(frame.width - 1, 20);
    EXPECT_NEAR(qRed(got), expected.r * 255.0, 1.0);
    EXPECT_NEAR(qGreen(got), expected.g * 255.0, 1.0);

    // In the view: the left half (frame) and the right half (reference) of each row agree.
    vp->setComparisonSplit(sample->frameTonemapped, sample->referenceTonemapped);
    ASSERT_TRUE(vp->comparisonSplitShown());
    const QImage shown = vp->grabFramebuffer().convertToFormat(QImage::Format_RGB32);
    int differing = 0, rows = 0;
    for (int y = 40; y < shown.height() - 4; y += 3, ++rows) {
        const QRgb l = shown.pixel(shown.width() / 4, y), r = shown.pixel(3 * shown.width() / 4, y);
        if (std::abs(qRed(l) - qRed(r)) > 1 || std::abs(qGreen(l) - qGreen(r)) > 1 ||
            std::abs(qBlue(l) - qBlue(r)) > 1)
            ++differing;
    }
    EXPECT_EQ(differing, 0) << "of " << rows << " rows";
    vp->setComparisonSplit({}, {});
}
