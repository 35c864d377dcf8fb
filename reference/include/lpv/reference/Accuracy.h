#pragma once
// Every figure `lpv compare` and the editor's Accuracy dock report for a
// renderer's HDR image against the path-traced reference, measured alike:
// MARE, relMSE and SSIM on linear luminance (Metrics.h), FLIP (Flip.h) on
// the two images as a display shows them, both mapped with one exposure
// (Preview.h, keyed on the reference), and beside each the figure the
// reference's own noise alone would cause.
#include "lpv/reference/Flip.h"
#include "lpv/reference/Metrics.h"
#include "lpv/scene/Image.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace lpv::reference {

struct AccuracyOptions {
    double pixelsPerDegree = 0.0; // FLIP's viewing setup; <= 0: the paper's 67 ppd
    bool keepFlipMap = false;     // keep the per-pixel FLIP error (the heat map)
    bool keepDisplayImages = false;
    // The noise copy's random numbers: fixed, so the same two images give the same figures.
    std::uint32_t noiseSeed = 1;
};

struct Accuracy {
    ErrorMetrics metrics; // relMSE, MARE, SSIM, with the noise figures of relMSE and MARE
    double flip = 0.0;    // mean FLIP over the kept pixels, 0 = identical
    // SSIM and FLIP have no closed form for the noise: these are the figures
    // of the reference against a copy of itself with its noise drawn again
    // (each pixel plus a normal sample of its variance). A test image at or
    // past them is as close as this reference can tell.
    double noiseSsim = 1.0;
    double noiseFlip = 0.0;
    float key = 1.0f;   // the exposure key both display images share (mean reference luminance)
    FlipResult flipMap; // when keepFlipMap: per pixel error, 0..1
    scene::Image8 testDisplay, referenceDisplay; // when keepDisplayImages: what FLIP compared
    bool flipBelowNoise() const { return flip <= noiseFlip; }
    bool ssimBelowNoise() const { return ssim() >= noiseSsim; }
    double ssim() const { return metrics.ssim; }
};

// `test` and `reference` are linear HDR (rows top to bottom, the same size);
// `variance` the variance of the reference's per-pixel mean (null: none);
// `mask` keeps the pixels > 0.5 (null: every pixel).
Accuracy measureAccuracy(const ImageView& test, const ImageView& reference,
                         const std::vector<glm::vec3>* variance, const std::vector<float>* mask,
                         const AccuracyOptions& options = {});

// The reference with its noise drawn again: each channel plus sigma * N(0, 1)
// with sigma^2 the variance of its mean, negative values clamped to 0.
std::vector<glm::vec3> redrawNoise(const std::vector<glm::vec3>& reference,
                                   const std::vector<glm::vec3>& variance, std::uint32_t seed);

} // namespace lpv::reference
