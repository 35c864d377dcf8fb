// The profiler table shows each pass's numbers and the frame total; the
// chart gets one point per frame per pass, and nothing while hidden.
#include "ProfilerPanel.h"

#include <QLineSeries>
#include <QTableWidget>

#include <gtest/gtest.h>

using lpv::editor::ProfilerPanel;
using lpv::renderer::PassTiming;

namespace {

std::vector<PassTiming> fakeTable(double scale) {
    PassTiming rsm{"rsm", 1.0 * scale, 0.5 * scale, 2.0 * scale, 1.25 * scale, 10};
    PassTiming propagate{"lpvPropagate", 3.0 * scale, 2.5 * scale, 4.0 * scale, 2.75 * scale, 10};
    return {rsm, propagate};
}

QString text(const QTableWidget* t, int row, int column) {
    const QTableWidgetItem* item = t->item(row, column);
    return item ? item->text() : QString();
}

} // namespace

TEST(ProfilerPanel, TableShowsPassesAndFrameTotal) {
    ProfilerPanel panel;
    panel.show();
    panel.addFrame(fakeTable(1.0));
    panel.refreshNow();
    const QTableWidget* t = panel.table();
    ASSERT_EQ(t->rowCount(), 3); // two passes and the frame
    EXPECT_EQ(text(t, 0, 0), "rsm");
    EXPECT_EQ(text(t, 0, 1), "1.250");  // last
    EXPECT_EQ(text(t, 0, 2), "1.000");  // median
    EXPECT_EQ(text(t, 0, 3), "0.500");  // min
    EXPECT_EQ(text(t, 0, 4), "2.000");  // max
    EXPECT_EQ(text(t, 0, 5), "25.0 %"); // 1 of 4 ms of medians
    EXPECT_EQ(text(t, 1, 0), "lpvPropagate");
    EXPECT_EQ(text(t, 1, 5), "75.0 %");
    EXPECT_TRUE(text(t, 2, 0).startsWith(ProfilerPanel::kFrameName));
    EXPECT_EQ(text(t, 2, 1), "4.000"); // 1.25 + 2.75
}

TEST(ProfilerPanel, ChartGetsOnePointPerFramePerPass) {
    ProfilerPanel panel;
    panel.show();
    for (int i = 1; i <= 3; ++i)
        panel.addFrame(fakeTable(double(i)));
    panel.refreshNow();
    QLineSeries* rsm = panel.series("rsm");
    QLineSeries* propagate = panel.series("lpvPropagate");
    QLineSeries* frame = panel.series(ProfilerPanel::kFrameName);
    ASSERT_TRUE(rsm && propagate && frame);
    ASSERT_EQ(rsm->count(), 3);
    ASSERT_EQ(frame->count(), 3);
    EXPECT_DOUBLE_EQ(rsm->at(2).y(), 3.75);   // last ms of the third frame
    EXPECT_DOUBLE_EQ(frame->at(2).y(), 12.0); // 3.75 + 8.25
    EXPECT_LE(frame->at(2).x(), 0.0);         // seconds before now
    EXPECT_GT(frame->at(0).x(), -ProfilerPanel::kWindowSeconds);
    // The frame total's median, min and max come from the frames seen: 4, 8, 12.
    EXPECT_EQ(text(panel.table(), 2, 2), "8.000");
    EXPECT_EQ(text(panel.table(), 2, 3), "4.000");
    EXPECT_EQ(text(panel.table(), 2, 4), "12.000");
}

TEST(ProfilerPanel, HiddenPanelOnlyRecordsAndCatchesUpWhenShown) {
    ProfilerPanel panel;
    panel.addFrame(fakeTable(1.0));
    panel.addFrame(fakeTable(2.0));
    EXPECT_EQ(panel.series("rsm"), nullptr) << "no chart work while hidden";
    EXPECT_EQ(panel.table()->rowCount(), 0);
    panel.show();
    ASSERT_NE(panel.series("rsm"), nullptr);
    EXPECT_EQ(panel.series("rsm")->count(), 2);
    EXPECT_EQ(panel.table()->rowCount(), 3);
}

TEST(ProfilerPanel, PassThatStopsRunningLeavesTheTable) {
    ProfilerPanel panel;
    panel.show();
    panel.addFrame(fakeTable(1.0));
    panel.addFrame({fakeTable(1.0)[1]});
    panel.refreshNow();
    ASSERT_EQ(panel.table()->rowCount(), 2);
    EXPECT_EQ(text(panel.table(), 0, 0), "lpvPropagate");
    panel.clear();
    EXPECT_EQ(panel.table()->rowCount(), 0);
    EXPECT_EQ(panel.series("lpvPropagate"), nullptr);
}

// A pass whose timer query has no result yet (samples 0) has no time: counted
// as 0 ms it made the Frame row's Min read 0.000 (issue #26).
TEST(ProfilerPanel, RowsWithoutASampleDoNotCountAsZeroMilliseconds) {
    ProfilerPanel panel;
    panel.show();
    std::vector<PassTiming> inFlight = fakeTable(1.0);
    for (PassTiming& t : inFlight)
        t = PassTiming{t.pass, 0.0, 0.0, 0.0, 0.0, 0};
    panel.addFrame(inFlight);
    panel.addFrame(fakeTable(1.0));
    panel.refreshNow();
    ASSERT_EQ(panel.table()->rowCount(), 3);
    EXPECT_EQ(text(panel.table(), 2, 3), "4.000"); // the Frame row's Min
    EXPECT_EQ(panel.series(ProfilerPanel::kFrameName)->count(), 1);
}
