// The slice viewer's image code without a GPU: which cell lands where, the
// quantities, errors for slices out of range, colours and the legend, and the
// leak maps on a wall of known blocking.
#include "lpv/renderer/viz/SliceImage.h"
#include "lpv/renderer/lpv/LpvReference.h"
#include "lpv/renderer/lpv/Sh.h"
#include "lpv/renderer/viz/LeakMaps.h"
#include "lpv/renderer/viz/LpvViews.h"
#include "lpv/renderer/viz/TileImages.h"

#include <gtest/gtest.h>

using namespace lpv::renderer;
using namespace lpv::renderer::viz;

namespace {

constexpr int kN = 4;

std::size_t cell(int x, int y, int z) {
    return std::size_t(x + kN * (y + kN * z));
}

// Every cell's band 0 encodes its coordinates, so a slice shows where it read.
ShVolume coordinateVolume() {
    ShVolume v;
    for (auto& c : v)
        c.assign(kN * kN * kN, glm::vec4(0.0f));
    for (int z = 0; z < kN; ++z)
        for (int y = 0; y < kN; ++y)
            for (int x = 0; x < kN; ++x) {
                const float code = float(100 * x + 10 * y + z);
                v[0][cell(x, y, z)] = glm::vec4(code, 1.0f, 2.0f, 3.0f);
                v[1][cell(x, y, z)] = glm::vec4(2.0f * code, 0.0f, 0.0f, 0.0f);
                v[2][cell(x, y, z)] = glm::vec4(-code, 0.0f, 0.0f, 0.0f);
            }
    return v;
}

VolumeView view(const ShVolume& v) {
    return {kN, 0.5f, {&v[0], &v[1], &v[2]}};
}

} // namespace

TEST(SliceImage, AxesMapCellsToTheDocumentedImageAxes) {
    const ShVolume v = coordinateVolume();
    SliceSpec spec;
    spec.channel = Channel::Red;
    spec.axis = Axis::Z; // u = x, v = y
    spec.index = 2;
    auto f = extractSlice(view(v), spec);
    ASSERT_TRUE(f.has_value());
    EXPECT_EQ(f->at(3, 1), 312.0f);
    spec.axis = Axis::X; // u = z, v = y
    spec.index = 1;
    f = extractSlice(view(v), spec);
    ASSERT_TRUE(f.has_value());
    EXPECT_EQ(f->at(3, 2), 123.0f);
    spec.axis = Axis::Y; // u = x, v = z
    spec.index = 0;
    f = extractSlice(view(v), spec);
    ASSERT_TRUE(f.has_value());
    EXPECT_EQ(f->at(2, 3), 203.0f);
}

TEST(SliceImage, ChannelsLuminanceAndCoefficients) {
    const ShVolume v = coordinateVolume();
    SliceSpec spec;
    spec.index = 1;
    spec.channel = Channel::Green;
    EXPECT_EQ(extractSlice(view(v), spec)->at(1, 1), 2.0f * 111.0f);
    spec.channel = Channel::Luminance;
    EXPECT_NEAR(extractSlice(view(v), spec)->at(1, 1), (0.2126f + 0.7152f * 2.0f - 0.0722f) * 111.0f, 1e-3f);
    spec.channel = Channel::Rgb;
    const auto rgb = extractSlice(view(v), spec);
    ASSERT_EQ(rgb->components, 3);
    EXPECT_EQ(rgb->at(1, 1, 2), -111.0f);
    spec.channel = Channel::Red;
    spec.quantity = Quantity::Coefficient;
    spec.coefficient = 3;
    const auto k = extractSlice(view(v), spec);
    EXPECT_TRUE(k->isSigned);
    EXPECT_EQ(k->at(0, 0), 3.0f);
}

// Irradiance facing d is what shading computes: max(0, I . cosineLobe(-d)) / s^2.
TEST(SliceImage, DirectionalIsShadingIrradiance) {
    ShVolume v;
    for (auto& c : v)
        c.assign(kN * kN * kN, glm::vec4(0.0f));
    const glm::vec4 lobe = sh::vplIntensity(glm::vec3(0, -1, 0), 4.0f); // light travelling down
    v[0][cell(1, 1, 1)] = lobe;
    SliceSpec spec;
    spec.index = 1;
    spec.channel = Channel::Red;
    spec.quantity = Quantity::Directional;
    spec.direction = {0.0f, 1.0f, 0.0f}; // a floor facing up receives it
    const auto up = extractSlice(view(v), spec);
    EXPECT_NEAR(up->at(1, 1), sh::irradiance(lobe, glm::vec3(0, 1, 0)) / 0.25f, 1e-5f);
    EXPECT_GT(up->at(1, 1), 0.0f);
    spec.direction = {0.0f, -1.0f, 0.0f}; // a ceiling facing down does not
    EXPECT_EQ(extractSlice(view(v), spec)->at(1, 1), 0.0f);
}

TEST(SliceImage, OutOfRangeRequestsAreErrors) {
    const ShVolume v = coordinateVolume();
    SliceSpec spec;
    spec.index = kN;
    auto f = extractSlice(view(v), spec);
    ASSERT_FALSE(f.has_value());
    EXPECT_NE(f.error().describe().find("4 is outside 0..3 along z"), std::string::npos)
        << f.error().describe();
    spec.index = 0;
    spec.quantity = Quantity::Coefficient;
    spec.coefficient = 4;
    EXPECT_FALSE(extractSlice(view(v), spec).has_value());
    EXPECT_FALSE(extractSlice(VolumeView{}, SliceSpec{}).has_value());
}

TEST(SliceImage, RenderScalesColoursAndDrawsALegend) {
    SliceField f{2, 1, 1, false, {1.0f, 0.001f}};
    ColourSpec c;
    c.pixelsPerCell = 10;
    c.title = "TEST";
    SliceRange range;
    const lpv::scene::Image8 linear = renderSlice(f, c, &range);
    EXPECT_EQ(range.high, 1.0f);
    EXPECT_GT(linear.height, 10);
    auto pixel = [](const lpv::scene::Image8& im, int x, int y) {
        const std::uint8_t* p = &im.pixels[(std::size_t(y) * std::size_t(im.width) + std::size_t(x)) * 4];
        return glm::ivec3(p[0], p[1], p[2]);
    };
    EXPECT_EQ(pixel(linear, 5, 5), glm::ivec3(falseColour(1.0f) * 255.0f + 0.5f));
    const glm::ivec3 dim = pixel(linear, 15, 5);
    EXPECT_LT(dim.r + dim.g + dim.b, 10) << "0.1% of the peak is nearly black on a linear scale";
    c.scale = Scale::Log; // 4 decades: 0.001 sits a quarter of the way up
    const lpv::scene::Image8 log = renderSlice(f, c);
    EXPECT_EQ(pixel(log, 15, 5), glm::ivec3(falseColour(0.25f) * 255.0f + 0.5f));
    // The legend ramp: darkest on the left, brightest on the right.
    const glm::ivec3 left = pixel(log, 5, 10 + 8), right = pixel(log, log.width - 6, 10 + 8);
    EXPECT_LT(left.r + left.g + left.b, right.r + right.g + right.b);
    c.rangeMax = 2.0f;
    renderSlice(f, c, &range);
    EXPECT_EQ(range.high, 2.0f);
}

namespace {

glm::ivec3 rgbAt(const lpv::scene::Image8& im, int x, int y) {
    const std::uint8_t* p = &im.pixels[(std::size_t(y) * std::size_t(im.width) + std::size_t(x)) * 4];
    return {p[0], p[1], p[2]};
}

glm::ivec3 bytes(const glm::vec3& c) {
    return glm::ivec3(glm::round(c * 255.0f));
}

} // namespace

// Issue #46: the title under the legend ran off the image (" LOG" was not
// counted in its width). Every lit pixel of the caption is in the image,
// wrapped onto lines with a margin to every edge, however narrow the slice.
TEST(SliceImage, TheCaptionIsWhollyInsideTheImage) {
    const std::string title =
        "CASCADE 0  Z = 12  STEP 8/8 ACCUMULATED  IRRADIANCE W/M^2 FACING (0,1,0)  LUMINANCE";
    SliceField f{4, 4, 1, false, std::vector<float>(16, 1.0f)};
    for (const Scale scale : {Scale::Linear, Scale::Log}) {
        ColourSpec c;
        c.pixelsPerCell = 4; // a 16 px slice: the caption is far wider
        c.scale = scale;
        c.title = title;
        const lpv::scene::Image8 im = renderSlice(f, c);
        const std::string caption = title + (scale == Scale::Log ? "  LOG" : "");
        // The caption on a canvas wide enough for it on one line: its lit pixels.
        lpv::scene::Image8 whole{textWidth(caption, 2) + 8, 14, 4, {}};
        whole.pixels.assign(std::size_t(whole.width) * 14 * 4, 0);
        drawText(whole, 0, 0, caption, 2);
        int expected = 0;
        for (std::size_t i = 0; i < whole.pixels.size(); i += 4)
            expected += whole.pixels[i] > 0 ? 1 : 0;

        const glm::ivec3 grey = bytes(kCaptionColour);
        int shown = 0, lowest = -1, leftmost = im.width, rightmost = -1;
        for (int y = 0; y < im.height; ++y)
            for (int x = 0; x < im.width; ++x)
                if (rgbAt(im, x, y) == grey) {
                    ++shown;
                    lowest = std::max(lowest, y);
                    leftmost = std::min(leftmost, x);
                    rightmost = std::max(rightmost, x);
                }
        EXPECT_EQ(shown, expected) << "every letter of \"" << caption << "\" is drawn";
        EXPECT_LE(lowest, im.height - 4) << "a margin under the last line";
        EXPECT_GE(leftmost, 4);
        EXPECT_LE(rightmost, im.width - 5) << "a margin to the right";
    }
}

// Issue #46: a slice says where it lies: the world coordinates of its edges,
// a scale bar in scene units (the same bar for a scene in metres or
// millimetres, labelled in its own units) and the outline of the geometry
// crossing the plane.
TEST(SliceImage, GuidesGiveWorldAxesAScaleBarAndTheGeometrysOutline) {
    EXPECT_FLOAT_EQ(scaleBarLength(4.0f), 1.0f);
    EXPECT_FLOAT_EQ(scaleBarLength(4000.0f), 1000.0f);
    EXPECT_FLOAT_EQ(scaleBarLength(10.0f), 2.0f);
    EXPECT_FLOAT_EQ(scaleBarLength(20.0f), 5.0f);
    EXPECT_NEAR(scaleBarLength(0.03f), 0.01f, 1e-7f);

    constexpr int n = 16, ppc = 8;
    SliceField f{n, n, 1, false, std::vector<float>(n * n, 0.5f)};
    ColourSpec c;
    c.pixelsPerCell = ppc;
    c.title = "CASCADE 0  Z = 4";
    const lpv::scene::Image8 bare = renderSlice(f, c);
    for (const float unit : {1.0f, 1000.0f}) { // metres, then millimetres
        SliceGuides g;
        g.axis = Axis::Z;
        g.origin = glm::vec2(-1.0f, 0.5f) * unit;
        g.cellSize = 0.25f * unit;
        g.plane = 1.125f * unit;
        g.geometry.assign(n * n, 0);
        for (int v = 6; v <= 9; ++v)
            for (int u = 6; u <= 9; ++u)
                g.geometry[std::size_t(v * n + u)] = 1;
        const lpv::scene::Image8 im = renderSlice(f, c, nullptr, &g);
        ASSERT_GT(im.height, bare.height) << "the u axis's coordinates and the scale bar under it";
        EXPECT_EQ(rgbAt(im, 4, 4), rgbAt(bare, 4, 4)) << "the slice stays at the top left";

        const glm::ivec3 label = bytes(kAxisLabelColour);
        int beside = 0, under = 0;
        for (int y = 0; y < im.height; ++y)
            for (int x = 0; x < im.width; ++x)
                if (rgbAt(im, x, y) == label)
                    (x >= n * ppc && y < n * ppc ? beside : y >= n * ppc ? under : beside) += 1;
        EXPECT_GT(beside, 20) << "v's coordinates right of the slice";
        EXPECT_GT(under, 20) << "u's coordinates, the bar's length and the plane under it";

        // The scale bar: 1 unit of 4 is 4 cells, 32 pixels, in either unit.
        const glm::ivec3 white = bytes(kScaleBarColour);
        int longest = 0;
        for (int y = n * ppc; y < n * ppc + 32; ++y)
            for (int x = 0, run = 0; x < im.width; ++x) {
                run = rgbAt(im, x, y) == white ? run + 1 : 0;
                longest = std::max(longest, run);
            }
        EXPECT_EQ(longest, 32) << "unit " << unit;

        // The outline: the block's edge cells are cyan at their border, not inside.
        const glm::ivec3 cyan = bytes(kOutlineColour);
        const int rowOf7 = (n - 1 - 7) * ppc + ppc / 2;
        EXPECT_EQ(rgbAt(im, 6 * ppc, rowOf7), cyan) << "the block's left edge";
        EXPECT_EQ(rgbAt(im, 10 * ppc - 1, rowOf7), cyan) << "its right edge";
        EXPECT_EQ(rgbAt(im, 8 * ppc, (n - 1 - 9) * ppc), cyan) << "its top edge (v up)";
        EXPECT_NE(rgbAt(im, 7 * ppc + ppc / 2, rowOf7), cyan) << "inside the block";
        EXPECT_NE(rgbAt(im, 4 * ppc + ppc / 2, rowOf7), cyan) << "outside it";
    }
}

TEST(SliceImage, SignedValuesUseTheDivergingRamp) {
    SliceField f{2, 1, 1, true, {-1.0f, 1.0f}};
    const lpv::scene::Image8 im = renderSlice(f, ColourSpec{});
    const std::uint8_t* neg = &im.pixels[4 * 4];
    const std::uint8_t* pos = &im.pixels[12 * 4];
    EXPECT_GT(neg[2], neg[0]) << "negative: blue";
    EXPECT_GT(pos[0], pos[2]) << "positive: red";
}

TEST(SliceImage, TextIsDrawn) {
    lpv::scene::Image8 im{40, 10, 4, std::vector<std::uint8_t>(40 * 10 * 4, 0)};
    drawText(im, 0, 0, "1.5E-3", 1);
    int lit = 0;
    for (std::size_t i = 0; i < im.pixels.size(); i += 4)
        lit += im.pixels[i] > 0;
    EXPECT_GT(lit, 20);
    EXPECT_EQ(textWidth("ABC", 2), 22);
}

// A full wall of surfels facing -x at GV x = 2 between a light travelling +x
// and the far side: the leak map shows the light that still crosses it, the
// back-side map the light that reaches the wall's back.
TEST(LeakMaps, WallOfKnownBlocking) {
    const int n = 6;
    lpvref::GridFrame grid{glm::vec3(0.0f), 1.0f, n};
    std::vector<lpvref::Surfel> wall;
    for (int y = 0; y <= n; ++y)
        for (int z = 0; z <= n; ++z)
            wall.push_back({glm::vec3(2.0f, float(y), float(z)), glm::vec3(-1, 0, 0), 1.0f});
    const lpvref::GvGrid gv = lpvref::injectSurfels(grid, wall);
    ShVolume light;
    for (auto& c : light)
        c.assign(std::size_t(n * n * n), glm::vec4(0.0f));
    const auto at = [&](int x, int y, int z) { return std::size_t(x + n * (y + n * z)); };
    for (auto& c : light)
        c[at(1, 3, 3)] = sh::vplIntensity(glm::vec3(1, 0, 0), 10.0f); // shining at the wall

    const ShVolume heat = leakHeat(light, gv.potential, n, true, 0.3f);
    EXPECT_GT(heat[0][at(2, 3, 3)].x, 0.0f)
        << "a quarter of the light crosses the wall (blocking 0.75 head-on)";
    EXPECT_EQ(heat[0][at(1, 4, 3)].x, 0.0f) << "the face between (1,3,3) and (1,4,3) is no wall";
    const ShVolume open = leakHeat(light, gv.potential, n, false, 0.3f);
    EXPECT_GT(open[0][at(2, 3, 3)].x, 3.0f * heat[0][at(2, 3, 3)].x) << "occlusion off: all of it crosses";
    const ShVolume none =
        leakHeat(light, std::vector<glm::vec4>(gv.potential.size(), glm::vec4(0.0f)), n, true);
    EXPECT_EQ(none[0][at(2, 3, 3)].x, 0.0f) << "no GV: no wall, nothing counts as a leak";

    // Light travelling +x reaches the back side of a wall facing +x placed in its cell.
    std::vector<lpvref::Surfel> facingPlusX;
    for (int y = 0; y <= n; ++y)
        for (int z = 0; z <= n; ++z)
            for (int x : {1, 2})
                facingPlusX.push_back({glm::vec3(float(x), float(y), float(z)), glm::vec3(1, 0, 0), 0.5f});
    const lpvref::GvGrid gv2 = lpvref::injectSurfels(grid, facingPlusX);
    const ShVolume back = backsideLight(light, gv2.potential, {glm::vec3(0.0f), 1.0f, n}, 0.3f);
    EXPECT_NEAR(back[0][at(1, 3, 3)].x, sh::irradiance(light[0][at(1, 3, 3)], glm::vec3(-1, 0, 0)), 1e-5f);
    EXPECT_GT(back[0][at(1, 3, 3)].x, 0.0f);
    const ShVolume front = backsideLight(light, gv.potential, {glm::vec3(0.0f), 1.0f, n}, 0.3f);
    EXPECT_EQ(front[0][at(1, 3, 3)].x, 0.0f) << "a wall facing the light is lit on its front only";
}

TEST(TileImages, RowHoldsEveryTileWithItsLabel) {
    DebugImage a{"rsm-0-flux", 8, 8, 4, std::vector<float>(8 * 8 * 4, 1.0f)};
    DebugImage b{"shadow-cascade-0", 16, 16, 1, std::vector<float>(16 * 16, 0.5f)};
    const lpv::scene::Image8 row = tileRow({a, b}, 8);
    EXPECT_GE(row.width, 8 + 8 + 12);
    EXPECT_GT(row.height, 8);
    EXPECT_EQ(imagesNamed({a, b}, "rsm-0-").size(), 1u);
    const lpv::scene::Image8 flux = debugImageView(a);
    EXPECT_EQ(flux.pixels[0], 255);
}
