#include "lpv/renderer/AutoExposure.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lpv::renderer {

int meterBin(float value) {
    // Float arithmetic, as the shader does it, so that both put a pixel in the same bin.
    const float position = (std::log2(value) - kMeterMinLog2) * kMeterBinsPerEv;
    return std::clamp(int(std::floor(position)), 0, kMeterBins - 1);
}

LuminanceMeter meterLuminance(const float* pixels, std::size_t pixelCount, int channels) {
    LuminanceMeter m;
    for (std::size_t i = 0; i < pixelCount; ++i) {
        const float* p = pixels + i * std::size_t(channels);
        const float l = luminance(p[0], p[1], p[2]);
        if (l > kMeterMinLuminance && !std::isinf(l)) { // NaN fails the comparison
            m.sumLog += std::log(double(l));
            m.lit += 1.0;
            ++m.histogram[std::size_t(meterBin(std::max({p[0], p[1], p[2]})))];
        }
    }
    return m;
}

double highlightPercentile(const LuminanceMeter& meter, double percent) {
    double total = 0.0;
    for (const std::uint32_t n : meter.histogram)
        total += double(n);
    if (total < 1.0)
        return 0.0;
    const double wanted = total * std::clamp(percent, 0.0, 100.0) / 100.0;
    double below = 0.0;
    for (int b = 0; b < kMeterBins; ++b) {
        const double n = double(meter.histogram[std::size_t(b)]);
        if (n > 0.0 && below + n >= wanted) {
            const double within = std::clamp((wanted - below) / n, 0.0, 1.0);
            return std::exp2(double(kMeterMinLog2) + (double(b) + within) / double(kMeterBinsPerEv));
        }
        below += n;
    }
    return 0.0; // not reached: the last non-empty bin holds the 100th percentile
}

double targetLogExposure(const LuminanceMeter& meter, const MeterTarget& target) {
    if (meter.lit < 1.0)
        return 0.0;
    const double limit = kMeterMaxEv * std::numbers::ln2;
    double logExposure = std::log(target.key) - meter.sumLog / meter.lit;
    const double highlight = highlightPercentile(meter, target.highlightPercent);
    if (highlight > 0.0)
        logExposure = std::min(logExposure, std::log(target.highlightInput) - std::log(highlight));
    return std::clamp(logExposure, -limit, limit);
}

double adaptationBlend(double frameSeconds, double tauSeconds) {
    if (tauSeconds <= 0.0)
        return 1.0;
    return 1.0 - std::exp(-std::max(frameSeconds, 0.0) / tauSeconds);
}

} // namespace lpv::renderer
