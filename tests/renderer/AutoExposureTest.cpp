// Auto exposure's CPU twin (AutoExposure.h): what the GPU meter must compute.
#include "lpv/renderer/AutoExposure.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

using namespace lpv::renderer;

namespace {
std::vector<float> uniformImage(std::size_t pixels, float r, float g, float b) {
    std::vector<float> px;
    for (std::size_t i = 0; i < pixels; ++i)
        px.insert(px.end(), {r, g, b, 1.0f});
    return px;
}
} // namespace

TEST(AutoExposure, AUniformImageIsExposedToTheKey) {
    const auto px = uniformImage(100, 2.0f, 2.0f, 2.0f);
    const LuminanceMeter s = meterLuminance(px.data(), 100, 4);
    EXPECT_DOUBLE_EQ(s.lit, 100.0);
    EXPECT_NEAR(std::exp(targetLogExposure(s, {.key = 0.18})) * 2.0, 0.18, 1e-6);
}

TEST(AutoExposure, TheLogAverageIsTheGeometricMeanOfTheLitPixels) {
    // Half the pixels at 0.5, half at 8: geometric mean 2, arithmetic mean 4.25.
    std::vector<float> px = uniformImage(50, 0.5f, 0.5f, 0.5f);
    const auto bright = uniformImage(50, 8.0f, 8.0f, 8.0f);
    px.insert(px.end(), bright.begin(), bright.end());
    const LuminanceMeter s = meterLuminance(px.data(), 100, 4);
    EXPECT_NEAR(std::exp(s.sumLog / s.lit), 2.0, 1e-5);
}

TEST(AutoExposure, UnlitNanAndInfinitePixelsAreNotMetered) {
    std::vector<float> px = uniformImage(10, 1.0f, 1.0f, 1.0f);
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    for (const float v : {0.0f, 1e-7f, nan, inf, -1.0f})
        px.insert(px.end(), {v, v, v, 1.0f});
    const LuminanceMeter s = meterLuminance(px.data(), 15, 4);
    EXPECT_DOUBLE_EQ(s.lit, 10.0);
    EXPECT_NEAR(s.sumLog, 0.0, 1e-12);
}

TEST(AutoExposure, NothingLitKeepsExposureOneAndExtremesClampTo16Ev) {
    EXPECT_DOUBLE_EQ(targetLogExposure({}, {.key = 0.18}), 0.0);
    const double limit = kMeterMaxEv * std::numbers::ln2;
    const auto dark = uniformImage(4, 1e-4f, 1e-4f, 1e-4f);   // 0.18/1e-4 = 2^10.8: inside
    const auto darker = uniformImage(4, 2e-5f, 2e-5f, 2e-5f); // 2^13.1: inside
    const auto blinding = uniformImage(4, 1e9f, 1e9f, 1e9f);   // 2^-32.4: clamped
    EXPECT_LT(targetLogExposure(meterLuminance(dark.data(), 4, 4), {.key = 0.18}), limit);
    EXPECT_LT(targetLogExposure(meterLuminance(darker.data(), 4, 4), {.key = 0.18}), limit);
    EXPECT_DOUBLE_EQ(targetLogExposure(meterLuminance(blinding.data(), 4, 4), {.key = 0.18}), -limit);
}

TEST(AutoExposure, TheHistogramBinsTheBrightestChannelInQuarterStops) {
    EXPECT_EQ(meterBin(1.0f), int(-kMeterMinLog2 * kMeterBinsPerEv));
    EXPECT_EQ(meterBin(2.0f) - meterBin(1.0f), 4);
    EXPECT_EQ(meterBin(1e-30f), 0);
    EXPECT_EQ(meterBin(1e30f), kMeterBins - 1);
    // A saturated red pixel is binned by its red channel: that is the one that clips.
    const auto red = uniformImage(1, 8.0f, 0.1f, 0.1f);
    const LuminanceMeter m = meterLuminance(red.data(), 1, 4);
    EXPECT_EQ(m.histogram[std::size_t(meterBin(8.0f))], 1u);
}

TEST(AutoExposure, ThePercentileLiesInTheBinOfThePixelsThatReachIt) {
    // 97 pixels at 0.1, 3 at 100: the 98th percentile is among the bright ones,
    // the 50th among the dim ones, each inside its quarter-stop bin.
    std::vector<float> px = uniformImage(97, 0.1f, 0.1f, 0.1f);
    const auto bright = uniformImage(3, 100.0f, 100.0f, 100.0f);
    px.insert(px.end(), bright.begin(), bright.end());
    const LuminanceMeter m = meterLuminance(px.data(), 100, 4);
    const double binRatio = std::exp2(1.0 / kMeterBinsPerEv);
    const double bin100 = std::exp2(kMeterMinLog2 + meterBin(100.0f) / kMeterBinsPerEv);
    const double bin01 = std::exp2(kMeterMinLog2 + meterBin(0.1f) / kMeterBinsPerEv);
    EXPECT_GE(highlightPercentile(m, 98.0), bin100);
    EXPECT_LE(highlightPercentile(m, 98.0), bin100 * binRatio);
    EXPECT_GE(highlightPercentile(m, 50.0), bin01);
    EXPECT_LE(highlightPercentile(m, 50.0), bin01 * binRatio);
    // It moves with the percentage inside a bin instead of jumping a whole bin.
    EXPECT_LT(highlightPercentile(m, 97.5), highlightPercentile(m, 99.0));
    EXPECT_DOUBLE_EQ(highlightPercentile({}, 98.0), 0.0);
}

TEST(AutoExposure, HighlightsAboveTheWhiteLowerTheExposureOtherwiseTheKeyRules) {
    // 97% of the pixels at 0.1, 3% at 100: the key alone (0.18 / geometric
    // mean 0.123) would put the bright ones at 146, far past a white of 10.
    std::vector<float> px = uniformImage(97, 0.1f, 0.1f, 0.1f);
    const auto bright = uniformImage(3, 100.0f, 100.0f, 100.0f);
    px.insert(px.end(), bright.begin(), bright.end());
    const LuminanceMeter m = meterLuminance(px.data(), 100, 4);
    const double keyOnly = targetLogExposure(m, {.key = 0.18});
    EXPECT_NEAR(std::exp(keyOnly), 0.18 / std::exp(m.sumLog / m.lit), 1e-9);
    const MeterTarget protect{.key = 0.18, .highlightPercent = 98.0, .highlightInput = 10.0};
    const double protectedLog = targetLogExposure(m, protect);
    EXPECT_LT(protectedLog, keyOnly);
    EXPECT_NEAR(std::exp(protectedLog) * highlightPercentile(m, 98.0), 10.0, 1e-9);
    // With 96% below the white allowed, the 3% of highlights may clip: the key rules.
    EXPECT_DOUBLE_EQ(targetLogExposure(m, {.key = 0.18, .highlightPercent = 96.0, .highlightInput = 10.0}), keyOnly);
    // A uniform image's highlights are its midtones: the key rules there too.
    const auto flat = uniformImage(100, 2.0f, 2.0f, 2.0f);
    const LuminanceMeter f = meterLuminance(flat.data(), 100, 4);
    EXPECT_NEAR(std::exp(targetLogExposure(f, protect)) * 2.0, 0.18, 1e-6);
}

TEST(AutoExposure, AdaptationFollowsTheTimeConstant) {
    EXPECT_DOUBLE_EQ(adaptationBlend(0.1, 0.0), 1.0);
    EXPECT_NEAR(adaptationBlend(0.5, 0.5), 1.0 - std::exp(-1.0), 1e-12);
    EXPECT_DOUBLE_EQ(adaptationBlend(0.0, 0.5), 0.0);
    // Two steps of dt equal one of 2 dt: the adaptation does not depend on the frame rate.
    const double a = adaptationBlend(0.04, 0.5);
    EXPECT_NEAR(1.0 - (1.0 - a) * (1.0 - a), adaptationBlend(0.08, 0.5), 1e-12);
}
