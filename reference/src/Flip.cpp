#include "lpv/reference/Flip.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cassert>
#include <cmath>

namespace lpv::reference {

namespace {

constexpr double kPi = glm::pi<double>();

// sRGB's transfer function (IEC 61966-2-1): display value to linear light.
float srgbToLinear(float v) {
    v = std::isfinite(v) ? std::clamp(v, 0.0f, 1.0f) : 0.0f;
    return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

// Linear sRGB to CIE XYZ, built from the sRGB primaries and the D65 white
// point (chromaticities of IEC 61966-2-1) rather than typed in, so its
// inverse is exact to double precision and white maps to Y = 1.
struct ColourSpace {
    glm::dmat3 toXyz;
    glm::dmat3 fromXyz;
    glm::dvec3 white; // XYZ of linear RGB (1, 1, 1)

    ColourSpace() {
        auto column = [](double x, double y) { return glm::dvec3(x / y, 1.0, (1.0 - x - y) / y); };
        const glm::dmat3 primaries(column(0.64, 0.33), column(0.30, 0.60), column(0.15, 0.06));
        white = column(0.3127, 0.3290);
        const glm::dvec3 scale = glm::inverse(primaries) * white;
        toXyz = glm::dmat3(primaries[0] * scale.x, primaries[1] * scale.y, primaries[2] * scale.z);
        fromXyz = glm::inverse(toXyz);
    }
};

const ColourSpace& colourSpace() {
    static const ColourSpace space;
    return space;
}

// CIE L*a*b* of linear RGB (D65 white), with the Hunt effect the paper
// applies: chroma shrinks with lightness (a* and b* scaled by L*/100), so
// dark colours that differ in hue count less than bright ones.
glm::dvec3 huntLab(const glm::dvec3& rgb) {
    const ColourSpace& cs = colourSpace();
    const glm::dvec3 t = (cs.toXyz * rgb) / cs.white;
    constexpr double delta = 6.0 / 29.0;
    auto f = [](double v) {
        return v > delta * delta * delta ? std::cbrt(v) : v / (3.0 * delta * delta) + 4.0 / 29.0;
    };
    const double L = 116.0 * f(t.y) - 16.0;
    const double a = 500.0 * (f(t.x) - f(t.y));
    const double b = 200.0 * (f(t.y) - f(t.z));
    return {L, 0.01 * L * a, 0.01 * L * b};
}

// The HyAB distance (Abasi et al. 2020): city-block in lightness, Euclidean
// in the chromatic plane; it tracks large colour differences better than
// Delta E.
double hyab(const glm::dvec3& p, const glm::dvec3& q) {
    return std::abs(p.x - q.x) + std::hypot(p.y - q.y, p.z - q.z);
}

// The largest colour difference in the sRGB gamut, between green and blue,
// to the power qc: the remapping sends it to 1.
double maxColourDistance() {
    static const double cmax =
        std::pow(hyab(huntLab({0.0, 1.0, 0.0}), huntLab({0.0, 0.0, 1.0})), FlipConstants::qc);
    return cmax;
}

using Plane = std::vector<float>;

// 1-D convolution along rows (`alongRows`) or columns, edges clamped.
Plane convolve(const Plane& in, int w, int h, const std::vector<float>& kernel, bool alongRows) {
    const int r = int(kernel.size() / 2);
    Plane out(in.size());
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float sum = 0.0f;
            for (int i = -r; i <= r; ++i) {
                const int sx = alongRows ? std::clamp(x + i, 0, w - 1) : x;
                const int sy = alongRows ? y : std::clamp(y + i, 0, h - 1);
                sum += kernel[std::size_t(i + r)] * in[std::size_t(sy) * std::size_t(w) + std::size_t(sx)];
            }
            out[std::size_t(y) * std::size_t(w) + std::size_t(x)] = sum;
        }
    return out;
}

Plane separable(const Plane& in, int w, int h, const std::vector<float>& rows,
                const std::vector<float>& cols) {
    return convolve(convolve(in, w, h, rows, true), w, h, cols, false);
}

// The contrast sensitivity of one opponent channel as a spatial filter: the
// paper models each CSF as a sum of Gaussians in frequency,
// a * exp(-b * pi^2 ... ), whose spatial form is a * sqrt(pi / b) *
// exp(-pi^2 r^2 / b) with r in degrees. Each such Gaussian is separable, so
// a channel is filtered once per Gaussian along rows and columns and the
// results are summed with the 2-D weights, normalised so the whole 2-D
// filter sums to 1 (a uniform image passes unchanged).
struct CsfTerm {
    double a, b;
};

Plane csfFilter(const Plane& in, int w, int h, const std::vector<CsfTerm>& terms, int radius, double ppd) {
    std::vector<std::vector<float>> kernels;
    std::vector<double> weights;
    double total = 0.0;
    for (const CsfTerm& t : terms) {
        std::vector<float> k;
        double sum = 0.0;
        for (int i = -radius; i <= radius; ++i) {
            const double x = double(i) / ppd; // degrees
            k.push_back(float(std::exp(-kPi * kPi * x * x / t.b)));
            sum += k.back();
        }
        kernels.push_back(std::move(k));
        weights.push_back(t.a * std::sqrt(kPi / t.b));
        total += weights.back() * sum * sum;
    }
    Plane out(in.size(), 0.0f);
    for (std::size_t t = 0; t < terms.size(); ++t) {
        const Plane part = separable(in, w, h, kernels[t], kernels[t]);
        const float weight = float(weights[t] / total);
        for (std::size_t i = 0; i < out.size(); ++i)
            out[i] += weight * part[i];
    }
    return out;
}

// The three opponent channels of an image, and its luminance Y / Y_white
// (what the feature detectors look at: the paper's achromatic channel
// before filtering, (Y' + 16) / 116).
struct Opponent {
    Plane y, cx, cz, luminance;
};

Opponent toOpponent(const ImageView& image) {
    const ColourSpace& cs = colourSpace();
    const std::size_t n = std::size_t(image.width) * std::size_t(image.height);
    Opponent o{Plane(n), Plane(n), Plane(n), Plane(n)};
    for (std::size_t i = 0; i < n; ++i) {
        const glm::vec3& c = (*image.pixels)[i];
        const glm::dvec3 rgb(srgbToLinear(c.r), srgbToLinear(c.g), srgbToLinear(c.b));
        const glm::dvec3 t = (cs.toXyz * rgb) / cs.white;
        // YCxCz (Zhang and Wandell's linearised CIELAB): linear in XYZ, so blurring in it is meaningful.
        o.y[i] = float(116.0 * t.y - 16.0);
        o.cx[i] = float(500.0 * (t.x - t.y));
        o.cz[i] = float(200.0 * (t.y - t.z));
        o.luminance[i] = float(t.y);
    }
    return o;
}

// Back from filtered YCxCz to linear RGB, clamped into the gamut (the
// filters can overshoot), then Hunt-adjusted L*a*b*.
glm::dvec3 filteredLab(const Opponent& o, std::size_t i) {
    const ColourSpace& cs = colourSpace();
    const double y = (double(o.y[i]) + 16.0) / 116.0;
    const glm::dvec3 xyz = glm::dvec3(y + double(o.cx[i]) / 500.0, y, y - double(o.cz[i]) / 200.0) * cs.white;
    const glm::dvec3 rgb = glm::clamp(cs.fromXyz * xyz, glm::dvec3(0.0), glm::dvec3(1.0));
    return huntLab(rgb);
}

// Remaps the colour distance (to the power qc) so that distances up to
// pc * cmax fill [0, pt] and the rest (pt, 1]: most differences one sees are
// small, and they get most of the range.
double redistribute(double distance) {
    const double cmax = maxColourDistance();
    const double knee = FlipConstants::pc * cmax;
    if (distance < knee)
        return FlipConstants::pt / knee * distance;
    return std::min(1.0, FlipConstants::pt + (distance - knee) / (cmax - knee) * (1.0 - FlipConstants::pt));
}

// 1-D Gaussian and its first and second derivatives (sigma in pixels),
// normalised as the paper does: the Gaussian sums to 1, the positive and the
// negative weights of each derivative to +1 and -1, so a uniform image gives
// no response and a unit step at most 1.
struct FeatureKernels {
    std::vector<float> g, dg, ddg;
};

FeatureKernels featureKernels(double ppd) {
    const double sigma = 0.5 * FlipConstants::w * ppd;
    const int radius = int(std::ceil(3.0 * sigma));
    FeatureKernels k;
    std::vector<double> g, dg, ddg;
    for (int i = -radius; i <= radius; ++i) {
        const double x = double(i);
        const double gauss = std::exp(-x * x / (2.0 * sigma * sigma));
        g.push_back(gauss);
        dg.push_back(-x * gauss);
        ddg.push_back((x * x / (sigma * sigma) - 1.0) * gauss);
    }
    auto normalise = [](const std::vector<double>& v, bool split) {
        double positive = 0.0, negative = 0.0;
        for (double x : v)
            (x > 0.0 ? positive : negative) += std::abs(x);
        std::vector<float> out;
        for (double x : v)
            out.push_back(float(!split ? x / positive : x > 0.0 ? x / positive : x / negative));
        return out;
    };
    k.g = normalise(g, false);
    k.dg = normalise(dg, true);
    k.ddg = normalise(ddg, true);
    return k;
}

// Edge and point strength per pixel: the length of the gradient of the
// luminance blurred at the feature scale, and of its second derivatives.
struct Features {
    Plane edge, point;
};

Features detectFeatures(const Plane& luminance, int w, int h, const FeatureKernels& k) {
    const Plane gx = convolve(luminance, w, h, k.g, true);
    const Plane ex = convolve(convolve(luminance, w, h, k.dg, true), w, h, k.g, false);
    const Plane px = convolve(convolve(luminance, w, h, k.ddg, true), w, h, k.g, false);
    const Plane ey = convolve(gx, w, h, k.dg, false);
    const Plane py = convolve(gx, w, h, k.ddg, false);
    Features f{Plane(luminance.size()), Plane(luminance.size())};
    for (std::size_t i = 0; i < luminance.size(); ++i) {
        f.edge[i] = std::hypot(ex[i], ey[i]);
        f.point[i] = std::hypot(px[i], py[i]);
    }
    return f;
}

} // namespace

double pixelsPerDegree(double distance, double monitorWidth, int monitorPixels) {
    // One degree at `distance` covers distance * tan(1 deg) metres; the
    // paper uses the small-angle form, distance * pi / 180.
    return distance * (double(monitorPixels) / monitorWidth) * (kPi / 180.0);
}

double defaultPixelsPerDegree() {
    return pixelsPerDegree(0.7, 0.7, 3840);
}

FlipResult flip(const ImageView& reference, const ImageView& test, double ppd) {
    assert(reference.width == test.width && reference.height == test.height);
    if (ppd <= 0.0)
        ppd = defaultPixelsPerDegree();
    const int w = reference.width, h = reference.height;
    const std::size_t n = std::size_t(w) * std::size_t(h);
    FlipResult result;
    result.width = w;
    result.height = h;
    if (n == 0)
        return result;

    // The paper's CSF fits (achromatic, red-green, blue-yellow: a1, b1, a2, b2);
    // a term with a = 0 adds nothing and is left out. Every channel's filter
    // reaches 3 standard deviations of the widest Gaussian of all (b = 0.04).
    const std::vector<CsfTerm> achromatic{{1.0, 0.0047}};
    const std::vector<CsfTerm> redGreen{{1.0, 0.0053}};
    const std::vector<CsfTerm> blueYellow{{34.1, 0.04}, {13.5, 0.025}};
    const int radius = int(std::ceil(3.0 * std::sqrt(0.04 / (2.0 * kPi * kPi)) * ppd));

    Opponent ref = toOpponent(reference), tst = toOpponent(test);
    const FeatureKernels fk = featureKernels(ppd);
    const Features fr = detectFeatures(ref.luminance, w, h, fk);
    const Features ft = detectFeatures(tst.luminance, w, h, fk);
    for (Opponent* o : {&ref, &tst}) {
        o->y = csfFilter(o->y, w, h, achromatic, radius, ppd);
        o->cx = csfFilter(o->cx, w, h, redGreen, radius, ppd);
        o->cz = csfFilter(o->cz, w, h, blueYellow, radius, ppd);
    }

    result.error.resize(n);
    result.colour.resize(n);
    result.feature.resize(n);
    double sum = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const double colour =
            redistribute(std::pow(hyab(filteredLab(ref, i), filteredLab(tst, i)), FlipConstants::qc));
        const double difference = std::max(std::abs(double(fr.edge[i]) - double(ft.edge[i])),
                                           std::abs(double(fr.point[i]) - double(ft.point[i])));
        const double feature = std::min(1.0, std::pow(difference / std::sqrt(2.0), FlipConstants::qf));
        // Features push the colour error towards 1: an error on an edge is seen more.
        const double error = std::pow(colour, 1.0 - feature);
        result.colour[i] = float(colour);
        result.feature[i] = float(feature);
        result.error[i] = float(error);
        sum += error;
    }
    result.mean = sum / double(n);
    return result;
}

std::vector<glm::vec3> unitRgb(const scene::Image8& image) {
    const std::size_t n = std::size_t(image.width) * std::size_t(image.height);
    const int c = std::max(1, image.channels);
    std::vector<glm::vec3> out(n);
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint8_t* p = image.pixels.data() + i * std::size_t(c);
        out[i] = c >= 3 ? glm::vec3(p[0], p[1], p[2]) / 255.0f : glm::vec3(float(p[0]) / 255.0f);
    }
    return out;
}

FlipResult flip(const scene::Image8& reference, const scene::Image8& test, double ppd) {
    const std::vector<glm::vec3> r = unitRgb(reference), t = unitRgb(test);
    return flip(ImageView{reference.width, reference.height, &r}, ImageView{test.width, test.height, &t},
                ppd);
}

double maskedMean(const std::vector<float>& values, const std::vector<float>* mask) {
    double sum = 0.0;
    std::size_t count = 0;
    for (std::size_t i = 0; i < values.size(); ++i)
        if (!mask || (i < mask->size() && (*mask)[i] > 0.5f)) {
            sum += values[i];
            ++count;
        }
    return count ? sum / double(count) : 0.0;
}

} // namespace lpv::reference
