#pragma once
// Auto exposure (output.exposureMode = auto): the exposure that maps the
// frame's log-average luminance to the key value (Reinhard, Stark, Shirley,
// Ferwerda 2002), lowered where that would clip the highlights: the value
// below which the brightest channel of output.exposureHighlights percent of
// the lit pixels lies may reach the tonemapper's white at most, so at most
// the rest show any channel clipped (histogram metering as in Unreal's and
// Frostbite's auto exposure, with the histogram as a clamp on the average). It adapts over time like an eye.
// Only the display image is exposed: metrics, EXR files and the HDR
// read-back stay linear.
//
// The GPU meters without read-back (exposure_reduce.comp, exposure_adapt.comp);
// these functions are its CPU twin, used by the tests and the editor.
#include <array>
#include <cstddef>
#include <cstdint>

namespace lpv::renderer {

// Pixels at or below this luminance count as unlit and are not metered.
inline constexpr float kMeterMinLuminance = 1e-5f;
// The metered exposure is clamped to +-16 EV (output.exposure's range).
inline constexpr double kMeterMaxEv = 16.0;
// The histogram of the lit pixels' brightest channel: kMeterBins bins of 1/kMeterBinsPerEv EV from
// 2^kMeterMinLog2 up; values outside fall into the end bins. The range
// spans the lit threshold (2^-16.6) to far above any sun, so only the first
// and last bins ever clamp. exposure_reduce.comp bins the same way.
inline constexpr int kMeterBins = 256;
inline constexpr float kMeterBinsPerEv = 4.0f;
inline constexpr float kMeterMinLog2 = -24.0f;

struct LuminanceMeter {
    double sumLog = 0.0; // sum of ln(luminance) over the lit pixels
    double lit = 0.0;    // how many pixels were lit
    std::array<std::uint32_t, kMeterBins> histogram{}; // lit pixels per log2 bin of max(r, g, b)
};

// What the metered exposure aims for.
struct MeterTarget {
    double key = 0.18;               // output.exposureKey: where the log-average goes
    double highlightPercent = 100.0; // output.exposureHighlights: this percentile of the lit pixels...
    double highlightInput = 1e30;    // ...may reach this value before the tonemapper at most (its white)
};

// Rec. 709 luminance of linear RGB.
inline float luminance(float r, float g, float b) { return 0.2126f * r + 0.7152f * g + 0.0722f * b; }

// The histogram bin of a lit pixel's brightest channel (exposure_reduce.comp's meterBin).
int meterBin(float value);

// The lit pixels of `pixels` (width*height pixels of `channels` floats, RGB first).
LuminanceMeter meterLuminance(const float* pixels, std::size_t pixelCount, int channels);

// The value below which the brightest channel of `percent` of the lit pixels lies, interpolated
// log-linearly inside its bin so that it moves smoothly with the counts; 0
// when nothing is lit.
double highlightPercentile(const LuminanceMeter& meter, double percent);

// ln of the metered exposure: the one that maps the log-average luminance to
// the key, or the lower one that maps the highlight percentile to the
// highlight input, clamped to +-kMeterMaxEv; 0 (exposure 1) when nothing is lit.
double targetLogExposure(const LuminanceMeter& meter, const MeterTarget& target);

// How far one frame moves the exposure toward its target: 1 - exp(-dt/tau);
// 1 (at once) when tau <= 0.
double adaptationBlend(double frameSeconds, double tauSeconds);

} // namespace lpv::renderer
