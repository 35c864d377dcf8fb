// lpv-ltc-fit: fits Linearly Transformed Cosines (Heitz, Dupuy, Hill, Neubelt
// 2016) to the GGX specular lobe of shaders/brdf.glsl and writes the table
// scene/src/LtcGgxTable.inc that lpv::scene::ltcGgxLookup and the area-light
// shader read. Standalone (glm only) so the table can be regenerated without
// building the project; tools/ltc-fit/README.md has the why and the numbers.
//
//   lpv-ltc-fit OUTPUT.inc [SIZE]
//
// The lobe is f(l) = D(h) * V(l, v) * cos(theta_l), with brdf.glsl's
// alpha = max(roughness^2, 1e-3), GGX D, height-correlated Smith V and its
// 1e-4 clamps on n.l and n.v; no Fresnel. Per cell (roughness, cos theta_v)
// the fitter computes
//   magnitude = integral of f,  fresnel = integral of f * (1 - v.h)^5,
// so that the integral of F * f over any region is, with Schlick's F,
//   F0 * magnitude * I + (1 - F0) * fresnel * I,
// I being the integral over that region of the LTC fitted to f / magnitude.
//
// The LTC is D(w) = cos+(w_o) / pi * |det M^-1| / |M^-1 w|^3, w_o = M^-1 w / |M^-1 w|,
// in the frame where n = +z and v = (sin theta_v, 0, cos theta_v). The lobe is
// symmetric about the x-z plane, so M = R(phi) * [[m11, 0, m13], [0, m22, 0], [0, 0, 1]]
// with R(phi) a rotation about y; (m11, m22, m13, phi) minimise the L2
// distance between the LTC and f / magnitude (Nelder-Mead, each cell starting
// from its neighbour's solution). The paper fixes phi at the lobe's mean
// direction; freeing it lowers the error at grazing views by a third to a half.
#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <numbers>
#include <span>
#include <string>
#include <tuple>
#include <vector>

namespace {

constexpr double kPi = std::numbers::pi;
// shaders/brdf.glsl's floor on alpha and its clamp on n.l and n.v.
constexpr double kMinAlpha = 1e-3;
constexpr double kMinCos = 1e-4;

// Points per cell for the lobe's integrals, for the fit's error and for
// judging the result; and Nelder-Mead's stopping size of the simplex.
constexpr int kMomentPoints = 8192;
constexpr int kFitPoints = 610;
constexpr int kJudgePoints = 4181;
constexpr double kTolerance = 1e-6;

// The table's axes (LtcSpecular.h documents them for the readers):
// column r: roughness = r / (N - 1); row t: cos theta_v = 1 - (t / (N - 1))^2.
double alphaOfRoughness(double roughness) {
    return std::max(roughness * roughness, kMinAlpha);
}
double cosThetaOfCoordinate(double x) {
    return std::max(1.0 - x * x, kMinCos);
}

// The GGX lobe f(l) for a view direction v in the upper hemisphere.
struct GgxLobe {
    double alpha = 1.0;
    glm::dvec3 v{0.0, 0.0, 1.0};

    double a2() const { return alpha * alpha; }
    double distribution(double nh) const {
        const double d = nh * nh * (a2() - 1.0) + 1.0;
        return a2() / (kPi * d * d);
    }
    // D * V * cos(theta_l), 0 below the horizon.
    double eval(const glm::dvec3& l) const {
        if (!(l.z > 0.0))
            return 0.0;
        const glm::dvec3 h = glm::normalize(l + v);
        const double nl = std::max(l.z, kMinCos), nv = std::max(v.z, kMinCos);
        const double vis = 0.5 / (nl * std::sqrt(nv * nv * (1.0 - a2()) + a2()) +
                                  nv * std::sqrt(nl * nl * (1.0 - a2()) + a2()));
        return distribution(std::max(h.z, 0.0)) * vis * l.z;
    }
    // Density of `sample` over directions: the visible-normal density
    // G1(v) D(h) (v.h) / (v.z) times the reflection's Jacobian 1 / (4 v.h).
    double pdf(const glm::dvec3& l) const {
        const glm::dvec3 h = glm::normalize(l + v);
        if (!(h.z > 0.0))
            return 0.0;
        return distribution(h.z) / (2.0 * (v.z + std::sqrt(a2() + (1.0 - a2()) * v.z * v.z)));
    }
    // Reflects v about a normal drawn from the visible normals (Heitz 2018):
    // a uniform point on the projected disc of the stretched hemisphere.
    glm::dvec3 sample(double u1, double u2) const {
        const glm::dvec3 vh = glm::normalize(glm::dvec3(alpha * v.x, alpha * v.y, v.z));
        const double lensq = vh.x * vh.x + vh.y * vh.y;
        const glm::dvec3 t1 =
            lensq > 0.0 ? glm::dvec3(-vh.y, vh.x, 0.0) / std::sqrt(lensq) : glm::dvec3(1.0, 0.0, 0.0);
        const glm::dvec3 t2 = glm::cross(vh, t1);
        const double r = std::sqrt(u1), phi = 2.0 * kPi * u2;
        const double p1 = r * std::cos(phi);
        const double s = 0.5 * (1.0 + vh.z);
        const double p2 = (1.0 - s) * std::sqrt(std::max(0.0, 1.0 - p1 * p1)) + s * r * std::sin(phi);
        const glm::dvec3 nh = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0, 1.0 - p1 * p1 - p2 * p2)) * vh;
        const glm::dvec3 h = glm::normalize(glm::dvec3(alpha * nh.x, alpha * nh.y, std::max(nh.z, 1e-12)));
        return 2.0 * glm::dot(v, h) * h - v;
    }
};

// A linearly transformed clamped cosine.
struct Ltc {
    glm::dmat3 m{1.0};
    glm::dmat3 inv{1.0};
    double invDet = 1.0;

    explicit Ltc(const glm::dmat3& matrix)
        : m(matrix), inv(glm::inverse(matrix)), invDet(std::abs(glm::determinant(inv))) {}

    double eval(const glm::dvec3& w) const {
        const glm::dvec3 o = inv * w;
        const double len = glm::length(o);
        return std::max(o.z / len, 0.0) / kPi * invDet / (len * len * len);
    }
};

// A Fibonacci lattice: n well spread points of the unit square, the same for
// every cell and every evaluation so that the error is a smooth, deterministic
// function of the parameters (Nelder-Mead dislikes noise).
std::vector<glm::dvec2> fibonacciLattice(int n) {
    std::vector<glm::dvec2> points;
    const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
    for (int i = 0; i < n; ++i)
        points.emplace_back((i + 0.5) / n, std::fmod(i * golden, 1.0));
    return points;
}

// Cosine-distributed directions: an LTC's samples are M w / |M w|.
std::vector<glm::dvec3> cosineSamples(std::span<const glm::dvec2> points) {
    std::vector<glm::dvec3> out;
    for (const glm::dvec2& u : points) {
        const double r = std::sqrt(u.x), phi = 2.0 * kPi * u.y;
        out.emplace_back(r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0, 1.0 - u.x)));
    }
    return out;
}

struct Moments {
    double magnitude = 0.0;
    double fresnel = 0.0;
    glm::dvec3 meanDirection{0.0, 0.0, 1.0};
};

// The lobe's integrals by importance sampling its visible normals; the
// weight f / pdf is bounded (G2 / G1 when the clamps are idle), so a few
// thousand points give four or five digits.
Moments lobeMoments(const GgxLobe& lobe, std::span<const glm::dvec2> points) {
    Moments m;
    glm::dvec3 sum(0.0);
    for (const glm::dvec2& u : points) {
        const glm::dvec3 l = lobe.sample(u.x, u.y);
        const double pdf = lobe.pdf(l);
        if (!(pdf > 0.0))
            continue;
        const double w = lobe.eval(l) / pdf;
        const double vh = std::max(glm::dot(lobe.v, glm::normalize(l + lobe.v)), 0.0);
        m.magnitude += w;
        m.fresnel += w * std::pow(1.0 - vh, 5.0);
        sum += w * l;
    }
    m.magnitude /= double(points.size());
    m.fresnel /= double(points.size());
    sum.y = 0.0; // zero by symmetry; drop the sampling noise
    m.meanDirection = glm::normalize(sum);
    return m;
}

// What the error needs of the lobe, computed once per cell: its samples with
// their normalised value and density, and the lobe to evaluate at the LTC's.
struct ErrorSamples {
    const GgxLobe* lobe = nullptr;
    double magnitude = 1.0;
    std::vector<glm::dvec3> lobeDirections;
    std::vector<double> lobeValues, lobePdfs;
    std::span<const glm::dvec3> cosines;
};

ErrorSamples errorSamples(const GgxLobe& lobe, double magnitude, std::span<const glm::dvec2> points,
                          std::span<const glm::dvec3> cosines) {
    ErrorSamples s;
    s.lobe = &lobe;
    s.magnitude = magnitude;
    s.cosines = cosines;
    for (const glm::dvec2& u : points) {
        const glm::dvec3 l = lobe.sample(u.x, u.y);
        s.lobeDirections.push_back(l);
        s.lobeValues.push_back(lobe.eval(l) / magnitude);
        s.lobePdfs.push_back(lobe.pdf(l));
    }
    return s;
}

// Integral over the sphere of (ltc - f / magnitude)^2 (kPower = 2) by
// multiple importance sampling, balance heuristic, of the LTC and the lobe.
// kPower = 1 gives the L1 distance, twice the largest error the LTC can make
// in the lobe's integral over any region, as a fraction of its magnitude.
template <int kPower> double fitError(const glm::dmat3& m, const ErrorSamples& s) {
    const Ltc ltc(m);
    const auto term = [](double fl, double fb, double pdfSum) {
        const double d = std::abs(fl - fb);
        return pdfSum > 0.0 ? (kPower == 1 ? d : d * d) / pdfSum : 0.0;
    };
    double sum = 0.0;
    for (std::size_t i = 0; i < s.lobeDirections.size(); ++i) {
        const double fl = ltc.eval(s.lobeDirections[i]);
        sum += term(fl, s.lobeValues[i], fl + s.lobePdfs[i]);
    }
    // At w = M c / |M c| the LTC's density is cos(c) / pi * |det M^-1| * |M c|^3.
    for (const glm::dvec3& c : s.cosines) {
        const glm::dvec3 mc = m * c;
        const double len = glm::length(mc);
        const glm::dvec3 w = mc / len;
        const double fl = c.z / kPi * ltc.invDet * len * len * len;
        sum += term(fl, s.lobe->eval(w) / s.magnitude, fl + s.lobe->pdf(w));
    }
    return sum / double(s.cosines.size());
}

using Params = std::array<double, 4>;

// Nelder-Mead with the usual coefficients (reflect 1, expand 2, contract 1/2, shrink 1/2).
Params nelderMead(const std::function<double(const Params&)>& f, const Params& start, double step,
                  int maxEvals, double tolerance) {
    constexpr int n = int(std::tuple_size_v<Params>);
    std::array<Params, n + 1> x;
    std::array<double, n + 1> fx;
    for (int i = 0; i <= n; ++i) {
        x[i] = start;
        if (i > 0)
            x[i][i - 1] += step;
        fx[i] = f(x[i]);
    }
    int evals = n + 1;
    const auto along = [](const Params& a, const Params& b, double t) {
        Params r;
        for (int k = 0; k < n; ++k)
            r[k] = a[k] + t * (b[k] - a[k]);
        return r;
    };
    while (evals < maxEvals) {
        std::array<int, n + 1> order;
        for (int i = 0; i <= n; ++i)
            order[i] = i;
        std::sort(order.begin(), order.end(), [&](int a, int b) { return fx[a] < fx[b]; });
        const int best = order[0], worst = order[n], second = order[n - 1];
        double size = 0.0;
        for (int i = 0; i <= n; ++i)
            for (int k = 0; k < n; ++k)
                size = std::max(size, std::abs(x[i][k] - x[best][k]));
        if (size < tolerance)
            break;
        Params centroid{};
        for (int i = 0; i <= n; ++i)
            if (i != worst)
                for (int k = 0; k < n; ++k)
                    centroid[k] += x[i][k] / n;
        const Params reflected = along(centroid, x[worst], -1.0);
        const double fr = f(reflected);
        ++evals;
        if (fr < fx[best]) {
            const Params expanded = along(centroid, x[worst], -2.0);
            const double fe = f(expanded);
            ++evals;
            if (fe < fr)
                x[worst] = expanded, fx[worst] = fe;
            else
                x[worst] = reflected, fx[worst] = fr;
        } else if (fr < fx[second]) {
            x[worst] = reflected, fx[worst] = fr;
        } else {
            const bool outside = fr < fx[worst];
            const Params contracted = along(centroid, outside ? reflected : x[worst], 0.5);
            const double fc = f(contracted);
            ++evals;
            if (fc < std::min(fr, fx[worst])) {
                x[worst] = contracted, fx[worst] = fc;
            } else {
                for (int i = 0; i <= n; ++i) {
                    if (i == best)
                        continue;
                    x[i] = along(x[best], x[i], 0.5);
                    fx[i] = f(x[i]);
                    ++evals;
                }
            }
        }
    }
    return x[std::min_element(fx.begin(), fx.end()) - fx.begin()];
}

// Parameters (log m11, log m22, m13 / m11, phi - phi_mean): the widths on a
// log scale, so that one simplex step means the same at alpha = 0.001 and at
// 1; the shear in units of the width; the rotation about y relative to the
// lobe's mean direction, where the paper keeps it. Freeing the rotation
// halves the error at grazing views; it and the shear nearly trade for each
// other on narrow lobes, so the fit must converge tightly (or the table
// zigzags between equivalent solutions, which interpolate badly).
glm::dmat3 ltcMatrix(const Params& p, const glm::dvec3& meanDirection) {
    const double m11 = std::exp(p[0]), m22 = std::exp(p[1]), m13 = p[2] * m11;
    const double phi = std::atan2(meanDirection.x, meanDirection.z) + p[3];
    // glm is column-major: the columns are the images of x, y and z.
    const glm::dmat3 rotation(glm::dvec3(std::cos(phi), 0.0, -std::sin(phi)), glm::dvec3(0.0, 1.0, 0.0),
                              glm::dvec3(std::sin(phi), 0.0, std::cos(phi)));
    const glm::dmat3 shape(glm::dvec3(m11, 0.0, 0.0), glm::dvec3(0.0, m22, 0.0), glm::dvec3(m13, 0.0, 1.0));
    return rotation * shape;
}

struct Cell {
    std::array<double, 4> inverse{}; // (M^-1)_00, _02, _20, _22 with (M^-1)_11 = 1; (row, column)
    double magnitude = 0.0;
    double fresnel = 0.0;
    double error = 0.0; // half the L1 distance between the LTC and the normalised lobe
};

struct PointSets {
    std::vector<glm::dvec2> moments = fibonacciLattice(kMomentPoints);
    std::vector<glm::dvec2> fit = fibonacciLattice(kFitPoints);
    std::vector<glm::dvec2> judge = fibonacciLattice(kJudgePoints);
    std::vector<glm::dvec3> fitCosines = cosineSamples(fit);
    std::vector<glm::dvec3> judgeCosines = cosineSamples(judge);
};

GgxLobe lobeAt(double roughness, double coordinate) {
    GgxLobe lobe;
    lobe.alpha = alphaOfRoughness(roughness);
    const double cosTheta = cosThetaOfCoordinate(coordinate);
    lobe.v = glm::dvec3(std::sqrt(1.0 - cosTheta * cosTheta), 0.0, cosTheta);
    return lobe;
}

glm::dmat3 inverseMatrix(const std::array<double, 4>& e) {
    // glm::dmat3 takes columns.
    return glm::dmat3(glm::dvec3(e[0], 0.0, e[2]), glm::dvec3(0.0, 1.0, 0.0), glm::dvec3(e[1], 0.0, e[3]));
}

// Fits every cell, roughest first (there the lobe is nearly a cosine, a known
// start), then toward grazing along each column, each cell starting from its
// neighbour's solution. Returns the cells row by row (cos theta_v).
std::vector<Cell> fitTable(int size, const PointSets& points, long& evaluations) {
    std::vector<Cell> table(std::size_t(size) * std::size_t(size));
    std::vector<Params> solution(table.size());
    for (int r = size - 1; r >= 0; --r) {
        for (int t = 0; t < size; ++t) {
            const GgxLobe lobe = lobeAt(double(r) / (size - 1), double(t) / (size - 1));
            const Moments moments = lobeMoments(lobe, points.moments);
            const ErrorSamples samples = errorSamples(lobe, moments.magnitude, points.fit, points.fitCosines);

            Params start{};
            if (t > 0)
                start = solution[std::size_t(t - 1) * size + std::size_t(r)];
            else if (r < size - 1)
                start = solution[std::size_t(r + 1)];
            const auto objective = [&](const Params& p) {
                ++evaluations;
                return fitError<2>(ltcMatrix(p, moments.meanDirection), samples);
            };
            Params best = nelderMead(objective, start, 0.1, 2000, kTolerance);
            // A restart from the optimum unsticks a simplex that collapsed early.
            best = nelderMead(objective, best, 0.01, 1000, kTolerance);

            const std::size_t index = std::size_t(t) * size + std::size_t(r);
            solution[index] = best;
            const glm::dmat3 m = ltcMatrix(best, moments.meanDirection);
            const glm::dmat3 inv = glm::inverse(m) / glm::inverse(m)[1][1];
            Cell& cell = table[index];
            cell.inverse = {inv[0][0], inv[2][0], inv[0][2], inv[2][2]}; // glm indexes [column][row]
            cell.magnitude = moments.magnitude;
            cell.fresnel = moments.fresnel;
            const ErrorSamples judge =
                errorSamples(lobe, moments.magnitude, points.judge, points.judgeCosines);
            cell.error = 0.5 * fitError<1>(m, judge);
        }
        std::fprintf(stderr, "\rfitted %3d/%d roughness columns", size - r, size);
    }
    std::fprintf(stderr, "\n");
    return table;
}

struct Stats {
    double worst = 0.0, mean = 0.0;
    double worstRoughness = 0.0, worstCosTheta = 1.0;
    double worstAbove = 0.0;          // worst where cos(theta_v) >= kSummaryCos
    double worstMagnitude = 0.0;      // relative, between cells only
    double worstMagnitudeAbove = 0.0; // the same where cos(theta_v) >= kSummaryCos
};

// Below this n.v (75.5 degrees) the lobe is increasingly cut by the horizon,
// a shape no LTC matches, so the summary also states the error above it.
constexpr double kSummaryCos = 0.25;

void account(Stats& s, double error, double roughness, double coordinate) {
    if (error > s.worst)
        s.worst = error, s.worstRoughness = roughness, s.worstCosTheta = cosThetaOfCoordinate(coordinate);
    if (cosThetaOfCoordinate(coordinate) >= kSummaryCos)
        s.worstAbove = std::max(s.worstAbove, error);
    s.mean += error;
}

Stats nodeStats(const std::vector<Cell>& table, int size) {
    Stats s;
    for (int t = 0; t < size; ++t)
        for (int r = 0; r < size; ++r)
            account(s, table[std::size_t(t) * size + std::size_t(r)].error, double(r) / (size - 1),
                    double(t) / (size - 1));
    s.mean /= double(table.size());
    return s;
}

// What the shader sees halfway between texel centres, where bilinear
// filtering averages four cells' inverse matrices and magnitudes.
Stats midpointStats(const std::vector<Cell>& table, int size, const PointSets& points) {
    Stats s;
    for (int t = 0; t + 1 < size; ++t) {
        for (int r = 0; r + 1 < size; ++r) {
            const double roughness = (r + 0.5) / (size - 1), coordinate = (t + 0.5) / (size - 1);
            const GgxLobe lobe = lobeAt(roughness, coordinate);
            const Moments moments = lobeMoments(lobe, points.moments);
            std::array<double, 4> e{};
            double magnitude = 0.0;
            for (int dt = 0; dt < 2; ++dt)
                for (int dr = 0; dr < 2; ++dr) {
                    const Cell& c = table[std::size_t(t + dt) * size + std::size_t(r + dr)];
                    for (int k = 0; k < 4; ++k)
                        e[std::size_t(k)] += 0.25 * c.inverse[std::size_t(k)];
                    magnitude += 0.25 * c.magnitude;
                }
            const ErrorSamples judge =
                errorSamples(lobe, moments.magnitude, points.judge, points.judgeCosines);
            account(s, 0.5 * fitError<1>(glm::inverse(inverseMatrix(e)), judge), roughness, coordinate);
            const double magnitudeError = std::abs(magnitude / moments.magnitude - 1.0);
            s.worstMagnitude = std::max(s.worstMagnitude, magnitudeError);
            if (cosThetaOfCoordinate(coordinate) >= kSummaryCos)
                s.worstMagnitudeAbove = std::max(s.worstMagnitudeAbove, magnitudeError);
        }
    }
    s.mean /= double((size - 1) * (size - 1));
    return s;
}

std::string commandLine(int argc, char** argv) {
    std::string s = "lpv-ltc-fit";
    for (int i = 1; i < argc; ++i)
        s += std::string(" ") + argv[i];
    return s;
}

std::string describe(const char* what, const Stats& s) {
    char text[512];
    std::snprintf(text, sizeof text,
                  "%s: worst %.4f (roughness %.4f, n.v %.6f), mean %.4f, worst with n.v >= %.2f %.4f", what,
                  s.worst, s.worstRoughness, s.worstCosTheta, s.mean, kSummaryCos, s.worstAbove);
    return text;
}

bool writeTable(const std::string& path, const std::vector<Cell>& table, int size, const std::string& command,
                const Stats& nodes, const Stats& midpoints) {
    std::FILE* out = std::fopen(path.c_str(), "w");
    if (!out)
        return false;
    std::fprintf(
        out,
        "// Generated by tools/ltc-fit/LtcFit.cpp; do not edit. Regenerate from the repository root with\n"
        "//   %s\n"
        "// (tools/ltc-fit/README.md). Linearly Transformed Cosines (Heitz et al. 2016) fitted to\n"
        "// the GGX lobe D * V * cos(theta_l) of shaders/brdf.glsl, without Fresnel.\n"
        "// %d x %d cells, 6 floats each, cell (row t, column r) at (t * %d + r) * 6:\n"
        "//   column r: roughness = r / %d (alpha = max(roughness^2, 1e-3));\n"
        "//   row t:    sqrt(1 - cos(theta_v)) = t / %d (cos(theta_v) at least 1e-4);\n"
        "//   floats:   M^-1 entries (0,0), (0,2), (2,0), (2,2) (row, column) scaled so that\n"
        "//             (1,1) = 1, in the frame x = tangent toward v, z = normal; then\n"
        "//             magnitude = integral of D V cos, fresnel = integral of D V cos (1 - v.h)^5.\n"
        "// Fit error, half the L1 distance between the LTC and the normalised lobe:\n"
        "//   %s;\n"
        "//   %s;\n"
        "//   interpolated magnitude off by at most %.4f (relative) between cells, %.4f with n.v >= %.2f.\n",
        command.c_str(), size, size, size, size - 1, size - 1, describe("at the cells", nodes).c_str(),
        describe("between cells", midpoints).c_str(), midpoints.worstMagnitude, midpoints.worstMagnitudeAbove,
        kSummaryCos);
    for (int t = 0; t < size; ++t) {
        std::fprintf(out, "// row %d: cos(theta_v) = %.9g\n", t,
                     cosThetaOfCoordinate(double(t) / (size - 1)));
        for (int r = 0; r < size; ++r) {
            const Cell& c = table[std::size_t(t) * size + std::size_t(r)];
            std::fprintf(out, "%.9g, %.9g, %.9g, %.9g, %.9g, %.9g,\n", c.inverse[0], c.inverse[1],
                         c.inverse[2], c.inverse[3], c.magnitude, c.fresnel);
        }
    }
    return std::fclose(out) == 0;
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 2 || argc > 3) {
        std::fprintf(
            stderr,
            "usage: lpv-ltc-fit OUTPUT.inc [SIZE]\n  e.g. lpv-ltc-fit scene/src/LtcGgxTable.inc 64\n");
        return 2;
    }
    const std::string output = argv[1];
    const int size = argc == 3 ? std::atoi(argv[2]) : 64;
    if (size < 2 || size > 256) {
        std::fprintf(stderr, "lpv-ltc-fit: SIZE must be in [2, 256], got '%s'\n", argv[2]);
        return 2;
    }
    const auto started = std::chrono::steady_clock::now();
    const PointSets points;
    long evaluations = 0;
    const std::vector<Cell> table = fitTable(size, points, evaluations);
    const Stats nodes = nodeStats(table, size);
    const Stats midpoints = midpointStats(table, size, points);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();

    if (!writeTable(output, table, size, commandLine(argc, argv), nodes, midpoints)) {
        std::fprintf(stderr, "lpv-ltc-fit: cannot write '%s'\n", output.c_str());
        return 1;
    }
    std::printf("lpv-ltc-fit: %d x %d table written to %s in %.1f s (%.0f error evaluations per cell)\n",
                size, size, output.c_str(), seconds, double(evaluations) / double(table.size()));
    std::printf("fit error (half L1 distance between LTC and normalised lobe)\n  %s\n  %s\n",
                describe("at the cells", nodes).c_str(), describe("between cells", midpoints).c_str());
    std::printf(
        "  interpolated magnitude off by at most %.4f (relative) between cells, %.4f with n.v >= %.2f\n",
        midpoints.worstMagnitude, midpoints.worstMagnitudeAbove, kSummaryCos);
    return 0;
}
