// The CPU reference of the LPV (docs/lpv.md) against analytic answers: SH
// identities, the face table, energy bookkeeping of injection and propagation,
// symmetry, occlusion and a point light. Every measured figure is printed and
// recorded as a test property so that docs/lpv.md can quote it.
#include "lpv/renderer/lpv/LpvReference.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <numbers>
#include <random>
#include <string>
#include <vector>

using namespace lpv::renderer;
using namespace lpv::renderer::lpvref;

namespace {

constexpr double kPi = std::numbers::pi;

void report(const std::string& key, double value) {
    char text[64];
    std::snprintf(text, sizeof text, "%.9g", value);
    ::testing::Test::RecordProperty(key, text);
    std::cout << "[measured] " << key << " = " << text << "\n";
}

// N points spread evenly over the unit sphere; each stands for 4 pi / N sr.
std::vector<glm::dvec3> fibonacciSphere(int count) {
    std::vector<glm::dvec3> out;
    const double golden = kPi * (3.0 - std::sqrt(5.0));
    for (int i = 0; i < count; ++i) {
        const double z = 1.0 - (2.0 * i + 1.0) / count;
        const double r = std::sqrt(1.0 - z * z);
        out.emplace_back(r * std::cos(golden * i), r * std::sin(golden * i), z);
    }
    return out;
}

glm::vec4 basisD(const glm::dvec3& w) { return sh::basis(glm::vec3(w)); }

// The SH of a direction-independent intensity i0 (W/sr).
glm::vec4 isotropic(float i0) { return {i0 / sh::kY0, 0.0f, 0.0f, 0.0f}; }

ShGrid singleCell(int n, glm::ivec3 c, const glm::vec4& sh) {
    ShGrid g(n);
    for (int ch = 0; ch < 3; ++ch)
        g.at(ch, c.x, c.y, c.z) = sh;
    return g;
}

// Solid angle of the rectangle [0, a] x [0, b] at distance d, seen from above its corner.
double cornerRectangle(double a, double b, double d) { return std::atan(a * b / (d * std::sqrt(a * a + b * b + d * d))); }

// Sum of the DC coefficients of channel 0 over the cells with x in [x0, x1).
double dcSlab(const ShGrid& g, int x0, int x1) {
    double s = 0.0;
    for (int z = 0; z < g.n; ++z)
        for (int y = 0; y < g.n; ++y)
            for (int x = x0; x < x1; ++x)
                s += g.at(0, x, y, z).x;
    return s;
}

} // namespace

// ---------------------------------------------------------------- SH identities

TEST(LpvReferenceSh, CosineLobeProjectionReproducesItself) {
    const auto points = fibonacciSphere(20000);
    const double dw = 4.0 * kPi / double(points.size());
    double maxSelf = 0.0, maxClamped = 0.0;
    for (const glm::vec3 d : {glm::vec3(1, 0, 0), glm::vec3(0, -1, 0), glm::normalize(glm::vec3(0.3f, -0.8f, 0.52f))}) {
        const glm::vec4 lobe = sh::cosineLobe(d);
        glm::dvec4 self(0.0), clamped(0.0);
        for (const glm::dvec3& w : points) {
            const glm::dvec4 y(basisD(w));
            self += double(sh::evaluate(lobe, glm::vec3(w))) * y * dw;
            clamped += std::max(0.0, glm::dot(glm::dvec3(d), w)) * y * dw; // the true clamped cosine
        }
        for (int i = 0; i < 4; ++i) {
            maxSelf = std::max(maxSelf, std::abs(self[i] - double(lobe[i])));
            maxClamped = std::max(maxClamped, std::abs(clamped[i] - double(lobe[i])));
        }
    }
    report("sh.reprojection_max_abs_error", maxSelf);
    report("sh.clamped_cosine_projection_max_abs_error", maxClamped);
    EXPECT_LT(maxSelf, 1e-5);
    EXPECT_LT(maxClamped, 1e-4);
}

TEST(LpvReferenceSh, CosineLobeInItsOwnDirectionIsThreeQuarters) {
    // Band-limited max(0, cos 0) = 1 comes back as pi Y00^2 + 2pi/3 Y1^2 = 1/4 + 1/2 = 3/4.
    double worst = 0.0;
    for (const glm::vec3 d : {glm::vec3(0, 0, 1), glm::vec3(-1, 0, 0), glm::normalize(glm::vec3(1, 2, -3))}) {
        const float v = glm::dot(sh::cosineLobe(d), sh::basis(d));
        worst = std::max(worst, std::abs(double(v) - 0.75));
        EXPECT_NEAR(v, 0.75f, 1e-6f);
    }
    report("sh.cosine_lobe_peak_abs_error_vs_0.75", worst);
}

TEST(LpvReferenceSh, ConstantRadianceGivesPiTimesRadiance) {
    // L(w) = L0 projects onto Y00 alone with coefficient L0 / Y00 = L0 * 2 sqrt(pi).
    const float l0 = 2.5f;
    const glm::vec4 radiance = isotropic(l0);
    double worst = 0.0;
    for (const glm::vec3 n : {glm::vec3(0, 1, 0), glm::vec3(0, 0, -1), glm::normalize(glm::vec3(-2, 1, 0.5f))}) {
        const double e = sh::irradiance(radiance, n);
        worst = std::max(worst, std::abs(e / (kPi * l0) - 1.0));
        EXPECT_NEAR(e, kPi * l0, 1e-5);
    }
    report("sh.constant_radiance_irradiance_rel_error", worst);
}

// ---------------------------------------------------------------- face table

TEST(LpvReferenceFaces, ThirtyFacesCoverTheSphere) {
    const auto& faces = propagationFaces();
    ASSERT_EQ(faces.size(), 30u);
    double total = 0.0;
    int front = 0;
    for (const PropagationFace& f : faces) {
        total += f.solidAngle;
        EXPECT_NEAR(glm::length(f.direction), 1.0f, 1e-6f);
        EXPECT_NE(glm::ivec3(f.normal), -f.travel) << "the face shared with the source is skipped";
        const glm::vec3 expected = glm::normalize(glm::vec3(f.travel) + 0.5f * f.normal);
        EXPECT_NEAR(glm::length(f.direction - expected), 0.0f, 1e-6f);
        if (glm::ivec3(f.normal) == f.travel) {
            ++front;
            EXPECT_EQ(f.solidAngle, kFrontFaceSolidAngle);
        } else {
            EXPECT_EQ(f.solidAngle, kSideFaceSolidAngle);
        }
    }
    EXPECT_EQ(front, 6);
    report("faces.solid_angle_sum_minus_4pi", total - 4.0 * kPi);
    EXPECT_NEAR(total, 4.0 * kPi, 1e-3);
}

TEST(LpvReferenceFaces, SolidAnglesMatchTheGeometry) {
    // Seen from q's centre, p's far face is the unit square at distance 1.5 and
    // a side face spans 0.5..1.5 along d at distance 0.5 beside it.
    const double front = 4.0 * cornerRectangle(0.5, 0.5, 1.5);
    const double side = 2.0 * (cornerRectangle(1.5, 0.5, 0.5) - cornerRectangle(0.5, 0.5, 0.5));
    report("faces.front_solid_angle_exact", front);
    report("faces.side_solid_angle_exact", side);
    EXPECT_NEAR(kFrontFaceSolidAngle, front, 1e-7);
    EXPECT_NEAR(kSideFaceSolidAngle, side, 1e-7);
    // p's five far faces hide exactly the face it shares with q: a sixth of the sphere.
    EXPECT_NEAR(front + 4.0 * side, 4.0 * kPi / 6.0, 1e-9);
}

// ---------------------------------------------------------------- energy

TEST(LpvReferenceEnergy, IsotropicCellSendsOutAllItsFlux) {
    const ShGrid v0 = singleCell(16, {8, 8, 8}, isotropic(1.0f));
    const double before = totalFlux(v0, 0);
    EXPECT_NEAR(before, 4.0 * kPi, 1e-5);
    ShGrid v = propagateStep(v0, nullptr);
    report("energy.isotropic_step1_ratio", totalFlux(v, 0) / before);
    EXPECT_NEAR(totalFlux(v, 0) / before, 1.0, 1e-4);
    double worst = 0.0;
    for (int step = 2; step <= 7; ++step) { // light reaches cell 1 and 15 at step 7: still inside
        v = propagateStep(v, nullptr);
        worst = std::max(worst, std::abs(totalFlux(v, 0) / before - 1.0));
    }
    report("energy.isotropic_steps2to7_max_abs_ratio_minus_1", worst);
    EXPECT_LT(worst, 1e-3);
}

TEST(LpvReferenceEnergy, DirectionalVplGainsOnceThenKeepsItsFlux) {
    const GridFrame frame{glm::vec3(0.0f), 1.0f, 16};
    const Vpl vpl{glm::vec3(8.5f), glm::vec3(1, 0, 0), glm::vec3(1.0f)};
    ShGrid v = injectVpls(frame, std::span(&vpl, 1), 0.0f);
    const double injected = totalFlux(v, 0);
    v = propagateStep(v, nullptr);
    const double step1 = totalFlux(v, 0);
    // The cosine lobe's two-band SH is negative behind the VPL; clamping that
    // to zero per face is what adds flux.
    report("energy.vpl_step1_ratio", step1 / injected);
    EXPECT_GT(step1 / injected, 1.0 + 1e-3);
    EXPECT_LT(step1 / injected, 1.5);
    double previous = step1, worst = 0.0;
    for (int step = 2; step <= 7; ++step) {
        v = propagateStep(v, nullptr);
        const double now = totalFlux(v, 0);
        const double r = now / previous;
        std::cout << "[measured] energy.vpl_step" << step << "_over_previous = " << r << "\n";
        worst = std::max(worst, std::abs(r - 1.0));
        previous = now;
    }
    report("energy.vpl_steps2to7_max_abs_step_ratio_minus_1", worst);
    EXPECT_LT(worst, 1e-3);
}

// ---------------------------------------------------------------- symmetry

TEST(LpvReferenceSymmetry, VplSpreadsAlongItsNormal) {
    const GridFrame frame{glm::vec3(0.0f), 1.0f, 16};
    const Vpl vpl{glm::vec3(8.5f), glm::vec3(1, 0, 0), glm::vec3(1.0f)};
    ShGrid v = injectVpls(frame, std::span(&vpl, 1), 0.0f);
    for (int i = 0; i < 4; ++i)
        v = propagateStep(v, nullptr);
    const double ahead = dcSlab(v, 9, 16), behind = dcSlab(v, 0, 8);
    report("symmetry.vpl_ahead_over_behind_after_4_steps", ahead / behind);
    EXPECT_GT(ahead, 3.0 * behind);
}

TEST(LpvReferenceSymmetry, IsotropicSourceGivesAMirrorSymmetricGrid) {
    ShGrid v = singleCell(16, {8, 8, 8}, isotropic(1.0f));
    for (int i = 0; i < 4; ++i)
        v = propagateStep(v, nullptr);
    // Mirror x -> 16 - x flips the sign of the x coefficient (Y11) and keeps the rest;
    // the swap x <-> y swaps Y11 = -x and Y1-1 = -y.
    double worst = 0.0, peak = 0.0;
    for (int z = 0; z < 16; ++z)
        for (int y = 0; y < 16; ++y)
            for (int x = 1; x < 16; ++x) {
                const glm::vec4 a = v.at(0, x, y, z);
                const glm::vec4 m = v.at(0, 16 - x, y, z);
                const glm::vec4 s = v.at(0, y, x, z);
                peak = std::max(peak, double(a.x));
                worst = std::max({worst, double(std::abs(a.x - m.x)), double(std::abs(a.y - m.y)),
                                  double(std::abs(a.z - m.z)), double(std::abs(a.w + m.w))});
                worst = std::max({worst, double(std::abs(a.x - s.x)), double(std::abs(a.y - s.w)),
                                  double(std::abs(a.w - s.y)), double(std::abs(a.z - s.z))});
            }
    report("symmetry.isotropic_max_mirror_difference_over_peak", worst / peak);
    EXPECT_LT(worst / peak, 1e-6);
    EXPECT_EQ(dcSlab(v, 0, 1), 0.0) << "no light beyond the mirror of the last lit cell";
}

// ---------------------------------------------------------------- occlusion

namespace {

// A wall of surfels filling the GV plane x = 7 (the face between cells 6 and 7), one per GV cell,
// each covering a whole cell face.
GvGrid wall(const GridFrame& frame, const glm::vec3& normal) {
    std::vector<Surfel> surfels;
    for (int z = 0; z <= frame.n; ++z)
        for (int y = 0; y <= frame.n; ++y)
            surfels.push_back({frame.origin + frame.cellSize * glm::vec3(7.0f, float(y), float(z)), normal,
                               frame.cellSize * frame.cellSize});
    return injectSurfels(frame, surfels);
}

} // namespace

TEST(LpvReferenceOcclusion, WallFacingTheSourceBlocksWallFacingAwayDoesNot) {
    const GridFrame frame{glm::vec3(-3.0f, 1.0f, 2.0f), 0.5f, 16};
    const ShGrid v0 = singleCell(16, {4, 8, 8}, isotropic(1.0f));
    const GvGrid facing = wall(frame, {-1, 0, 0});
    const GvGrid away = wall(frame, {1, 0, 0});
    // The GV cells sit where the surfels are: round((p - o) / s) = (7, y, z).
    EXPECT_NEAR(facing.at(7, 3, 5).x, sh::kCos0, 1e-6f);
    EXPECT_EQ(facing.at(6, 3, 5).x, 0.0f);

    // Head-on through the wall: 1 - (1/4 + 1/2) for the facing wall, nothing for the back of it.
    const glm::vec3 crossing(7.0f, 8.5f, 8.5f);
    const float tFacing = transmittance(facing, crossing, {1, 0, 0});
    const float tAway = transmittance(away, crossing, {1, 0, 0});
    report("occlusion.facing_wall_head_on_transmittance", tFacing);
    report("occlusion.away_wall_head_on_transmittance", tAway);
    EXPECT_NEAR(tFacing, 0.25f, 1e-6f);
    EXPECT_EQ(tAway, 1.0f);

    const glm::ivec3 probe(10, 8, 8);
    const auto open = propagateAndAccumulate(v0, nullptr, 16).at(0, probe.x, probe.y, probe.z).x;
    const auto blocked = propagateAndAccumulate(v0, &facing, 16).at(0, probe.x, probe.y, probe.z).x;
    const auto behind = propagateAndAccumulate(v0, &away, 16).at(0, probe.x, probe.y, probe.z).x;
    report("occlusion.probe_dc_open_over_facing_wall", open / blocked);
    report("occlusion.probe_dc_away_wall_over_open", behind / open);
    EXPECT_GT(open / blocked, 2.0f);
    EXPECT_GT(behind / open, 0.8f);
}

TEST(LpvReferenceOcclusion, GvSampleOutsideCountsZero) {
    GvGrid gv(4);
    for (auto& p : gv.potential)
        p = glm::vec4(1.0f);
    EXPECT_NEAR(gv.sample({2.0f, 2.0f, 2.0f}).x, 1.0f, 1e-6f);
    EXPECT_NEAR(gv.sample({4.5f, 2.0f, 2.0f}).x, 0.5f, 1e-6f);  // half of it beyond GV cell 4
    EXPECT_NEAR(gv.sample({-0.5f, -0.5f, 2.0f}).x, 0.25f, 1e-6f);
    EXPECT_EQ(gv.sample({-2.0f, 2.0f, 2.0f}).x, 0.0f);
}

TEST(LpvReferenceOcclusion, MergeByMaxKeepsTheLargerDc) {
    GvGrid a(2), b(2);
    a.at(0, 0, 0) = {0.5f, 0.3f, 0.0f, 0.0f};
    b.at(0, 0, 0) = {0.4f, -0.9f, 0.0f, 0.0f};
    a.at(1, 2, 0) = {0.1f, 0.0f, 0.2f, 0.0f};
    b.at(1, 2, 0) = {0.7f, 0.0f, -0.1f, 0.3f};
    b.at(2, 2, 2) = {0.2f, 0.0f, 0.0f, 0.1f};
    const GvGrid m = mergeByMax(a, b);
    EXPECT_EQ(m.at(0, 0, 0), a.at(0, 0, 0)); // whole SH of the winner, not per coefficient
    EXPECT_EQ(m.at(1, 2, 0), b.at(1, 2, 0));
    EXPECT_EQ(m.at(2, 2, 2), b.at(2, 2, 2));
    EXPECT_EQ(m.at(1, 1, 1), glm::vec4(0.0f));
}

TEST(LpvReferenceOcclusion, SurfelCoverageIsCappedAtOneCellFace) {
    const GridFrame frame{glm::vec3(0.0f), 2.0f, 4};
    const Surfel small{{2.9f, 4.2f, 5.1f}, {0, 1, 0}, 1.0f}; // round((1.45, 2.1, 2.55)) = (1, 2, 3)
    const Surfel huge{{2.9f, 4.2f, 5.1f}, {0, 1, 0}, 100.0f};
    EXPECT_NEAR(injectSurfels(frame, std::span(&small, 1)).at(1, 2, 3).x, 0.25f * sh::kCos0, 1e-6f);
    EXPECT_NEAR(injectSurfels(frame, std::span(&huge, 1)).at(1, 2, 3).x, sh::kCos0, 1e-6f);
    const Surfel outside{{9.5f, 4.0f, 4.0f}, {0, 1, 0}, 1.0f}; // GV x = round(4.75) = 5 > n
    const GvGrid none = injectSurfels(frame, std::span(&outside, 1));
    for (const glm::vec4& p : none.potential)
        EXPECT_EQ(p, glm::vec4(0.0f));
}

// ---------------------------------------------------------------- injection

TEST(LpvReferenceInjection, OffsetMovesTheVplAlongItsNormal) {
    const GridFrame frame{glm::vec3(-1.0f, 2.0f, 0.0f), 0.5f, 8};
    auto litCells = [&](const Vpl& v, float offset) {
        const ShGrid g = injectVpls(frame, std::span(&v, 1), offset);
        std::vector<glm::ivec3> lit;
        for (int z = 0; z < 8; ++z)
            for (int y = 0; y < 8; ++y)
                for (int x = 0; x < 8; ++x)
                    if (g.at(0, x, y, z) != glm::vec4(0.0f))
                        lit.emplace_back(x, y, z);
        return lit;
    };
    // Cell coordinate (3.4, 4.5, 4.5).
    const Vpl px{frame.origin + 0.5f * glm::vec3(3.4f, 4.5f, 4.5f), {1, 0, 0}, glm::vec3(1.0f)};
    EXPECT_EQ(litCells(px, 0.0f), std::vector{glm::ivec3(3, 4, 4)});
    EXPECT_EQ(litCells(px, 1.0f), std::vector{glm::ivec3(4, 4, 4)});
    const Vpl my{frame.origin + 0.5f * glm::vec3(4.5f, 4.2f, 4.5f), {0, -1, 0}, glm::vec3(1.0f)};
    EXPECT_EQ(litCells(my, 1.0f), std::vector{glm::ivec3(4, 3, 4)});
    // Dropped: outside the grid, and moved out of it by the offset.
    const Vpl out{frame.origin + 0.5f * glm::vec3(-0.1f, 4.5f, 4.5f), {0, 1, 0}, glm::vec3(1.0f)};
    EXPECT_TRUE(litCells(out, 0.0f).empty());
    const Vpl edge{frame.origin + 0.5f * glm::vec3(7.6f, 4.5f, 4.5f), {1, 0, 0}, glm::vec3(1.0f)};
    EXPECT_EQ(litCells(edge, 0.0f), std::vector{glm::ivec3(7, 4, 4)});
    EXPECT_TRUE(litCells(edge, 1.0f).empty());
}

TEST(LpvReferenceInjection, InjectedFluxIsTheVplsFlux) {
    const GridFrame frame{glm::vec3(-2.0f, 1.0f, 0.5f), 0.25f, 8};
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> pos(0.0f, 2.0f), dir(-1.0f, 1.0f), flux(0.0f, 3.0f);
    std::vector<Vpl> vpls;
    glm::dvec3 expected(0.0);
    for (int i = 0; i < 200; ++i) {
        Vpl v{frame.origin + glm::vec3(pos(rng), pos(rng), pos(rng)),
              glm::normalize(glm::vec3(dir(rng), dir(rng), dir(rng))), glm::vec3(flux(rng), flux(rng), flux(rng))};
        vpls.push_back(v);
        expected += glm::dvec3(v.flux);
    }
    // Several VPLs share cells: their intensities add.
    const ShGrid g = injectVpls(frame, vpls, 0.0f);
    double worst = 0.0;
    for (int c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(totalFlux(g, c) / expected[c] - 1.0));
    report("injection.total_flux_rel_error", worst);
    EXPECT_LT(worst, 1e-5);
}

// ---------------------------------------------------------------- point light

TEST(LpvReferencePointLight, IrradianceFollowsInverseSquare) {
    // An isotropic source of 1 W/sr in the middle of a 33^3 grid of 0.5 m cells;
    // a point light of the same intensity gives E = I / r^2 at r metres, facing it.
    const int n = 33;
    const GridFrame frame{glm::vec3(-4.0f, 0.0f, 1.0f), 0.5f, n};
    const glm::ivec3 source(16, 16, 16);
    const ShGrid v0 = singleCell(n, source, isotropic(1.0f));
    const glm::vec3 centre = frame.origin + frame.cellSize * (glm::vec3(source) + 0.5f);
    const int stepsList[] = {8, 16, 32};
    const int distances[] = {2, 4, 8};
    double ratio[3][3];
    std::cout << "steps | cells | E_lpv | E_exact | ratio\n";
    for (int si = 0; si < 3; ++si) {
        const ShGrid acc = propagateAndAccumulate(v0, nullptr, stepsList[si]);
        for (int di = 0; di < 3; ++di) {
            const float r = float(distances[di]) * frame.cellSize;
            const glm::vec3 x = centre + glm::vec3(r, 0, 0);
            const double e = irradianceAt(acc, frame, x, {-1, 0, 0}).x;
            const double exact = 1.0 / (double(r) * double(r));
            ratio[si][di] = e / exact;
            std::printf("%5d | %5d | %.5f | %.5f | %.4f\n", stepsList[si], distances[di], e, exact, e / exact);
            report("pointlight.ratio_steps" + std::to_string(stepsList[si]) + "_cells" +
                       std::to_string(distances[di]),
                   e / exact);
        }
    }
    // LPV is an approximation: within a factor 2 of the point light at 4 cells.
    EXPECT_GT(ratio[1][1], 0.5);
    EXPECT_LT(ratio[1][1], 2.0);
    // More steps only add light (the accumulator is a sum of non-negative lobes here).
    for (int di = 0; di < 3; ++di) {
        EXPECT_GE(ratio[1][di], ratio[0][di] * (1.0 - 1e-6));
        EXPECT_GE(ratio[2][di], ratio[1][di] * (1.0 - 1e-6));
    }
    // The far cell has not seen its light yet after 8 steps: it must gain with more.
    EXPECT_GT(ratio[1][2], ratio[0][2] * 1.05);
}

TEST(LpvReferencePointLight, TrilinearLookupClampsAndInterpolates) {
    ShGrid g(4);
    g.at(0, 1, 2, 2) = glm::vec4(2.0f);
    g.at(0, 2, 2, 2) = glm::vec4(4.0f);
    EXPECT_NEAR(sampleTrilinear(g, 0, {1.5f, 2.5f, 2.5f}).x, 2.0f, 1e-6f);
    EXPECT_NEAR(sampleTrilinear(g, 0, {2.0f, 2.5f, 2.5f}).x, 3.0f, 1e-6f);
    EXPECT_NEAR(sampleTrilinear(g, 0, {2.0f, 2.0f, 2.5f}).x, 1.5f, 1e-6f); // half of it in row y = 1
    g.at(0, 3, 3, 3) = glm::vec4(5.0f);
    EXPECT_NEAR(sampleTrilinear(g, 0, {9.0f, 9.0f, 9.0f}).x, 5.0f, 1e-6f); // clamped to the last centre
    // irradianceAt divides by the face area s^2: a cell of constant radiance-like intensity.
    const GridFrame frame{glm::vec3(1.0f), 0.5f, 4};
    ShGrid c(4);
    for (int ch = 0; ch < 3; ++ch)
        for (auto& v : c.channel[ch])
            v = isotropic(float(ch + 1));
    const glm::vec3 e = irradianceAt(c, frame, glm::vec3(2.0f), glm::normalize(glm::vec3(1, 1, 0)));
    for (int ch = 0; ch < 3; ++ch)
        EXPECT_NEAR(e[ch], kPi * (ch + 1) / 0.25, 1e-4);
}

// lpv.twoSidedOcclusion: a wall the GV saw from one side (normal -x) blocks
// light travelling +x (it meets the wall's front) either way, and light
// travelling -x (it meets the back) only when two-sided.
TEST(LpvReference, TwoSidedOcclusionBlocksLightReachingASurfelsBack) {
    GridFrame grid{glm::vec3(0.0f), 1.0f, 4};
    const std::vector<Surfel> wall{{glm::vec3(2.0f, 2.0f, 2.0f), glm::vec3(-1.0f, 0.0f, 0.0f), 1.0f}};
    GvGrid gv = injectSurfels(grid, wall);
    gv.strength = 4.0f / 3.0f;
    const glm::vec3 g(2.0f, 2.0f, 2.0f); // the surfel's GV cell
    const float intoFront = transmittance(gv, g, glm::vec3(1, 0, 0));
    const float intoBack = transmittance(gv, g, glm::vec3(-1, 0, 0));
    EXPECT_LT(intoFront, 0.05f);
    EXPECT_GT(intoBack, 0.95f) << "one-sided: light leaving past the back passes";
    gv.twoSided = true;
    EXPECT_FLOAT_EQ(transmittance(gv, g, glm::vec3(1, 0, 0)), intoFront);
    EXPECT_LT(transmittance(gv, g, glm::vec3(-1, 0, 0)), 0.05f);
    // Across the wall's plane (along it) nothing changes: the lobe is symmetric there.
    gv.twoSided = false;
    const float along = transmittance(gv, g, glm::vec3(0, 1, 0));
    gv.twoSided = true;
    EXPECT_FLOAT_EQ(transmittance(gv, g, glm::vec3(0, 1, 0)), along);
}
