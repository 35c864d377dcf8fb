#pragma once
// LDR-FLIP (Andersson, Nilsson, Akenine-Moeller, Oskarsson, Astroem,
// Fairchild, "FLIP: A Difference Evaluator for Alternating Images", HPG 2020):
// the error a viewer sees when flipping between a reference and a test image
// on a monitor, per pixel in [0, 1]. Written from the paper (docs/reference.md
// says how it was checked against the authors' published figures).
//
// Two terms, both from what the eye does:
// - colour: each image in the opponent space YCxCz is blurred by the
//   contrast sensitivity of each channel (fine detail the eye cannot resolve
//   at this distance does not count), then compared in a Hunt-adjusted
//   L*a*b* with the HyAB distance, and the distance is remapped so that small
//   differences fill most of [0, 0.95] and the largest (green against blue)
//   reaches 1;
// - features: edges and points (first and second Gaussian derivatives of the
//   luminance, at the scale of the eye's resolution) that differ between the
//   images raise the colour error towards 1 (e = colour^(1 - feature)).
#include "lpv/reference/Metrics.h"
#include "lpv/scene/Image.h"

#include <glm/glm.hpp>

#include <vector>

namespace lpv::reference {

// The paper's constants (section 4), named as there.
struct FlipConstants {
    static constexpr double qc = 0.7;  // exponent on the HyAB colour distance
    static constexpr double pc = 0.4;  // fraction of the largest distance mapped onto [0, pt]
    static constexpr double pt = 0.95; // error at that fraction
    static constexpr double w = 0.082; // feature width in degrees (Gaussian sigma = w / 2)
    static constexpr double qf = 0.5;  // exponent on the feature difference
};

// Pixels per degree of visual angle for a viewer `distance` metres from a
// monitor `monitorWidth` metres wide that shows `monitorPixels` across.
double pixelsPerDegree(double distance, double monitorWidth, int monitorPixels);
// The paper's viewing setup: 0.7 m from a 0.7 m wide 3840-pixel monitor (about 67 ppd).
double defaultPixelsPerDegree();

struct FlipResult {
    int width = 0;
    int height = 0;
    std::vector<float> error;   // per pixel, 0..1 (rows top to bottom)
    std::vector<float> colour;  // the colour term after the remapping, 0..1
    std::vector<float> feature; // the feature term, 0..1
    double mean = 0.0;          // mean error over every pixel (the figure FLIP reports)
};

// `reference` and `test` hold display values (sRGB-encoded, 0..1; values
// outside are clamped), the same size. ppd <= 0 means defaultPixelsPerDegree().
FlipResult flip(const ImageView& reference, const ImageView& test, double ppd = 0.0);
// The same on 8-bit images (RGB or RGBA; alpha is ignored).
FlipResult flip(const scene::Image8& reference, const scene::Image8& test, double ppd = 0.0);

// Display values 0..1 of an 8-bit image (1, 2, 3 or 4 channels: grey is spread to RGB).
std::vector<glm::vec3> unitRgb(const scene::Image8& image);
// Mean of `values` over the pixels where `mask` > 0.5 (every pixel without a
// mask); 0 when none is kept.
double maskedMean(const std::vector<float>& values, const std::vector<float>* mask);

} // namespace lpv::reference
