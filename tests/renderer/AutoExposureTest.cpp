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
    const LogLuminanceSum s = meterLogLuminance(px.data(), 100, 4);
    EXPECT_DOUBLE_EQ(s.lit, 100.0);
    EXPECT_NEAR(std::exp(targetLogExposure(s, 0.18)) * 2.0, 0.18, 1e-6);
}

TEST(AutoExposure, TheLogAverageIsTheGeometricMeanOfTheLitPixels) {
    // Half the pixels at 0.5, half at 8: geometric mean 2, arithmetic mean 4.25.
    std::vector<float> px = uniformImage(50, 0.5f, 0.5f, 0.5f);
    const auto bright = uniformImage(50, 8.0f, 8.0f, 8.0f);
    px.insert(px.end(), bright.begin(), bright.end());
    const LogLuminanceSum s = meterLogLuminance(px.data(), 100, 4);
    EXPECT_NEAR(std::exp(s.sumLog / s.lit), 2.0, 1e-5);
}

TEST(AutoExposure, UnlitNanAndInfinitePixelsAreNotMetered) {
    std::vector<float> px = uniformImage(10, 1.0f, 1.0f, 1.0f);
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    for (const float v : {0.0f, 1e-7f, nan, inf, -1.0f})
        px.insert(px.end(), {v, v, v, 1.0f});
    const LogLuminanceSum s = meterLogLuminance(px.data(), 15, 4);
    EXPECT_DOUBLE_EQ(s.lit, 10.0);
    EXPECT_NEAR(s.sumLog, 0.0, 1e-12);
}

TEST(AutoExposure, NothingLitKeepsExposureOneAndExtremesClampTo16Ev) {
    EXPECT_DOUBLE_EQ(targetLogExposure({}, 0.18), 0.0);
    const double limit = kMeterMaxEv * std::numbers::ln2;
    const auto dark = uniformImage(4, 1e-4f, 1e-4f, 1e-4f);   // 0.18/1e-4 = 2^10.8: inside
    const auto darker = uniformImage(4, 2e-5f, 2e-5f, 2e-5f); // 2^13.1: inside
    const auto blinding = uniformImage(4, 1e9f, 1e9f, 1e9f);   // 2^-32.4: clamped
    EXPECT_LT(targetLogExposure(meterLogLuminance(dark.data(), 4, 4), 0.18), limit);
    EXPECT_LT(targetLogExposure(meterLogLuminance(darker.data(), 4, 4), 0.18), limit);
    EXPECT_DOUBLE_EQ(targetLogExposure(meterLogLuminance(blinding.data(), 4, 4), 0.18), -limit);
}

TEST(AutoExposure, AdaptationFollowsTheTimeConstant) {
    EXPECT_DOUBLE_EQ(adaptationBlend(0.1, 0.0), 1.0);
    EXPECT_NEAR(adaptationBlend(0.5, 0.5), 1.0 - std::exp(-1.0), 1e-12);
    EXPECT_DOUBLE_EQ(adaptationBlend(0.0, 0.5), 0.0);
    // Two steps of dt equal one of 2 dt: the adaptation does not depend on the frame rate.
    const double a = adaptationBlend(0.04, 0.5);
    EXPECT_NEAR(1.0 - (1.0 - a) * (1.0 - a), adaptationBlend(0.08, 0.5), 1e-12);
}
