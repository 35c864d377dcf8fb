// Error metrics on synthetic images whose answer is known in closed form.
#include "lpv/reference/Metrics.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using namespace lpv::reference;

std::vector<glm::vec3> constant(int w, int h, float v) {
    return std::vector<glm::vec3>(std::size_t(w * h), glm::vec3(v));
}

TEST(Metrics, IdenticalImagesHaveNoError) {
    auto ref = constant(8, 8, 2.0f);
    for (std::size_t i = 0; i < ref.size(); ++i)
        ref[i] *= 1.0f + 0.1f * float(i % 7); // some structure for SSIM
    const ErrorMetrics m = compareImages({8, 8, &ref}, {8, 8, &ref}, nullptr, nullptr);
    EXPECT_EQ(m.pixels, 64u);
    EXPECT_EQ(m.relMse, 0.0);
    EXPECT_EQ(m.mare, 0.0);
    EXPECT_NEAR(m.ssim, 1.0, 1e-12);
}

// Without SSIM (the editor's live reference asks only its noise) the other
// figures are the same and ssim stays 1.
TEST(Metrics, SsimCanBeLeftOutAndTheRestIsUnchanged) {
    auto ref = constant(16, 16, 2.0f), test = ref;
    for (std::size_t i = 0; i < ref.size(); ++i)
        test[i] *= 1.0f + 0.3f * float(i % 5);
    std::vector<glm::vec3> variance(ref.size(), glm::vec3(0.04f));
    MetricOptions noSsim;
    noSsim.ssim = false;
    const ErrorMetrics with = compareImages({16, 16, &test}, {16, 16, &ref}, &variance, nullptr);
    const ErrorMetrics without = compareImages({16, 16, &test}, {16, 16, &ref}, &variance, nullptr, noSsim);
    EXPECT_LT(with.ssim, 0.99);
    EXPECT_EQ(without.ssim, 1.0);
    EXPECT_EQ(without.mare, with.mare);
    EXPECT_EQ(without.relMse, with.relMse);
    EXPECT_EQ(without.noiseMare, with.noiseMare);
    EXPECT_GT(without.noiseMare, 0.0);
}

TEST(Metrics, UniformScaleErrorHasClosedForm) {
    // t = (1 + k) r on a constant r: relMSE = k^2 r^2 / (r^2 + eps^2), MARE = k r / (r + eps), eps = 0.01 r.
    const float r = 3.0f, k = 0.2f;
    const auto ref = constant(16, 8, r);
    const auto test = constant(16, 8, r * (1.0f + k));
    const ErrorMetrics m = compareImages({16, 8, &test}, {16, 8, &ref}, nullptr, nullptr);
    EXPECT_NEAR(m.relMse, double(k * k) / (1.0 + 1e-4), 1e-6);
    EXPECT_NEAR(m.mare, double(k) / 1.01, 1e-6);
    EXPECT_NEAR(m.meanTest / m.meanReference, 1.0 + k, 1e-6);
    // Both constant: SSIM's contrast and structure terms are 1; the mean term is
    // (2xy + c1) / (x^2 + y^2 + c1) with x, y mapped by v / (v + r).
    const double x = (r * (1.0 + k)) / (r * (1.0 + k) + r), y = 0.5, c1 = 1e-4;
    EXPECT_NEAR(m.ssim, (2 * x * y + c1) / (x * x + y * y + c1), 1e-6);
}

TEST(Metrics, MaskedPixelsAreLeftOut) {
    auto ref = constant(4, 4, 1.0f);
    auto test = ref;
    std::vector<float> mask(16, 1.0f);
    test[5] = glm::vec3(1000.0f); // the sky, say
    mask[5] = 0.0f;
    const ErrorMetrics m = compareImages({4, 4, &test}, {4, 4, &ref}, nullptr, &mask);
    EXPECT_EQ(m.pixels, 15u);
    EXPECT_EQ(m.relMse, 0.0);
    const ErrorMetrics unmasked = compareImages({4, 4, &test}, {4, 4, &ref}, nullptr, nullptr);
    EXPECT_GT(unmasked.relMse, 1000.0);
}

TEST(Metrics, ErrorBelowTheReferenceNoiseIsReportedAsSuch) {
    // The reference's per-pixel sigma is 0.1 on r = 1 (grey: sigma_Y = 0.1).
    const auto ref = constant(8, 8, 1.0f);
    const std::vector<glm::vec3> variance(64, glm::vec3(0.01f));
    const double eps2 = 1e-4;
    auto close = constant(8, 8, 1.05f); // 5% off: inside the noise
    ErrorMetrics m = compareImages({8, 8, &close}, {8, 8, &ref}, &variance, nullptr);
    EXPECT_NEAR(m.noiseRelMse, 0.01 / (1.0 + eps2), 1e-6);
    EXPECT_NEAR(m.noiseMare, std::sqrt(2.0 / 3.14159265358979) * 0.1 / 1.01, 1e-6);
    EXPECT_TRUE(m.relMseBelowNoise());
    EXPECT_TRUE(m.mareBelowNoise());
    EXPECT_EQ(m.relMseDenoised(), 0.0);
    EXPECT_NE(describe(m).find("below noise"), std::string::npos);

    auto far = constant(8, 8, 1.5f); // 50% off: well above it
    m = compareImages({8, 8, &far}, {8, 8, &ref}, &variance, nullptr);
    EXPECT_FALSE(m.relMseBelowNoise());
    EXPECT_FALSE(m.mareBelowNoise());
    EXPECT_NEAR(m.relMseDenoised(), (0.25 - 0.01) / (1.0 + eps2), 1e-6);
}

TEST(Metrics, NonFiniteTestPixelsCountAsWrongNotAsNan) {
    const auto ref = constant(4, 4, 1.0f);
    auto test = ref;
    test[3] = glm::vec3(std::nanf(""));
    const ErrorMetrics m = compareImages({4, 4, &test}, {4, 4, &ref}, nullptr, nullptr);
    EXPECT_TRUE(std::isfinite(m.relMse));
    EXPECT_NEAR(m.mare, 1.0 / 1.01 / 16.0, 1e-9);
}

TEST(Metrics, SsimDropsWithNoiseButNotWithIdenticalStructure) {
    const int w = 32, h = 32;
    std::vector<float> a(std::size_t(w * h)), noisy(a.size());
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            a[std::size_t(y * w + x)] = 1.0f + 0.5f * std::sin(0.3f * float(x)) * std::cos(0.2f * float(y));
            // A deterministic high-frequency pattern stands in for noise.
            noisy[std::size_t(y * w + x)] =
                a[std::size_t(y * w + x)] * (1.0f + 0.4f * float(((x * 7 + y * 13) % 5) - 2) / 2.0f);
        }
    EXPECT_NEAR(ssimLuminance(a, a, w, h, nullptr), 1.0, 1e-9);
    const double s = ssimLuminance(noisy, a, w, h, nullptr);
    EXPECT_LT(s, 0.95);
    EXPECT_GT(s, 0.0);
}

} // namespace

// The symmetric error (issue #43) counts too dark and too bright alike:
// half and twice the reference are both a factor of 2 off (100%), where
// MARE says 50% and 100%, so a dark LPV no longer scores better.
TEST(Metrics, SymmetricErrorCountsTooDarkAndTooBrightAlike) {
    const auto ref = constant(8, 8, 4.0f), half = constant(8, 8, 2.0f), twice = constant(8, 8, 8.0f);
    MetricOptions noEps;
    noEps.epsilonFraction = 0.0f; // the closed form without the floor (1e-20 remains)
    noEps.ssim = false;
    const ErrorMetrics dark = compareImages({8, 8, &half}, {8, 8, &ref}, nullptr, nullptr, noEps);
    const ErrorMetrics bright = compareImages({8, 8, &twice}, {8, 8, &ref}, nullptr, nullptr, noEps);
    EXPECT_NEAR(dark.mare, 0.5, 1e-9);
    EXPECT_NEAR(bright.mare, 1.0, 1e-9);
    EXPECT_NEAR(dark.logError, std::log(2.0), 1e-9);
    EXPECT_NEAR(bright.logError, std::log(2.0), 1e-9);
    EXPECT_NEAR(dark.symmetricError(), 1.0, 1e-9);
    EXPECT_NEAR(bright.symmetricError(), 1.0, 1e-9);

    // lpv.intensity = 0.7 against 1.3: MARE calls both 30%; the symmetric
    // error calls the darker one further off (a factor 1/0.7 = 1.43 against 1.3).
    const auto dim = constant(8, 8, 2.8f), hot = constant(8, 8, 5.2f);
    const ErrorMetrics d = compareImages({8, 8, &dim}, {8, 8, &ref}, nullptr, nullptr, noEps);
    const ErrorMetrics h = compareImages({8, 8, &hot}, {8, 8, &ref}, nullptr, nullptr, noEps);
    EXPECT_NEAR(d.mare, h.mare, 1e-6);
    EXPECT_NEAR(d.symmetricError(), 1.0 / 0.7 - 1.0, 1e-6);
    EXPECT_NEAR(h.symmetricError(), 0.3, 1e-6);

    // A black image is far off, not at most 100%: with the default floor of
    // 1% of the mean, ln(101) = a factor of 101.
    const auto black = constant(8, 8, 0.0f);
    const ErrorMetrics none = compareImages({8, 8, &black}, {8, 8, &ref}, nullptr, nullptr);
    EXPECT_NEAR(none.mare, 1.0 / 1.01, 1e-6);
    EXPECT_NEAR(none.symmetricError(), 100.0, 1e-3);

    const ErrorMetrics same = compareImages({8, 8, &ref}, {8, 8, &ref}, nullptr, nullptr);
    EXPECT_EQ(same.logError, 0.0);
}

// The reference's noise raises the floor of the log ratio and gives the
// symmetric error its own noise share, which an image equal to the
// reference's noisy mean is below.
TEST(Metrics, SymmetricErrorHasANoiseShare) {
    auto ref = constant(16, 16, 1.0f), test = ref;
    for (std::size_t i = 0; i < test.size(); ++i)
        test[i] *= i % 2 ? 1.05f : 0.95f; // 5% either way
    const std::vector<glm::vec3> variance(ref.size(), glm::vec3(0.1f * 0.1f)); // sigma 0.1 per channel
    const ErrorMetrics m = compareImages({16, 16, &test}, {16, 16, &ref}, &variance, nullptr);
    // sigma_Y = 0.1, floor 0.1: first order sqrt(2/pi) 0.1 / 1.1 = 0.0725.
    EXPECT_NEAR(m.noiseLogError, std::sqrt(2.0 / 3.14159265358979) * 0.1 / 1.1, 1e-4);
    EXPECT_TRUE(m.symmetricBelowNoise());
    EXPECT_NE(describe(m).find("symmetric"), std::string::npos);
}
