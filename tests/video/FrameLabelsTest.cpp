// Side-by-side composition and the built-in label font.
#include "lpv/video/FrameLabels.h"

#include <gtest/gtest.h>

using namespace lpv;
using namespace lpv::video;

namespace {

std::vector<std::uint8_t> flat(int w, int h, std::uint8_t v) {
    std::vector<std::uint8_t> p(std::size_t(w) * std::size_t(h) * 4, v);
    for (std::size_t i = 3; i < p.size(); i += 4)
        p[i] = 255;
    return p;
}

std::uint8_t at(const scene::Image8& image, int x, int y, int c = 0) {
    return image.pixels[(std::size_t(y) * std::size_t(image.width) + std::size_t(x)) * 4 + std::size_t(c)];
}

int countWhite(const scene::Image8& image, int x0, int x1, int y0, int y1) {
    int n = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x)
            n += at(image, x, y) == 255;
    return n;
}

} // namespace

TEST(FrameLabels, ScaleGrowsWithTheFrame) {
    EXPECT_EQ(labelScale(120), 1);
    EXPECT_EQ(labelScale(720), 4);
    EXPECT_EQ(labelScale(1080), 6);
    EXPECT_EQ(labelWidth("AB", 1), 11);
    EXPECT_EQ(labelWidth("", 3), 0);
    EXPECT_EQ(labelHeight(2), 14);
}

TEST(FrameLabels, SideBySidePutsLeftThenRight) {
    const scene::Image8 out = sideBySide(flat(10, 4, 40), 10, flat(7, 4, 90), 7, 4, "", "");
    EXPECT_EQ(out.width, 17);
    EXPECT_EQ(out.height, 4);
    EXPECT_EQ(at(out, 0, 0), 40);
    EXPECT_EQ(at(out, 8, 3), 40);
    EXPECT_EQ(at(out, 9, 0), 230) << "divider";
    EXPECT_EQ(at(out, 10, 0), 230) << "divider";
    EXPECT_EQ(at(out, 11, 2), 90);
    EXPECT_EQ(at(out, 16, 3), 90);
    EXPECT_EQ(at(out, 16, 3, 3), 255) << "opaque";
}

TEST(FrameLabels, LabelsAreDrawnInTheirOwnHalf) {
    const int w = 80, h = 60;
    const scene::Image8 plain = sideBySide(flat(w, h, 60), w, flat(w, h, 60), w, h, "", "");
    const scene::Image8 labelled = sideBySide(flat(w, h, 60), w, flat(w, h, 60), w, h, "LPV OFF", "lpv on");
    // White text pixels in the top-left of each half, none below the labels.
    EXPECT_EQ(countWhite(plain, 0, 2 * w, 0, 20), 0);
    EXPECT_GT(countWhite(labelled, 0, w - 1, 0, 20), 20);
    EXPECT_GT(countWhite(labelled, w + 1, 2 * w, 0, 20), 20);
    EXPECT_EQ(countWhite(labelled, 0, 2 * w, 20, h), 0);
    // The box darkens what is behind it.
    EXPECT_LT(at(labelled, 3, 3), 60);
    // "lpv on" in lower case draws as "LPV ON": the same pixels as upper case.
    const scene::Image8 upper = sideBySide(flat(w, h, 60), w, flat(w, h, 60), w, h, "LPV OFF", "LPV ON");
    EXPECT_EQ(labelled.pixels, upper.pixels);
}

TEST(FrameLabels, LongLabelsAreClippedToTheirHalf) {
    const int w = 30, h = 40;
    const scene::Image8 out =
        sideBySide(flat(w, h, 10), w, flat(w, h, 10), w, h, "A VERY LONG LABEL INDEED", "");
    EXPECT_EQ(countWhite(out, w + 1, 2 * w, 0, h), 0) << "nothing spills into the right half";
    EXPECT_EQ(at(out, w + 5, 5), 10);
}

TEST(FrameLabels, UnknownCharactersDrawAsQuestionMarks) {
    scene::Image8 a{40, 20, 4, flat(40, 20, 0)};
    scene::Image8 b = a;
    drawLabel(a, 0, 0, "\x7f", 1, 40);
    drawLabel(b, 0, 0, "?", 1, 40);
    EXPECT_EQ(a.pixels, b.pixels);
}
