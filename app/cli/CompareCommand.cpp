// `lpv compare TEST.exr REF.exr`: the error of a renderer image against the
// path-traced reference (reference/Accuracy.h), background masked out, with
// the reference's own noise level beside each figure. Two display images
// (PNG, JPEG) get FLIP alone, as the FLIP authors' tool reports it, so
// published image pairs can be checked with the same code.
#include "Cli.h"
#include "lpv/bench/ContentHash.h"
#include "lpv/bench/ReferenceFile.h"

#include "lpv/importers/ImageIO.h"
#include "lpv/reference/Accuracy.h"
#include "lpv/reference/Magma.h"

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <iostream>

namespace lpv::cli {

void printCompareHelp() {
    std::cout << R"(Usage: lpv compare TEST.exr REF.exr [--layer image|indirect|indirect1] [--json]
                   [--ppd N] [--flip-map FILE.png]
       lpv compare TEST.png REF.png [--json] [--ppd N] [--flip-map FILE.png]

Measures TEST (an EXR from `lpv render`, R,G,B) against REF (an EXR from
`lpv reference` at the same size and camera) on luminance, over the pixels
where the reference sees geometry (the background and sky are masked out):
  relMSE  mean (t - r)^2 / (r^2 + eps^2), eps = 1% of the mean reference
  MARE    mean |t - r| / (r + eps)
  SSIM    structural similarity of the tone-mapped luminance (1 = identical)
  FLIP    the error a viewer sees flipping between the two images on a
          monitor (Andersson et al. 2020, LDR-FLIP; 0 = identical, 1 = the
          largest), averaged over the same pixels. It is measured on the
          images as displayed: both mapped with one exposure, x / (x + key)
          per channel and gamma 2.2, key = the reference's mean luminance
          (as `lpv reference --preview` shows it).
Each error is printed with what the reference's own noise alone would give
(for SSIM and FLIP: the reference against a copy with its noise drawn
again); an error at or below it is reported as "below noise" (trace more
samples to resolve it).

Two display images (PNG, JPEG, ... anything but EXR: sRGB values as stored)
are compared with FLIP alone, over every pixel, as the FLIP authors' tool
does; REF is the reference.

  --layer NAME  Reference layer to compare with: image (full image),
                indirect (multi-bounce indirect irradiance) or indirect1
                (one bounce). Default: indirect when TEST was rendered with
                output.view=indirect, image otherwise.
  --json        Print the figures as one JSON object
  --ppd N       FLIP's pixels per degree of visual angle (default 67.0: the
                paper's 0.7 m from a 0.7 m wide 3840-pixel monitor)
  --flip-map FILE.png
                Write the FLIP error per pixel as a heat map (magma: black
                = no error, yellow = the largest)
)";
}

namespace {

bool isExr(const std::string& file) {
    std::string ext = std::filesystem::path(file).extension().string();
    for (char& c : ext)
        c = char(std::tolower(static_cast<unsigned char>(c)));
    return ext == ".exr";
}

bool writeFlipMap(const std::string& file, const reference::FlipResult& map) {
    if (auto ok = importers::writeImage(file, reference::magmaImage(map.error, map.width, map.height)); !ok) {
        std::cerr << "lpv: " << ok.error().describe() << "\n";
        return false;
    }
    return true;
}

// Two display images: FLIP alone, over every pixel.
int compareDisplayImages(const std::string& testFile, const std::string& refFile, double ppd, bool json,
                         const std::optional<std::string>& flipMap) {
    auto test = importers::readImage8(testFile);
    if (!test) {
        std::cerr << "lpv: " << test.error().describe() << "\n";
        return kFailure;
    }
    auto ref = importers::readImage8(refFile);
    if (!ref) {
        std::cerr << "lpv: " << ref.error().describe() << "\n";
        return kFailure;
    }
    if (test->width != ref->width || test->height != ref->height) {
        std::cerr << "lpv: " << testFile << " is " << test->width << "x" << test->height << " but " << refFile
                  << " is " << ref->width << "x" << ref->height << ": FLIP compares images of one size\n";
        return kFailure;
    }
    const reference::FlipResult r = reference::flip(*ref, *test, ppd);
    if (flipMap && !writeFlipMap(*flipMap, r))
        return kFailure;
    if (json)
        std::printf("{\"pixels\": %zu, \"flip\": %.6f, \"ppd\": %.4f}\n", r.error.size(), r.mean, ppd);
    else
        std::printf("%s vs %s (%dx%d, %.1f pixels per degree)\nFLIP %.6f\n", testFile.c_str(),
                    refFile.c_str(), r.width, r.height, ppd, r.mean);
    return kOk;
}

} // namespace

int runCompare(Args args) {
    const auto layerText = args.choice("--layer", {"image", "indirect", "indirect1"});
    const bool json = args.flag("--json");
    // Pixels per degree: FLIP's viewing distance; beyond 10,000 a pixel is smaller than any eye resolves.
    const double ppd = args.real("--ppd", reference::defaultPixelsPerDegree(), {0.0, 1e4, true, true});
    const auto flipMap = args.option("--flip-map");
    const auto pos = args.expectPositionals(2, "expected TEST and REF images");
    if (pos.empty())
        return usageError(*args.error(), "compare");
    if (isExr(pos[0]) != isExr(pos[1]))
        return usageError(
            "compare two EXR images (renderer and reference) or two display images, not one of each",
            "compare");
    if (!isExr(pos[0])) {
        if (layerText)
            return usageError("--layer needs a reference EXR", "compare");
        return compareDisplayImages(pos[0], pos[1], ppd, json, flipMap);
    }
    auto test = bench::readRgbExr(pos[0]);
    if (!test) {
        std::cerr << "lpv: " << test.error().describe() << "\n";
        return kFailure;
    }
    auto ref = bench::readReferenceExr(pos[1]);
    if (!ref) {
        std::cerr << "lpv: " << ref.error().describe() << "\n";
        return kFailure;
    }
    const reference::ReferenceImage& r = ref->image;
    if (test->width != r.width || test->height != r.height) {
        std::cerr << "lpv: " << pos[0] << " is " << test->width << "x" << test->height << " but " << pos[1]
                  << " is " << r.width << "x" << r.height
                  << ": render both at the same --width and --height\n";
        return kFailure;
    }
    if (test->outputView == "direct" && !layerText) {
        std::cerr
            << "lpv: " << pos[0]
            << " shows direct light only; the reference has no direct-only layer (give --layer to compare "
               "anyway)\n";
        return kFailure;
    }
    const std::string layer = layerText.value_or(test->outputView == "indirect" ? "indirect" : "image");
    const auto& pixels = layer == "image" ? r.image : layer == "indirect" ? r.indirectMulti : r.indirectOne;
    const auto& variance = layer == "image"      ? r.imageVariance
                           : layer == "indirect" ? r.indirectMultiVariance
                                                 : r.indirectOneVariance;
    reference::AccuracyOptions options;
    options.pixelsPerDegree = ppd;
    options.keepFlipMap = flipMap.has_value();
    const reference::Accuracy a =
        reference::measureAccuracy({test->width, test->height, &test->pixels}, {r.width, r.height, &pixels},
                                   &variance, &r.coverage, options);
    if (flipMap && !writeFlipMap(*flipMap, a.flipMap))
        return kFailure;
    const reference::ErrorMetrics& m = a.metrics;
    if (json) {
        std::printf(
            "{\"layer\": \"%s\", \"pixels\": %zu, \"relMse\": %.6g, \"noiseRelMse\": %.6g, \"mare\": %.6g, "
            "\"noiseMare\": %.6g, \"ssim\": %.6g, \"meanTest\": %.6g, \"meanReference\": %.6g, "
            "\"relMseBelowNoise\": %s, \"mareBelowNoise\": %s, \"referenceSpp\": %d, \"noiseSsim\": %.6g, "
            "\"flip\": %.6g, \"noiseFlip\": %.6g, \"ppd\": %.4f}\n",
            layer.c_str(), m.pixels, m.relMse, m.noiseRelMse, m.mare, m.noiseMare, m.ssim, m.meanTest,
            m.meanReference, m.relMseBelowNoise() ? "true" : "false", m.mareBelowNoise() ? "true" : "false",
            r.samplesPerPixel, a.noiseSsim, a.flip, a.noiseFlip, ppd);
    } else {
        std::printf("%s vs %s (layer %s, %zu pixels, reference %d spp)\n", pos[0].c_str(), pos[1].c_str(),
                    layer.c_str(), m.pixels, r.samplesPerPixel);
        std::printf("%s\n", reference::describe(m).c_str());
        std::printf(
            "SSIM noise %.3f; FLIP %.4f (noise %.4f%s, %.1f pixels per degree, display mapping key %.4g)\n",
            a.noiseSsim, a.flip, a.noiseFlip, a.flipBelowNoise() ? ", below noise" : "", ppd, a.key);
    }
    return kOk;
}

} // namespace lpv::cli
