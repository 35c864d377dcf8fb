#include "lpv/reference/Flicker.h"

#include "lpv/reference/Metrics.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

namespace lpv::reference {

namespace {

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

bool hasGeometry(const FlickerFrame& f, std::size_t i) {
    return finite((*f.position)[i]) && glm::dot((*f.normal)[i], (*f.normal)[i]) > 0.25f;
}

[[maybe_unused]] std::size_t pixelCount(const FlickerFrame& f) { // for the asserts
    return std::size_t(f.width) * std::size_t(f.height);
}

} // namespace

FlickerResult measureFlicker(const FlickerFrame& previous, const FlickerFrame& current,
                             const FlickerOptions& options) {
    assert(previous.indirect && previous.position && previous.normal);
    assert(current.indirect && current.position && current.normal);
    assert(previous.indirect->size() == pixelCount(previous) &&
           current.indirect->size() == pixelCount(current));
    FlickerResult result;
    struct Pair {
        double now, before;
    };
    std::vector<Pair> pairs;
    for (int y = 0; y < current.height; ++y)
        for (int x = 0; x < current.width; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(current.width) + std::size_t(x);
            if (!hasGeometry(current, i))
                continue;
            ++result.candidates;
            const glm::vec3 p = (*current.position)[i];
            const glm::vec4 clip = previous.viewProjection * glm::vec4(p, 1.0f);
            if (clip.w <= 0.0f)
                continue; // behind the previous camera
            const glm::vec2 ndc = glm::vec2(clip) / clip.w;
            const int px = int(std::floor((ndc.x * 0.5f + 0.5f) * float(previous.width)));
            const int py = int(std::floor((0.5f - ndc.y * 0.5f) * float(previous.height)));
            if (px < 0 || py < 0 || px >= previous.width || py >= previous.height)
                continue; // outside the previous frame
            const std::size_t j = std::size_t(py) * std::size_t(previous.width) + std::size_t(px);
            if (!hasGeometry(previous, j))
                continue;
            const float distance = glm::length(p - current.cameraPosition);
            if (glm::length((*previous.position)[j] - p) > options.positionTolerance * distance)
                continue; // another surface was in front (disocclusion) or the silhouette moved
            if (glm::dot((*previous.normal)[j], (*current.normal)[i]) < options.normalCosTolerance)
                continue;
            pairs.push_back(
                {double(luminance((*current.indirect)[i])), double(luminance((*previous.indirect)[j]))});
        }
    result.pixels = pairs.size();
    if (pairs.empty())
        return result;
    double mean = 0.0;
    for (const Pair& pr : pairs)
        mean += 0.5 * (pr.now + pr.before);
    mean /= double(pairs.size());
    result.meanLuminance = mean;
    const double eps = double(options.epsilonFraction) * mean;
    std::vector<double> change;
    change.reserve(pairs.size());
    for (const Pair& pr : pairs) {
        const double denominator = 0.5 * (pr.now + pr.before) + eps;
        change.push_back(denominator > 0.0 ? std::abs(pr.now - pr.before) / denominator : 0.0);
    }
    double sum = 0.0;
    for (double c : change)
        sum += c;
    result.meanRelativeChange = sum / double(change.size());
    const std::size_t k = std::min(change.size() - 1, std::size_t(0.95 * double(change.size())));
    std::nth_element(change.begin(), change.begin() + std::ptrdiff_t(k), change.end());
    result.p95RelativeChange = change[k];
    return result;
}

std::vector<glm::vec3> positionsFromDepth(const std::vector<float>& depth, int width, int height,
                                          const glm::mat4& inverseViewProjection) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    std::vector<glm::vec3> out(std::size_t(width) * std::size_t(height), glm::vec3(nan));
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(width) + std::size_t(x);
            const float d = depth[i];
            if (!(d < 1.0f))
                continue; // background (or NaN)
            const glm::vec4 ndc((float(x) + 0.5f) / float(width) * 2.0f - 1.0f,
                                1.0f - (float(y) + 0.5f) / float(height) * 2.0f, d * 2.0f - 1.0f, 1.0f);
            const glm::vec4 w = inverseViewProjection * ndc;
            out[i] = glm::vec3(w) / w.w;
        }
    return out;
}

} // namespace lpv::reference
