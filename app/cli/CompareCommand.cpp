// `lpv compare TEST.exr REF.exr`: the error of a renderer image against the
// path-traced reference (reference/Metrics.h), background masked out, with
// the reference's own noise level beside each figure.
#include "Cli.h"
#include "ReferenceFile.h"

#include "lpv/reference/Metrics.h"

#include <cstdio>
#include <iostream>

namespace lpv::cli {

void printCompareHelp() {
    std::cout << R"(Usage: lpv compare TEST.exr REF.exr [--layer image|indirect|indirect1] [--json]

Measures TEST (an EXR from `lpv render`, R,G,B) against REF (an EXR from
`lpv reference` at the same size and camera) on luminance, over the pixels
where the reference sees geometry (the background and sky are masked out):
  relMSE  mean (t - r)^2 / (r^2 + eps^2), eps = 1% of the mean reference
  MARE    mean |t - r| / (r + eps)
  SSIM    structural similarity of the tone-mapped luminance (1 = identical)
Each error is printed with what the reference's own noise alone would give;
an error at or below it is reported as "below noise" (trace more samples to
resolve it).

  --layer NAME  Reference layer to compare with: image (full image),
                indirect (multi-bounce indirect irradiance) or indirect1
                (one bounce). Default: indirect when TEST was rendered with
                output.view=indirect, image otherwise.
  --json        Print the figures as one JSON object
)";
}

int runCompare(Args args) {
    const auto layerText = args.option("--layer");
    const bool json = args.flag("--json");
    if (!args.missingValue().empty())
        return usageError(args.missingValue() + " needs a value", "compare");
    if (auto unknown = args.unknownOption())
        return usageError("unknown option '" + *unknown + "'", "compare");
    const auto pos = args.positionals();
    if (pos.size() != 2)
        return usageError("expected TEST.exr and REF.exr", "compare");
    if (layerText && *layerText != "image" && *layerText != "indirect" && *layerText != "indirect1")
        return usageError("--layer must be image, indirect or indirect1", "compare");
    auto test = readRgbExr(pos[0]);
    if (!test) {
        std::cerr << "lpv: " << test.error().describe() << "\n";
        return kFailure;
    }
    auto ref = readReferenceExr(pos[1]);
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
    const reference::ErrorMetrics m = reference::compareImages(
        {test->width, test->height, &test->pixels}, {r.width, r.height, &pixels}, &variance, &r.coverage);
    if (json) {
        std::printf(
            "{\"layer\": \"%s\", \"pixels\": %zu, \"relMse\": %.6g, \"noiseRelMse\": %.6g, \"mare\": %.6g, "
            "\"noiseMare\": %.6g, \"ssim\": %.6g, \"meanTest\": %.6g, \"meanReference\": %.6g, "
            "\"relMseBelowNoise\": %s, \"mareBelowNoise\": %s, \"referenceSpp\": %d}\n",
            layer.c_str(), m.pixels, m.relMse, m.noiseRelMse, m.mare, m.noiseMare, m.ssim, m.meanTest,
            m.meanReference, m.relMseBelowNoise() ? "true" : "false", m.mareBelowNoise() ? "true" : "false",
            r.samplesPerPixel);
    } else {
        std::printf("%s vs %s (layer %s, %zu pixels, reference %d spp)\n", pos[0].c_str(), pos[1].c_str(),
                    layer.c_str(), m.pixels, r.samplesPerPixel);
        std::printf("%s\n", reference::describe(m).c_str());
    }
    return kOk;
}

} // namespace lpv::cli
