#include "lpv/reference/Metrics.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdio>

namespace lpv::reference {

float luminance(const glm::vec3& c) {
    return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b;
}

namespace {

bool kept(const std::vector<float>* mask, std::size_t i) {
    return !mask || (*mask)[i] > 0.5f;
}

// Separable Gaussian blur (sigma 1.5, radius 5) of `v`, the SSIM window.
std::vector<double> blur(const std::vector<double>& v, int w, int h) {
    constexpr int r = 5;
    double k[2 * r + 1];
    double sum = 0.0;
    for (int i = -r; i <= r; ++i)
        sum += k[i + r] = std::exp(-double(i * i) / (2.0 * 1.5 * 1.5));
    for (double& x : k)
        x /= sum;
    std::vector<double> tmp(v.size()), out(v.size());
    // Edges clamp: the window's weights stay normalised at the border.
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double a = 0.0;
            for (int i = -r; i <= r; ++i)
                a += k[i + r] * v[std::size_t(y) * std::size_t(w) + std::size_t(std::clamp(x + i, 0, w - 1))];
            tmp[std::size_t(y) * std::size_t(w) + std::size_t(x)] = a;
        }
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double a = 0.0;
            for (int i = -r; i <= r; ++i)
                a += k[i + r] *
                     tmp[std::size_t(std::clamp(y + i, 0, h - 1)) * std::size_t(w) + std::size_t(x)];
            out[std::size_t(y) * std::size_t(w) + std::size_t(x)] = a;
        }
    return out;
}

} // namespace

double ssimLuminance(const std::vector<float>& a, const std::vector<float>& b, int width, int height,
                     const std::vector<float>* mask) {
    const std::size_t n = std::size_t(width) * std::size_t(height);
    double meanB = 0.0;
    std::size_t count = 0;
    for (std::size_t i = 0; i < n; ++i)
        if (kept(mask, i)) {
            meanB += b[i];
            ++count;
        }
    if (count == 0)
        return 1.0;
    meanB = std::max(meanB / double(count), 1e-20);
    std::vector<double> x(n), y(n), xx(n), yy(n), xy(n);
    for (std::size_t i = 0; i < n; ++i) {
        // Reinhard with the reference's mean as key: HDR into 0..1 for SSIM's constants.
        x[i] = std::max(double(a[i]), 0.0) / (std::max(double(a[i]), 0.0) + meanB);
        y[i] = std::max(double(b[i]), 0.0) / (std::max(double(b[i]), 0.0) + meanB);
        if (!std::isfinite(x[i]))
            x[i] = 1.0;
        xx[i] = x[i] * x[i];
        yy[i] = y[i] * y[i];
        xy[i] = x[i] * y[i];
    }
    const auto mx = blur(x, width, height), my = blur(y, width, height);
    const auto sxx = blur(xx, width, height), syy = blur(yy, width, height), sxy = blur(xy, width, height);
    constexpr double c1 = 0.01 * 0.01, c2 = 0.03 * 0.03;
    double total = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        if (!kept(mask, i))
            continue;
        const double vx = std::max(sxx[i] - mx[i] * mx[i], 0.0), vy = std::max(syy[i] - my[i] * my[i], 0.0);
        const double cov = sxy[i] - mx[i] * my[i];
        total += ((2.0 * mx[i] * my[i] + c1) * (2.0 * cov + c2)) /
                 ((mx[i] * mx[i] + my[i] * my[i] + c1) * (vx + vy + c2));
    }
    return total / double(count);
}

ErrorMetrics compareImages(const ImageView& test, const ImageView& reference,
                           const std::vector<glm::vec3>* referenceVariance, const std::vector<float>* mask,
                           const MetricOptions& options) {
    assert(test.width == reference.width && test.height == reference.height);
    const std::size_t n = std::size_t(reference.width) * std::size_t(reference.height);
    std::vector<float> yt(n), yr(n);
    double meanRef = 0.0;
    ErrorMetrics m;
    for (std::size_t i = 0; i < n; ++i) {
        yt[i] = luminance((*test.pixels)[i]);
        yr[i] = luminance((*reference.pixels)[i]);
        if (kept(mask, i)) {
            meanRef += yr[i];
            ++m.pixels;
        }
    }
    if (m.pixels == 0)
        return m;
    meanRef /= double(m.pixels);
    const double eps = std::max(double(options.epsilonFraction) * meanRef, 1e-20);
    for (std::size_t i = 0; i < n; ++i) {
        if (!kept(mask, i))
            continue;
        // A non-finite test pixel is as wrong as can be: it counts as 100% off, not as NaN.
        const double t = std::isfinite(yt[i]) ? double(yt[i]) : 0.0;
        const double r = yr[i];
        const double d = t - r;
        m.meanTest += t;
        m.relMse += d * d / (r * r + eps * eps);
        m.mare += std::abs(d) / (std::abs(r) + eps);
        double sigma = 0.0;
        if (referenceVariance) {
            // Channels of one path are correlated: sigma_Y <= sum w_c sigma_c, taken as the noise.
            const glm::vec3 v = glm::max((*referenceVariance)[i], glm::vec3(0.0f));
            sigma = 0.2126 * std::sqrt(v.r) + 0.7152 * std::sqrt(v.g) + 0.0722 * std::sqrt(v.b);
            m.noiseRelMse += sigma * sigma / (r * r + eps * eps);
            m.noiseMare += std::sqrt(2.0 / 3.14159265358979) * sigma / (std::abs(r) + eps);
        }
        // The log ratio's floor follows the reference's noise where it is
        // larger: a noisy dark pixel cannot tell 0 from its noise.
        const double floor = std::max(eps, sigma);
        m.logError += std::abs(std::log((std::max(t, 0.0) + floor) / (std::max(r, 0.0) + floor)));
        m.noiseLogError += std::sqrt(2.0 / 3.14159265358979) * sigma / (std::max(r, 0.0) + floor);
    }
    const double count = double(m.pixels);
    m.meanTest /= count;
    m.meanReference = meanRef;
    m.relMse /= count;
    m.mare /= count;
    m.logError /= count;
    m.noiseLogError /= count;
    m.noiseRelMse /= count;
    m.noiseMare /= count;
    if (options.ssim)
        m.ssim = ssimLuminance(yt, yr, reference.width, reference.height, mask);
    return m;
}

std::string describe(const ErrorMetrics& m) {
    char text[400];
    std::snprintf(text, sizeof text,
                  "relMSE %.4g (reference noise %.2g%s), MARE %.2f%% (noise %.2f%%%s), symmetric %.2f%% (noise "
                  "%.2f%%%s), SSIM %.4f, mean %.4g (reference %.4g)",
                  m.relMse, m.noiseRelMse, m.relMseBelowNoise() ? ", below noise" : "", 100.0 * m.mare,
                  100.0 * m.noiseMare, m.mareBelowNoise() ? ", below noise" : "", 100.0 * m.symmetricError(),
                  100.0 * m.noiseSymmetricError(), m.symmetricBelowNoise() ? ", below noise" : "", m.ssim,
                  m.meanTest, m.meanReference);
    return text;
}

} // namespace lpv::reference
