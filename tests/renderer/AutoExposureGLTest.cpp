// Auto exposure on the GPU (exposure_reduce.comp, exposure_adapt.comp) against
// its CPU twin (AutoExposure.h), through the whole renderer on the Cornell box.
#include "GlFixture.h"

#include "lpv/renderer/AutoExposure.h"
#include "lpv/renderer/DisplayMapping.h"
#include "lpv/renderer/ForwardRenderer.h"
#include "lpv/scene/CornellBox.h"

#include <cmath>

using namespace lpv;

namespace {

constexpr int kWidth = 200, kHeight = 150; // not a multiple of the 64-pixel tiles

class AutoExposureGL : public GlTest {
protected:
    void SetUp() override {
        GlTest::SetUp();
        auto r = renderer::ForwardRenderer::create();
        ASSERT_TRUE(r.has_value()) << r.error().describe();
        renderer.emplace(std::move(*r));
        renderer->setScene(project.scene);
        ASSERT_TRUE(params.set("output.exposure", 0.0).has_value());
        // Without the camera G-buffer in the geometry volume the second frame's
        // LPV equals the first's: every frame of a test sees the same HDR image.
        ASSERT_TRUE(params.set("lpv.gvFromCamera", false).has_value());
    }
    void render() {
        auto ok = renderer->render(project.scene, params, project.scene.cameras.front(), kWidth, kHeight);
        ASSERT_TRUE(ok.has_value()) << ok.error().describe();
    }
    // ln of the exposure the CPU twin meters on the renderer's last HDR frame.
    double cpuTargetLogExposure() const {
        const std::vector<float> hdr = renderer->readHdr();
        return renderer::targetLogExposure(renderer::meterLuminance(hdr.data(), hdr.size() / 4, 4),
                                           renderer::meterTargetOf(params));
    }
    double meanDisplay() const {
        double sum = 0.0;
        const auto px = renderer->readDisplay();
        for (std::size_t i = 0; i < px.size(); i += 4)
            sum += px[i] + px[i + 1] + px[i + 2];
        return sum / double(px.size() / 4 * 3);
    }

    scene::Project project = scene::makeCornellBoxProject();
    scene::ParameterSet params = project.parameters;
    std::optional<renderer::ForwardRenderer> renderer;
};

} // namespace

TEST_F(AutoExposureGL, IsTheDefaultAndMatchesTheCpuMeter) {
    EXPECT_EQ(params.getEnum("output.exposureMode"), "auto");
    render();
    const double expected = std::exp(cpuTargetLogExposure());
    EXPECT_NEAR(renderer->displayExposure(params) / expected, 1.0, 1e-3) << "CPU twin " << expected;
    EXPECT_NE(expected, 1.0); // the Cornell box is not already at the key
}

TEST_F(AutoExposureGL, HighlightProtectionMatchesTheCpuMeter) {
    // A high key under the linear operator (white at 1) would clip the lit
    // walls: the histogram's percentile, not the log-average, sets the
    // exposure, on the GPU as on the CPU.
    ASSERT_TRUE(params.set("output.exposureKey", 2.0).has_value());
    ASSERT_TRUE(params.set("output.tonemapper", std::string("linear")).has_value());
    ASSERT_TRUE(params.set("output.exposureHighlights", 90.0).has_value());
    render();
    const std::vector<float> hdr = renderer->readHdr();
    const renderer::LuminanceMeter meter = renderer::meterLuminance(hdr.data(), hdr.size() / 4, 4);
    renderer::MeterTarget keyOnly = renderer::meterTargetOf(params);
    keyOnly.highlightPercent = 100.0;
    keyOnly.highlightInput = 1e30;
    ASSERT_LT(cpuTargetLogExposure(), renderer::targetLogExposure(meter, keyOnly) - 0.1)
        << "the highlights must lower the exposure for this test to see them";
    // A pixel whose log2 rounds the other way on the GPU moves one quarter-stop
    // bin, which the in-bin interpolation turns into a tiny shift.
    EXPECT_NEAR(std::log(renderer->displayExposure(params)), cpuTargetLogExposure(), 2e-3);
}

TEST_F(AutoExposureGL, CompensationMultipliesTheMeteredExposure) {
    render();
    const double metered = renderer->displayExposure(params);
    ASSERT_TRUE(params.set("output.exposure", 1.5).has_value());
    render();
    EXPECT_NEAR(renderer->displayExposure(params) / metered, std::exp2(1.5), 1e-3);
}

TEST_F(AutoExposureGL, AdaptsTowardTheNewTargetByTheTimeStep) {
    renderer->setExposureTimeStep(0.1);
    ASSERT_TRUE(params.set("output.exposureAdaptation", 0.5).has_value());
    render(); // the first frame takes its target at once
    const double first = cpuTargetLogExposure();
    EXPECT_NEAR(std::log(renderer->displayExposure(params)), first, 1e-3);
    project.scene.lights[0].intensity *= 8.0f; // the lamp turned up: the target drops by ln 8
    render();
    const double target = cpuTargetLogExposure();
    EXPECT_NEAR(target, first - std::log(8.0), 0.05);
    const double blend = renderer::adaptationBlend(0.1, 0.5);
    EXPECT_NEAR(std::log(renderer->displayExposure(params)), first + (target - first) * blend, 1e-3);
    // And after a reset (a cut) the next frame is at its target again.
    renderer->resetExposure();
    render();
    EXPECT_NEAR(std::log(renderer->displayExposure(params)), cpuTargetLogExposure(), 1e-3);
}

TEST_F(AutoExposureGL, ShowsADimSceneAsWellAsABrightOneWhileManualDoesNot) {
    render();
    const double bright = meanDisplay();
    project.scene.lights[0].intensity *= 1e-2f;
    render();
    const double dimAuto = meanDisplay();
    ASSERT_TRUE(params.setFromText("output.exposureMode", "manual", "test").has_value());
    render();
    const double dimManual = meanDisplay();
    EXPECT_GT(bright, 20.0) << "the Cornell box must be visible at the defaults";
    EXPECT_NEAR(dimAuto / bright, 1.0, 0.1) << "bright " << bright << " dim (auto) " << dimAuto;
    EXPECT_LT(dimManual, 0.2 * dimAuto) << "manual exposure keeps the dim scene dark";
}

TEST_F(AutoExposureGL, LeavesTheHdrImageLinear) {
    render();
    const std::vector<float> autoHdr = renderer->readHdr();
    ASSERT_TRUE(params.setFromText("output.exposureMode", "manual", "test").has_value());
    ASSERT_TRUE(params.set("output.exposure", 3.0).has_value());
    render();
    EXPECT_EQ(renderer->readHdr(), autoHdr);
    EXPECT_DOUBLE_EQ(renderer->displayExposure(params), 8.0);
}
