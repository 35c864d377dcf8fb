// `lpv bench lpv` as a user runs it, on a small imported scene with a sun:
// the tables exist, name every variant with occlusion off and on, and hold
// measured figures; bad lists are usage errors.
#include "RunLpv.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

using namespace lpv::test;
namespace fs = std::filesystem;

namespace {

std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
        ++n;
    return n;
}

TEST(BenchLpv, WritesTheThesisTablesForEveryVariant) {
    const fs::path dir = freshTempDir("bench-lpv");
    const fs::path project = dir / "box.lpvproj";
    const RunResult imported =
        runLpv("import '" + (fs::path(kSharedScenesDir) / "gltf-small/Box/glTF/Box.gltf").string() + "' -o '" +
               project.string() + "'");
    ASSERT_EQ(imported.exitCode, 0) << imported.output;
    const fs::path md = dir / "lpv.md", csv = dir / "lpv.csv";
    const RunResult r = runLpv("bench lpv '" + project.string() +
                               "' --tiles 32,64 --steps 1,2 --frames 1 --warmup 0 --rounds 2 --width 64 --height 48 --markdown '" +
                               md.string() + "' --csv '" + csv.string() + "'");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("Fastest variant"), std::string::npos) << r.output;
    const std::string table = readText(md);
    EXPECT_NE(table.find("Machine: "), std::string::npos);
    // Issue #43: all 18 settings timed in the same interleaved rounds, each
    // figure with its spread, and settings within the noise named.
    EXPECT_NE(table.find("Load: load "), std::string::npos) << table;
    EXPECT_NE(table.find("Timing: 2 interleaved rounds"), std::string::npos) << table;
    EXPECT_NE(table.find("stopped: round limit after 2 rounds"), std::string::npos) << table;
    EXPECT_NE(table.find("| rsm + injection | same cost as |"), std::string::npos) << table;
    EXPECT_NE(table.find("| fastest | median ms | same cost within the noise |"), std::string::npos) << table;
    EXPECT_NE(table.find(" ±"), std::string::npos) << table;
    EXPECT_NE(table.find("| 32^2 |"), std::string::npos);
    EXPECT_NE(table.find("| 64^2 |"), std::string::npos);
    for (const char* variant : {"computeGather", "computeScatter", "rasterGather", "rasterScatter"})
        for (const char* occlusion : {"off", "on"}) // one row per step count
            EXPECT_EQ(count(table, "| " + std::string(occlusion) + " | " + variant + " | "), 2u) << variant;
    // Every propagation row has a measured time, not a dash.
    EXPECT_EQ(count(table, " | - |"), 0u) << table;
    const std::string rows = readText(csv);
    EXPECT_EQ(rows.substr(0, rows.find('\n')),
              "table,rsm.tileSize,lpv.variant,lpv.occlusion,lpv.propagationSteps,pass,median_ms,q1_ms,q3_ms,min_ms,"
              "max_ms,rounds,frames");
    std::size_t propagationRows = 0;
    std::istringstream lines(rows);
    for (std::string line; std::getline(lines, line);)
        if (line.rfind("steps,", 0) == 0 && line.find(",lpvPropagation,") != std::string::npos) {
            ++propagationRows;
            EXPECT_TRUE(line.ends_with(",2,2")) << "2 rounds of 1 frame: " << line;
        }
    EXPECT_EQ(propagationRows, 16u) << rows; // 4 variants x 2 step counts x occlusion off/on
    fs::remove_all(dir);
}

TEST(BenchLpv, BadListsAreUsageErrors) {
    EXPECT_EQ(runLpv("bench lpv '" + cornellProject() + "' --steps 1,65").exitCode, 2);
    EXPECT_EQ(runLpv("bench lpv '" + cornellProject() + "' --tiles 16").exitCode, 2);
    EXPECT_EQ(runLpv("bench lpv").exitCode, 2);
}

} // namespace
