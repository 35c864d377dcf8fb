#pragma once
// WCAG 2's contrast between two colours as a display shows them: what the
// label tests measure from drawn pixels (issue #46). 4.5:1 is the level
// WCAG AA asks of normal text.
#include <QRgb>

#include <algorithm>
#include <cmath>

namespace lpv::test {

// Relative luminance of an sRGB colour.
inline double wcagLuminance(QRgb c) {
    auto linear = [](int v) {
        const double s = v / 255.0;
        return s <= 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4);
    };
    return 0.2126 * linear(qRed(c)) + 0.7152 * linear(qGreen(c)) + 0.0722 * linear(qBlue(c));
}

inline double wcagContrast(double luminanceA, double luminanceB) {
    return (std::max(luminanceA, luminanceB) + 0.05) / (std::min(luminanceA, luminanceB) + 0.05);
}

} // namespace lpv::test
