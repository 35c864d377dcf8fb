// `lpv bench report --quick` as a user runs it, on the Cornell box alone at a
// tiny size: every question's sweep ran against the reference, the summary
// names the project's own settings and the radiosity measurement, and the
// JSON holds finite errors.
#include "RunLpv.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

using namespace lpv::test;
namespace fs = std::filesystem;

TEST(BenchReport, QuickCornellReportHasSweepsAndRadiosity) {
    const fs::path dir = fs::temp_directory_path() / ("lpv-bench-report-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    const RunResult r = runLpv("bench report --quick --scene cornell-box --out '" + dir.string() +
                               "' --width 64 --height 48 --spp 64 --frames 1 --warmup 0");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    ASSERT_TRUE(fs::exists(dir / "report.md")) << r.output;
    std::ifstream in(dir / "report.json");
    const auto j = nlohmann::json::parse(in, nullptr, false);
    ASSERT_FALSE(j.is_discarded());
    ASSERT_EQ(j["scenes"].size(), 1u);
    const auto& scene = j["scenes"][0];
    EXPECT_EQ(scene["name"], "cornell-box");
    EXPECT_TRUE(scene["failures"].empty()) << scene["failures"].dump();
    // --quick: steps 0,4,16; grid 16,32; occlusion false,true.
    ASSERT_EQ(scene["runs"].size(), 7u);
    int projectRuns = 0;
    double mareAt0Steps = -1.0, mareAt16Steps = -1.0;
    for (const auto& run : scene["runs"]) {
        EXPECT_TRUE(std::isfinite(run["indirectMare"].get<double>())) << run.dump();
        EXPECT_GT(run["totalMs"].get<double>(), 0.0) << run.dump();
        projectRuns += run["projectSettings"].get<bool>() ? 1 : 0;
        if (run["setting"] == "lpv.propagationSteps=0")
            mareAt0Steps = run["indirectMare"];
        if (run["setting"] == "lpv.propagationSteps=16")
            mareAt16Steps = run["indirectMare"];
    }
    // The grid and occlusion questions each contain the project's value (32, true).
    EXPECT_EQ(projectRuns, 2);
    // Propagation is what carries the sun's bounce across the box: without it
    // the indirect light is far off the reference.
    ASSERT_GE(mareAt0Steps, 0.0);
    ASSERT_GE(mareAt16Steps, 0.0);
    EXPECT_LT(mareAt16Steps, mareAt0Steps);
    ASSERT_EQ(scene["radiosity"].size(), 1u);
    EXPECT_TRUE(std::isfinite(scene["radiosity"][0]["imageMare"].get<double>()));
    std::ifstream md(dir / "report.md");
    std::stringstream text;
    text << md.rdbuf();
    EXPECT_NE(text.str().find("| cornell-box |"), std::string::npos);
    EXPECT_NE(text.str().find("Radiosity against solve time"), std::string::npos);
    EXPECT_TRUE(fs::exists(dir / "cornell-box" / "steps" / "error-time.png"));
    fs::remove_all(dir);
}
