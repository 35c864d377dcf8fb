#pragma once
// Error of a renderer image against the path-traced reference, on luminance:
// relative MSE, mean absolute relative error, and SSIM (a perceptual metric)
// on tone-mapped luminance, over the pixels a mask keeps (background and sky
// left out). Each is reported next to the error the reference's own noise
// alone would cause, so an error below the noise is reported as such.
#include <glm/glm.hpp>

#include <cmath>

#include <string>
#include <vector>

namespace lpv::reference {

struct ImageView {
    int width = 0;
    int height = 0;
    const std::vector<glm::vec3>* pixels = nullptr; // rows top to bottom
};

struct MetricOptions {
    // Added to the reference in the denominators, as a fraction of the mean
    // reference luminance, so near-black pixels do not dominate.
    float epsilonFraction = 0.01f;
    // SSIM blurs five images: off where only the other figures are wanted
    // (the editor's live reference asks its own noise every pass); ssim stays 1.
    bool ssim = true;
};

struct ErrorMetrics {
    std::size_t pixels = 0; // pixels compared (mask > 0.5)
    double relMse = 0.0;    // mean (t - r)^2 / (r^2 + eps^2)
    double mare = 0.0;      // mean |t - r| / (r + eps)
    // Symmetric in too dark and too bright (issue #43): mean |ln((t + e) / (r + e))|
    // with e = max(eps, the reference pixel's noise). Half and twice the
    // reference both give ln 2, where MARE gives 50% and 100%: a dark image
    // no longer scores better than a bright one that is as far off.
    double logError = 0.0;
    double ssim = 1.0;      // mean SSIM over kept pixels, 1 = identical
    // Mean luminance of each image over the kept pixels: their ratio shows a
    // global bias (a missing pi or albedo, an intensity setting) at a glance.
    double meanTest = 0.0;
    double meanReference = 0.0;
    // What the reference's noise alone contributes (0 for a noiseless reference).
    double noiseRelMse = 0.0; // mean sigma^2 / (r^2 + eps^2)
    double noiseMare = 0.0;   // mean sqrt(2/pi) sigma / (r + eps): E|N(0, sigma)|
    double noiseLogError = 0.0; // mean sqrt(2/pi) sigma / (r + e): logError's first-order noise share
    // relMse minus the noise's expected share (the bias the test image has), >= 0.
    double relMseDenoised() const { return relMse > noiseRelMse ? relMse - noiseRelMse : 0.0; }
    bool relMseBelowNoise() const { return relMse <= noiseRelMse; }
    bool mareBelowNoise() const { return mare <= noiseMare; }
    // logError as a factor off, in percent of the reference: exp(logError) - 1
    // (1.0 = on average a factor of 2 too dark or too bright).
    double symmetricError() const { return std::expm1(logError); }
    double noiseSymmetricError() const { return std::expm1(noiseLogError); }
    bool symmetricBelowNoise() const { return logError <= noiseLogError; }
};

float luminance(const glm::vec3& c);

// `referenceVariance` is the variance of the reference's per-pixel mean
// (may be null: a noiseless reference); `mask` weights 0/1 per pixel (may be
// null: every pixel). All images must have the same size.
ErrorMetrics compareImages(const ImageView& test, const ImageView& reference,
                           const std::vector<glm::vec3>* referenceVariance, const std::vector<float>* mask,
                           const MetricOptions& options = {});

// SSIM of two luminance images mapped by x / (x + m) with m the mean of `b`
// (so HDR values fall into 0..1), 11x11 Gaussian window (sigma 1.5), averaged over
// the mask. Exposed for tests.
double ssimLuminance(const std::vector<float>& a, const std::vector<float>& b, int width, int height,
                     const std::vector<float>* mask);

// "relMSE 0.0123 (noise 0.0004), MARE 8.1% (noise 1.2%), SSIM 0.912, mean 0.95x the reference"
// with "below noise" where it is.
std::string describe(const ErrorMetrics& m);

} // namespace lpv::reference
