// FLIP (reference/Flip.h) on images whose answer follows from the paper's
// formulas: uniform colour pairs (the filters leave a uniform image as it is
// and find no features, so the error is the remapped HyAB distance, computed
// here in doubles from the published sRGB matrix), a thin line against a
// uniform shift, and the viewing distance.
#include "lpv/reference/Flip.h"
#include "lpv/reference/Accuracy.h"
#include "lpv/reference/Magma.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace {

using namespace lpv::reference;

std::vector<glm::vec3> uniform(int w, int h, glm::vec3 c) {
    return std::vector<glm::vec3>(std::size_t(w) * std::size_t(h), c);
}

std::vector<glm::vec3> randomImage(int w, int h, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<glm::vec3> out(std::size_t(w) * std::size_t(h));
    for (glm::vec3& c : out)
        c = {u(rng), u(rng), u(rng)};
    return out;
}

FlipResult flipOf(const std::vector<glm::vec3>& ref, const std::vector<glm::vec3>& test, int w, int h,
                  double ppd = 0.0) {
    return flip(ImageView{w, h, &ref}, ImageView{w, h, &test}, ppd);
}

// --- The paper's colour pipeline by hand, in doubles. ---
double decode(double v) {
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}
// IEC 61966-2-1's linear sRGB to XYZ (D65), as printed there.
glm::dvec3 toXyz(const glm::dvec3& c) {
    return {0.4124 * c.r + 0.3576 * c.g + 0.1805 * c.b, 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b,
            0.0193 * c.r + 0.1192 * c.g + 0.9505 * c.b};
}
glm::dvec3 huntLabOf(const glm::dvec3& linear) {
    const glm::dvec3 white = toXyz({1.0, 1.0, 1.0});
    const glm::dvec3 t = toXyz(linear) / white;
    auto f = [](double v) {
        return v > 216.0 / 24389.0 ? std::cbrt(v) : (24389.0 / 27.0 * v + 16.0) / 116.0;
    };
    const double L = 116.0 * f(t.y) - 16.0;
    return {L, L / 100.0 * 500.0 * (f(t.x) - f(t.y)), L / 100.0 * 200.0 * (f(t.y) - f(t.z))};
}
double hyabOf(const glm::dvec3& a, const glm::dvec3& b) {
    return std::abs(a.x - b.x) + std::sqrt((a.y - b.y) * (a.y - b.y) + (a.z - b.z) * (a.z - b.z));
}
// The colour error of two uniform sRGB colours: HyAB^qc, remapped with pc, pt.
double expectedUniformError(const glm::dvec3& srgbA, const glm::dvec3& srgbB) {
    auto lab = [](const glm::dvec3& s) { return huntLabOf({decode(s.r), decode(s.g), decode(s.b)}); };
    const double cmax = std::pow(hyabOf(huntLabOf({0, 1, 0}), huntLabOf({0, 0, 1})), 0.7);
    const double d = std::pow(hyabOf(lab(srgbA), lab(srgbB)), 0.7);
    const double knee = 0.4 * cmax;
    return d < knee ? 0.95 / knee * d : 0.95 + (d - knee) / (cmax - knee) * 0.05;
}

TEST(Flip, IdenticalImagesGiveZero) {
    const auto image = randomImage(40, 30, 1);
    const FlipResult r = flipOf(image, image, 40, 30);
    ASSERT_EQ(r.error.size(), 40u * 30u);
    EXPECT_EQ(r.mean, 0.0);
    for (float e : r.error)
        ASSERT_EQ(e, 0.0f);
}

// Both terms compare the two images alike (HyAB and the feature difference
// are distances), so swapping reference and test changes nothing; and every
// pixel's error is in [0, 1].
TEST(Flip, IsSymmetricAndBounded) {
    const auto a = randomImage(48, 32, 2), b = randomImage(48, 32, 3);
    const FlipResult ab = flipOf(a, b, 48, 32), ba = flipOf(b, a, 48, 32);
    EXPECT_GT(ab.mean, 0.1) << "two unrelated noise images differ visibly";
    for (std::size_t i = 0; i < ab.error.size(); ++i) {
        ASSERT_NEAR(ab.error[i], ba.error[i], 1e-5f) << i;
        ASSERT_GE(ab.error[i], 0.0f);
        ASSERT_LE(ab.error[i], 1.0f);
    }
    EXPECT_NEAR(ab.mean, ba.mean, 1e-6);
}

TEST(Flip, UniformColourPairsGiveTheRemappedHyabDistance) {
    const std::pair<glm::dvec3, glm::dvec3> pairs[] = {
        {{0.5, 0.5, 0.5}, {0.55, 0.55, 0.55}}, // small grey step: on the steep first segment
        {{0.2, 0.2, 0.2}, {0.8, 0.8, 0.8}},    // large grey step
        {{0.8, 0.3, 0.2}, {0.8, 0.5, 0.2}},    // hue shift
        {{0.0, 0.0, 0.0}, {1.0, 1.0, 1.0}},    // black and white
        {{0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}},    // green and blue: the largest difference, error 1
    };
    for (const auto& [a, b] : pairs) {
        const auto ref = uniform(24, 20, glm::vec3(a)), test = uniform(24, 20, glm::vec3(b));
        const FlipResult r = flipOf(ref, test, 24, 20);
        const double expected = expectedUniformError(a, b);
        for (std::size_t i = 0; i < r.error.size(); ++i) {
            // (Rounding leaves derivative responses near 1e-8, which the
            // feature term's square root lifts to about 1e-4.)
            ASSERT_LT(r.feature[i], 1e-3f) << "a uniform image has no edges or points";
            ASSERT_NEAR(r.error[i], expected, 2e-3) << a.r << "," << a.g << "," << a.b;
        }
    }
    const auto green = uniform(8, 8, {0, 1, 0}), blue = uniform(8, 8, {0, 0, 1});
    EXPECT_NEAR(flipOf(green, blue, 8, 8).mean, 1.0, 1e-4);
}

// A one-pixel line of a colour is an edge the eye catches; the same colour
// difference spread over the whole image is not. The line's feature term
// raises its error above its (blurred) colour term.
TEST(Flip, AThinLineScoresOnTheFeatureTermAndAUniformShiftDoesNot) {
    const int w = 48, h = 48;
    const auto ref = uniform(w, h, glm::vec3(0.5f));
    auto line = ref;
    for (int y = 0; y < h; ++y)
        line[std::size_t(y) * w + 24] = glm::vec3(0.7f);
    const auto shifted = uniform(w, h, glm::vec3(0.7f));
    const FlipResult l = flipOf(ref, line, w, h), s = flipOf(ref, shifted, w, h);
    const std::size_t at = std::size_t(h / 2) * w + 24;
    EXPECT_GT(l.feature[at], 0.2f);
    EXPECT_LT(s.feature[at], 1e-3f);
    EXPECT_GT(l.error[at], l.colour[at] + 0.05f);
    EXPECT_NEAR(s.error[at], s.colour[at], 1e-3f);
}

// Farther away (more pixels per degree) a thin line is finer than the eye
// resolves: the contrast filters spread it thinner and its error falls
// (the mean need not: the spread reaches more pixels); a uniform shift looks
// the same at any distance.
TEST(Flip, MorePixelsPerDegreeHideFineDetail) {
    const int w = 64, h = 48;
    const auto ref = uniform(w, h, glm::vec3(0.4f));
    auto line = ref;
    for (int y = 0; y < h; ++y)
        line[std::size_t(y) * w + 31] = glm::vec3(0.9f, 0.3f, 0.3f);
    const std::size_t at = std::size_t(h / 2) * w + 31;
    const FlipResult near = flipOf(ref, line, w, h, 30.0), far = flipOf(ref, line, w, h, 120.0);
    EXPECT_GT(near.colour[at], far.colour[at] * 1.2) << near.colour[at] << " vs " << far.colour[at];
    EXPECT_GT(near.error[at], far.error[at]) << near.error[at] << " vs " << far.error[at];
    const auto shifted = uniform(w, h, glm::vec3(0.45f));
    EXPECT_NEAR(flipOf(ref, shifted, w, h, 30.0).mean, flipOf(ref, shifted, w, h, 120.0).mean, 1e-5);
}

TEST(Flip, PixelsPerDegreeOfThePapersSetup) {
    // 0.7 m from a 0.7 m wide 3840-pixel monitor: 3840 pixels span 2 atan(0.5) rad, in the small-angle form
    // 3840 * pi / 180.
    EXPECT_NEAR(defaultPixelsPerDegree(), 3840.0 * 3.14159265358979 / 180.0, 1e-6);
    EXPECT_NEAR(pixelsPerDegree(1.4, 0.7, 3840), 2.0 * defaultPixelsPerDegree(), 1e-9);
}

TEST(Flip, EightBitImagesAreReadAsDisplayValues) {
    lpv::scene::Image8 a{2, 1, 3, {0, 0, 0, 255, 255, 255}}, b{2, 1, 4, {0, 0, 0, 7, 255, 255, 255, 9}};
    const auto va = unitRgb(a), vb = unitRgb(b);
    EXPECT_EQ(va[1], glm::vec3(1.0f));
    EXPECT_EQ(vb[1], glm::vec3(1.0f)) << "alpha is not a colour channel";
    EXPECT_EQ(flip(a, b).mean, 0.0);
}

// Magma is ordered by lightness, so a larger error always shows brighter.
TEST(Magma, GrowsBrighterFromBlackToPaleYellow) {
    const auto& table = magmaTable();
    auto lightness = [](const std::array<std::uint8_t, 3>& c) {
        return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
    };
    for (std::size_t i = 1; i < table.size(); ++i)
        ASSERT_GE(lightness(table[i]) + 0.5, lightness(table[i - 1])) << i;
    EXPECT_LT(lightness(table.front()), 5.0);
    EXPECT_GT(lightness(table.back()), 230.0);
    EXPECT_EQ(magma(-1.0f), table.front());
    EXPECT_EQ(magma(2.0f), table.back());
    EXPECT_EQ(magma(std::nanf("")), table.back());
}

// The figures of the reference's own noise: a noiseless reference has none;
// a noisy one scores its redrawn copy below SSIM 1 and above FLIP 0, and a
// biased image is further from it than its noise.
TEST(Accuracy, ReportsFlipAndTheNoiseOfSsimAndFlip) {
    const int w = 32, h = 24;
    std::vector<glm::vec3> ref(std::size_t(w * h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            ref[std::size_t(y * w + x)] =
                glm::vec3(0.2f + 0.05f * float(x % 8), 0.3f, 0.25f + 0.02f * float(y % 5));
    const std::vector<glm::vec3> noVariance(ref.size(), glm::vec3(0.0f)),
        variance(ref.size(), glm::vec3(0.004f));
    EXPECT_EQ(redrawNoise(ref, noVariance, 5), ref);
    const ImageView view{w, h, &ref};
    const Accuracy same = measureAccuracy(view, view, &variance, nullptr);
    EXPECT_EQ(same.flip, 0.0);
    EXPECT_GT(same.noiseFlip, 0.0);
    EXPECT_LT(same.noiseSsim, 1.0);
    EXPECT_TRUE(same.flipBelowNoise());
    auto biased = ref;
    for (glm::vec3& c : biased)
        c *= 1.8f;
    AccuracyOptions keep;
    keep.keepFlipMap = keep.keepDisplayImages = true;
    const Accuracy off = measureAccuracy({w, h, &biased}, view, &variance, nullptr, keep);
    EXPECT_GT(off.flip, off.noiseFlip);
    EXPECT_FALSE(off.flipBelowNoise());
    ASSERT_EQ(off.flipMap.error.size(), ref.size());
    EXPECT_NEAR(maskedMean(off.flipMap.error, nullptr), off.flip, 1e-9);
    EXPECT_EQ(off.testDisplay.width, w);
    EXPECT_NE(off.testDisplay.pixels, off.referenceDisplay.pixels);
    const Accuracy noiseless = measureAccuracy({w, h, &biased}, view, nullptr, nullptr);
    EXPECT_EQ(noiseless.noiseFlip, 0.0);
    EXPECT_EQ(noiseless.noiseSsim, 1.0);
}

} // namespace
