// The display mapping's CPU twin (DisplayMapping.h): the operators' whites
// that auto exposure meters toward, and the neutral operator's shoulder.
#include "lpv/renderer/DisplayMapping.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace lpv::renderer;

namespace {
constexpr Tonemapper kAll[] = {Tonemapper::Aces, Tonemapper::Reinhard, Tonemapper::Uncharted2, Tonemapper::Linear,
                               Tonemapper::Neutral};

int byteOf(float display) { return int(std::lround(display * 255.0f)); }
bool shownWhite(const glm::vec3& display) {
    return byteOf(display.r) == 255 && byteOf(display.g) == 255 && byteOf(display.b) == 255;
}
} // namespace

TEST(DisplayMapping, WhiteInputIsWhereAGreyFirstShowsAsWhite) {
    for (const Tonemapper op : kAll) {
        const double white = whiteInput(op);
        EXPECT_TRUE(shownWhite(mapToDisplay(glm::vec3(float(white)), {1.0, op}))) << int(op);
        EXPECT_FALSE(shownWhite(mapToDisplay(glm::vec3(float(white * 0.99)), {1.0, op}))) << int(op);
    }
    // Linear clips at 1 less the last code's rounding; ACES near 6.4; neutral a stop further (13.5).
    EXPECT_NEAR(whiteInput(Tonemapper::Linear), 0.9955, 1e-3);
    EXPECT_GT(whiteInput(Tonemapper::Aces), 4.0);
    EXPECT_GT(whiteInput(Tonemapper::Neutral), 2.0 * whiteInput(Tonemapper::Aces));
}

TEST(DisplayMapping, NeutralIsLinearBelowItsShoulderAndKeepsTheHueAboveIt) {
    // Below 0.76 it only lifts the toe offset (0.04) off: a mid grey stays a mid grey.
    const glm::vec3 mid = mapToDisplay(glm::vec3(0.5f), {1.0, Tonemapper::Neutral});
    const glm::vec3 expected = mapToDisplay(glm::vec3(0.46f), {1.0, Tonemapper::Linear});
    EXPECT_NEAR(mid.g, expected.g, 1e-6);
    // A warm sunlit stone 4x past white keeps its order of channels and is not
    // white yet, where ACES has clipped every channel.
    const glm::vec3 stone = glm::vec3(1.0f, 0.8f, 0.6f) * float(whiteInput(Tonemapper::Neutral));
    const glm::vec3 neutral = mapToDisplay(stone, {1.0, Tonemapper::Neutral});
    EXPECT_GT(neutral.r, neutral.g);
    EXPECT_GT(neutral.g, neutral.b);
    EXPECT_FALSE(shownWhite(neutral));
    EXPECT_TRUE(shownWhite(mapToDisplay(stone, {1.0, Tonemapper::Aces})));
}

TEST(DisplayMapping, TheMeterTargetsTheChosenOperatorsWhite) {
    lpv::scene::ParameterSet params;
    EXPECT_EQ(params.getEnum("output.tonemapper"), "neutral");
    EXPECT_DOUBLE_EQ(meterTargetOf(params).highlightInput, whiteInput(Tonemapper::Neutral));
    EXPECT_DOUBLE_EQ(meterTargetOf(params).highlightPercent, 98.0);
    ASSERT_TRUE(params.set("output.tonemapper", std::string("aces")).has_value());
    EXPECT_DOUBLE_EQ(meterTargetOf(params).highlightInput, whiteInput(Tonemapper::Aces));
}
