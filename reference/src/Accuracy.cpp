#include "lpv/reference/Accuracy.h"

#include "lpv/reference/Preview.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace lpv::reference {

namespace {

std::vector<glm::vec3> displayValues(const scene::Image8& image) {
    return unitRgb(image);
}

// FLIP of two HDR images through one display mapping, averaged over the mask.
FlipResult displayFlip(const ImageView& test, const ImageView& reference, float key, double ppd,
                       scene::Image8* testOut, scene::Image8* referenceOut) {
    const int w = reference.width, h = reference.height;
    scene::Image8 t = previewImage(*test.pixels, w, 0, 0, w, h, key);
    scene::Image8 r = previewImage(*reference.pixels, w, 0, 0, w, h, key);
    const std::vector<glm::vec3> tv = displayValues(t), rv = displayValues(r);
    FlipResult result = flip(ImageView{w, h, &rv}, ImageView{w, h, &tv}, ppd);
    if (testOut)
        *testOut = std::move(t);
    if (referenceOut)
        *referenceOut = std::move(r);
    return result;
}

} // namespace

std::vector<glm::vec3> redrawNoise(const std::vector<glm::vec3>& reference,
                                   const std::vector<glm::vec3>& variance, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::normal_distribution<float> normal(0.0f, 1.0f);
    std::vector<glm::vec3> out(reference.size());
    for (std::size_t i = 0; i < reference.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const float sigma = i < variance.size() ? std::sqrt(std::max(variance[i][c], 0.0f)) : 0.0f;
            out[i][c] = std::max(0.0f, reference[i][c] + sigma * normal(rng));
        }
    return out;
}

Accuracy measureAccuracy(const ImageView& test, const ImageView& reference,
                         const std::vector<glm::vec3>* variance, const std::vector<float>* mask,
                         const AccuracyOptions& options) {
    Accuracy a;
    a.metrics = compareImages(test, reference, variance, mask);
    // One exposure for both images, from the reference: the renderer's own
    // auto exposure would hide a global bias that FLIP should see.
    a.key = meanLuminance(*reference.pixels, mask ? *mask : std::vector<float>{});
    FlipResult map = displayFlip(test, reference, a.key, options.pixelsPerDegree,
                                 options.keepDisplayImages ? &a.testDisplay : nullptr,
                                 options.keepDisplayImages ? &a.referenceDisplay : nullptr);
    a.flip = maskedMean(map.error, mask);
    if (options.keepFlipMap)
        a.flipMap = std::move(map);
    if (variance && !variance->empty()) {
        const std::vector<glm::vec3> copy = redrawNoise(*reference.pixels, *variance, options.noiseSeed);
        const ImageView copyView{reference.width, reference.height, &copy};
        std::vector<float> copyLum, refLum;
        for (std::size_t i = 0; i < copy.size(); ++i) {
            copyLum.push_back(luminance(copy[i]));
            refLum.push_back(luminance((*reference.pixels)[i]));
        }
        a.noiseSsim = ssimLuminance(copyLum, refLum, reference.width, reference.height, mask);
        a.noiseFlip = maskedMean(
            displayFlip(copyView, reference, a.key, options.pixelsPerDegree, nullptr, nullptr).error, mask);
    }
    return a;
}

} // namespace lpv::reference
