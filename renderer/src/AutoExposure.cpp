#include "lpv/renderer/AutoExposure.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lpv::renderer {

LogLuminanceSum meterLogLuminance(const float* pixels, std::size_t pixelCount, int channels) {
    LogLuminanceSum s;
    for (std::size_t i = 0; i < pixelCount; ++i) {
        const float* p = pixels + i * std::size_t(channels);
        const float l = luminance(p[0], p[1], p[2]);
        if (l > kMeterMinLuminance && !std::isinf(l)) { // NaN fails the comparison
            s.sumLog += std::log(double(l));
            s.lit += 1.0;
        }
    }
    return s;
}

double targetLogExposure(const LogLuminanceSum& sum, double key) {
    if (sum.lit < 1.0)
        return 0.0;
    const double limit = kMeterMaxEv * std::numbers::ln2;
    return std::clamp(std::log(key) - sum.sumLog / sum.lit, -limit, limit);
}

double adaptationBlend(double frameSeconds, double tauSeconds) {
    if (tauSeconds <= 0.0)
        return 1.0;
    return 1.0 - std::exp(-std::max(frameSeconds, 0.0) / tauSeconds);
}

} // namespace lpv::renderer
