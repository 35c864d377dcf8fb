// The tables of `lpv bench render` on synthetic timings (issue #43): no GL,
// no process; the command's own functions. Two settings whose totals lie
// within each other's noise are named the same cost, a 2x one is not. (The
// thesis phases are lpv_bench's: tests/bench/ThesisSettingsTest.cpp.)
#include "BenchReport.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

using namespace lpv;
using namespace lpv::cli;

namespace {

// A run with one pass "shading" whose rounds gave `samples`.
BenchRun runOf(const std::string& value, const std::vector<double>& samples) {
    BenchRun run;
    run.settings = {{"shadow.mapSize", value}};
    const bench::TimingStats t = bench::timingStatsOf(samples);
    run.passes = {{"shading", t.median, t.min, t.max, samples.back(), samples.size() * 5}};
    run.passStats = {t};
    run.total = t;
    return run;
}

// The Markdown row whose first cell is `value`.
std::string rowOf(const std::string& markdown, const std::string& value) {
    std::istringstream lines(markdown);
    for (std::string line; std::getline(lines, line);)
        if (line.rfind("| " + value + " |", 0) == 0)
            return line;
    return {};
}

TEST(BenchTables, EqualCostRunsAreTheSameCostAndA2xOneIsNot) {
    // 256 and 512: the same cost with a 2% difference inside a ~4% spread; 1024: twice as long.
    const std::vector<BenchRun> runs = {runOf("256", {98.0, 100.0, 102.0, 99.0, 101.0}),
                                        runOf("512", {100.0, 102.0, 104.0, 101.0, 103.0}),
                                        runOf("1024", {196.0, 200.0, 204.0, 198.0, 202.0})};
    ASSERT_TRUE(bench::sameCost(runs[0].total, runs[1].total));
    ASSERT_FALSE(bench::sameCost(runs[0].total, runs[2].total));
    const std::string md =
        benchMarkdown(runs, "lpv bench render x.lpvproj", "test machine",
                      {5, "every spread within 10% after 5 rounds", "load 0.10 0.10 0.10 -> load 0.20 0.10 0.10"});
    EXPECT_NE(md.find("Machine: test machine"), std::string::npos) << md;
    EXPECT_NE(md.find("Load: load 0.10 0.10 0.10 -> load 0.20 0.10 0.10"), std::string::npos) << md;
    EXPECT_NE(md.find("Timing: 5 interleaved rounds"), std::string::npos) << md;
    EXPECT_NE(md.find("stopped: every spread within 10% after 5 rounds"), std::string::npos) << md;
    EXPECT_NE(md.find("| shadow.mapSize | shading | total | q1-q3 | rounds | same cost as |"), std::string::npos)
        << md;
    // Each row: the median ± half the interquartile range, the quartiles, the rounds, who costs the same.
    EXPECT_EQ(rowOf(md, "256"),
              "| 256 | 100.000 ±1.000 | 100.000 ±1.000 | 99.000-101.000 | 5 | shadow.mapSize=512 |");
    EXPECT_EQ(rowOf(md, "512"),
              "| 512 | 102.000 ±1.000 | 102.000 ±1.000 | 101.000-103.000 | 5 | shadow.mapSize=256 |");
    EXPECT_EQ(rowOf(md, "1024"), "| 1024 | 200.000 ±2.000 | 200.000 ±2.000 | 198.000-202.000 | 5 | none |");

    EXPECT_EQ(benchSameCostAs(runs, 0), (std::vector<std::size_t>{1}));
    EXPECT_TRUE(benchSameCostAs(runs, 2).empty());
    const std::string comparison = benchComparison(runs);
    EXPECT_NE(comparison.find("shadow.mapSize=1024"), std::string::npos) << comparison;
    EXPECT_NE(comparison.find("none"), std::string::npos) << comparison;
}

TEST(BenchTables, CsvHasTheQuartilesRoundsAndTheSameCostOnTotalRows) {
    const std::vector<BenchRun> runs = {runOf("256", {98.0, 100.0, 102.0}), runOf("512", {99.0, 101.0, 103.0})};
    const std::string csv = benchCsv(runs);
    EXPECT_EQ(csv, "shadow.mapSize,pass,median_ms,q1_ms,q3_ms,min_ms,max_ms,rounds,frames,same_cost_as\n"
                   "256,shading,100.000,99.000,101.000,98.000,102.000,3,15,\n"
                   "256,total,100.000,99.000,101.000,98.000,102.000,3,15,shadow.mapSize=512\n"
                   "512,shading,101.000,100.000,102.000,99.000,103.000,3,15,\n"
                   "512,total,101.000,100.000,102.000,99.000,103.000,3,15,shadow.mapSize=256\n");
}

TEST(BenchTables, PrintedTableGivesTheSpreadInPercent) {
    // Quartiles 95 and 105 around 100: an interquartile range of 10%.
    const BenchRun run = runOf("256", {90.0, 95.0, 100.0, 105.0, 110.0});
    const std::string table = benchTable(run);
    EXPECT_NE(table.find("q1-q3"), std::string::npos) << table;
    EXPECT_NE(table.find("95.000-105.000"), std::string::npos) << table;
    EXPECT_NE(table.find(" 10% "), std::string::npos) << table;
    EXPECT_NE(table.find("90.000-110.000"), std::string::npos) << table;
    EXPECT_NE(table.find("\ntotal "), std::string::npos) << table;
    EXPECT_EQ(benchComparison({run}), "") << "one setting compares with nothing";
}

} // namespace
