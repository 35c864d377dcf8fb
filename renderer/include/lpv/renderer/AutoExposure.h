#pragma once
// Auto exposure (output.exposureMode = auto): the exposure that maps the
// frame's log-average luminance to the key value (Reinhard, Stark, Shirley,
// Ferwerda 2002), adapting over time like an eye. Only the display image is
// exposed: metrics, EXR files and the HDR read-back stay linear.
//
// The GPU meters without read-back (exposure_reduce.comp, exposure_adapt.comp);
// these functions are its CPU twin, used by the tests.
#include <cstddef>

namespace lpv::renderer {

// Pixels at or below this luminance count as unlit and are not metered.
inline constexpr float kMeterMinLuminance = 1e-5f;
// The metered exposure is clamped to +-16 EV (output.exposure's range).
inline constexpr double kMeterMaxEv = 16.0;

struct LogLuminanceSum {
    double sumLog = 0.0; // sum of ln(luminance) over the lit pixels
    double lit = 0.0;    // how many pixels were lit
};

// Rec. 709 luminance of linear RGB.
inline float luminance(float r, float g, float b) { return 0.2126f * r + 0.7152f * g + 0.0722f * b; }

// The lit pixels of `pixels` (width*height pixels of `channels` floats, RGB first).
LogLuminanceSum meterLogLuminance(const float* pixels, std::size_t pixelCount, int channels);

// ln of the exposure that maps the log-average luminance to `key`, clamped to
// +-kMeterMaxEv; 0 (exposure 1) when nothing is lit.
double targetLogExposure(const LogLuminanceSum& sum, double key);

// How far one frame moves the exposure toward its target: 1 - exp(-dt/tau);
// 1 (at once) when tau <= 0.
double adaptationBlend(double frameSeconds, double tauSeconds);

} // namespace lpv::renderer
