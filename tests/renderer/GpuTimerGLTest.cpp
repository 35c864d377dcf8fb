#include "GlFixture.h"

#include "lpv/renderer/GpuTimer.h"

using namespace lpv::renderer;

class GpuTimerTest : public GlTest {};

TEST_F(GpuTimerTest, CollectsOneSamplePerFrameWithOrderedStats) {
    GpuTimer timer(16);
    const int frames = 10;
    for (int f = 0; f < frames; ++f) {
        timer.beginFrame();
        timer.begin("clear");
        glClear(GL_COLOR_BUFFER_BIT);
        timer.end("clear");
        timer.begin("second");
        timer.end("second");
    }
    timer.resolveAll();
    const auto table = timer.table();
    ASSERT_EQ(table.size(), 2u);
    EXPECT_EQ(table[0].pass, "clear");
    EXPECT_EQ(table[1].pass, "second");
    for (const PassTiming& t : table) {
        EXPECT_EQ(t.samples, std::size_t(frames));
        EXPECT_LE(t.minMs, t.medianMs);
        EXPECT_LE(t.medianMs, t.maxMs);
        EXPECT_GE(t.minMs, 0.0);
    }
}

TEST_F(GpuTimerTest, HistoryIsBounded) {
    GpuTimer timer(4);
    for (int f = 0; f < 12; ++f) {
        timer.beginFrame();
        timer.begin("p");
        timer.end("p");
    }
    timer.resolveAll();
    EXPECT_EQ(timer.table().front().samples, 4u);
}
