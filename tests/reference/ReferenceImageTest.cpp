#include "lpv/reference/ReferenceImage.h"

#include <gtest/gtest.h>

namespace {

using namespace lpv::reference;

TEST(ReferenceImage, ChannelsRoundTrip) {
    ReferenceImage a;
    a.resize(3, 2);
    for (std::size_t i = 0; i < a.pixelCount(); ++i) {
        a.image[i] = glm::vec3(float(i), 1.0f, 2.0f);
        a.indirectOne[i] = glm::vec3(0.5f * float(i));
        a.indirectMulti[i] = glm::vec3(0.25f * float(i), 0.0f, 3.0f);
        a.indirectMultiVariance[i] = glm::vec3(1e-3f * float(i));
        a.coverage[i] = i % 2 ? 1.0f : 0.0f;
    }
    const auto channels = toChannels(a);
    EXPECT_EQ(channels.size(), 19u);
    EXPECT_EQ(channels[0].name, "R");
    EXPECT_EQ(channels[5].name, "indirect1.B");
    ReferenceImage b;
    ASSERT_TRUE(fromChannels(channels, 3, 2, b));
    EXPECT_EQ(b.image, a.image);
    EXPECT_EQ(b.indirectOne, a.indirectOne);
    EXPECT_EQ(b.indirectMulti, a.indirectMulti);
    EXPECT_EQ(b.indirectMultiVariance, a.indirectMultiVariance);
    EXPECT_EQ(b.coverage, a.coverage);
    EXPECT_FALSE(fromChannels(channels, 2, 2, b)) << "sizes that do not match are refused";
}

} // namespace
