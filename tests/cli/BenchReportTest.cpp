// `lpv bench report` as a user runs it, on the Cornell box alone at a tiny
// size: every question's sweep ran against its like-for-like reference, the
// summary names the project's own settings and the radiosity measurement,
// and the JSON holds finite errors and mean ratios.
#include "RunLpv.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

using namespace lpv::test;
namespace fs = std::filesystem;

TEST(BenchReport, QuickCornellReportHasSweepsAndRadiosity) {
    const fs::path dir = fs::temp_directory_path() / ("lpv-bench-report-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    const RunResult r = runLpv("bench report --quick --scene cornell-box --out '" + dir.string() +
                               "' --width 64 --height 48 --spp 64 --frames 1 --warmup 0 --rounds 2");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    // Issue #43: the scene's 7 distinct settings (9 rows, the project's own in 3 of them) timed once, together.
    EXPECT_NE(r.output.find("timing 7 distinct settings of 4 sweeps in interleaved rounds"), std::string::npos)
        << r.output;
    EXPECT_TRUE(fs::exists(dir / "cornell-box" / "timing.json"));
    ASSERT_TRUE(fs::exists(dir / "report.md")) << r.output;
    std::ifstream in(dir / "report.json");
    const auto j = nlohmann::json::parse(in, nullptr, false);
    ASSERT_FALSE(j.is_discarded());
    ASSERT_EQ(j["scenes"].size(), 1u);
    const auto& scene = j["scenes"][0];
    EXPECT_EQ(scene["name"], "cornell-box");
    EXPECT_TRUE(scene["failures"].empty()) << scene["failures"].dump();
    // --quick: steps 0,4,16; grid 16,32; cellSize auto,0.25; occlusion false,true.
    ASSERT_EQ(scene["runs"].size(), 9u);
    int projectRuns = 0;
    double ratioAt0Steps = -1.0, ratioAt16Steps = -1.0;
    for (const auto& run : scene["runs"]) {
        EXPECT_TRUE(std::isfinite(run["indirectMare"].get<double>())) << run.dump();
        EXPECT_GT(run["totalMs"].get<double>(), 0.0) << run.dump();
        projectRuns += run["projectSettings"].get<bool>() ? 1 : 0;
        EXPECT_TRUE(std::isfinite(run["indirectMeanRatio"].get<double>())) << run.dump();
        if (run["setting"] == "lpv.propagationSteps=0")
            ratioAt0Steps = run["indirectMeanRatio"];
        if (run["setting"] == "lpv.propagationSteps=16")
            ratioAt16Steps = run["indirectMeanRatio"];
    }
    // The grid, cellSize and occlusion questions each contain the project's value (32, auto, true),
    // and it has one time, one memory figure and one spread in all three.
    EXPECT_EQ(projectRuns, 3);
    std::vector<nlohmann::json> projectTimes;
    for (const auto& run : scene["runs"]) {
        EXPECT_EQ(run["time"]["rounds"].get<int>(), 2) << run.dump();
        EXPECT_LE(run["time"]["q1Ms"].get<double>(), run["time"]["medianMs"].get<double>()) << run.dump();
        EXPECT_GT(run["gpuBytes"].get<std::uint64_t>(), 0u) << run.dump();
        EXPECT_TRUE(std::isfinite(run["indirectSymmetric"].get<double>())) << run.dump();
        if (run["projectSettings"].get<bool>())
            projectTimes.push_back({run["time"], run["gpuBytes"]});
    }
    ASSERT_EQ(projectTimes.size(), 3u);
    EXPECT_EQ(projectTimes[0], projectTimes[1]);
    EXPECT_EQ(projectTimes[0], projectTimes[2]);
    // Propagation is what carries the lamp's bounce across the box: without it
    // the LPV holds a fraction of the reference's one-bounce light.
    ASSERT_GE(ratioAt0Steps, 0.0);
    ASSERT_GE(ratioAt16Steps, 0.0);
    EXPECT_LT(ratioAt0Steps, 0.5);
    EXPECT_GT(ratioAt16Steps, 2.0 * ratioAt0Steps);
    ASSERT_EQ(scene["radiosity"].size(), 1u);
    EXPECT_TRUE(std::isfinite(scene["radiosity"][0]["imageMare"].get<double>()));
    // Radiosity is measured like for like (issue #27 item 5): the frame's
    // indirect light against an 8-bounce reference of the same lights; on the
    // Cornell box a solved solution holds about the reference's light.
    const double radiosityRatio = scene["radiosity"][0]["indirectMeanRatio"].get<double>();
    EXPECT_GT(radiosityRatio, 0.7) << scene["radiosity"].dump();
    EXPECT_LT(radiosityRatio, 1.4) << scene["radiosity"].dump();
    EXPECT_GT(scene["radiosity"][0]["seconds"].get<double>(), 0.0);
    std::ifstream md(dir / "report.md");
    std::stringstream text;
    text << md.rdbuf();
    EXPECT_NE(text.str().find("| cornell-box |"), std::string::npos);
    EXPECT_NE(text.str().find("like for like"), std::string::npos);
    EXPECT_NE(text.str().find("Radiosity against solve time"), std::string::npos);
    EXPECT_NE(text.str().find("lowest unbiased error"), std::string::npos);
    EXPECT_NE(text.str().find("indirect symmetric error"), std::string::npos);
    EXPECT_TRUE(fs::exists(dir / "cornell-box" / "steps" / "error-time.png"));

    // --resume reuses every sweep the same command made, and gives the same error figures.
    const RunResult again = runLpv("bench report --quick --scene cornell-box --out '" + dir.string() +
                                   "' --width 64 --height 48 --spp 64 --frames 1 --warmup 0 --rounds 2 --resume");
    ASSERT_EQ(again.exitCode, 0) << again.output;
    EXPECT_NE(again.output.find("timing.json (--resume: the same 7 settings timed by the same command)"),
              std::string::npos)
        << again.output;
    EXPECT_EQ(again.output.find("distinct settings of"), std::string::npos) << "no setting may be timed again";
    std::size_t reused = 0;
    for (std::size_t at = again.output.find("(--resume: made by the same sweep command)"); at != std::string::npos;
         at = again.output.find("(--resume: made by the same sweep command)", at + 1))
        ++reused;
    EXPECT_EQ(reused, 4u) << again.output; // steps, grid, cellSize, occlusion
    EXPECT_EQ(again.output.find("$ lpv bench "), std::string::npos) << "no sweep may run again";
    std::ifstream in2(dir / "report.json");
    const auto j2 = nlohmann::json::parse(in2, nullptr, false);
    ASSERT_FALSE(j2.is_discarded());
    ASSERT_EQ(j2["scenes"][0]["runs"].size(), scene["runs"].size());
    for (std::size_t i = 0; i < scene["runs"].size(); ++i) {
        EXPECT_EQ(j2["scenes"][0]["runs"][i]["indirectMare"], scene["runs"][i]["indirectMare"]);
        EXPECT_EQ(j2["scenes"][0]["runs"][i]["time"], scene["runs"][i]["time"]);
    }
    // The ranking check of two runs (issue #43): a timing agrees with itself; a file that is no timing is an error.
    const std::string timing = (dir / "cornell-box" / "timing.json").string();
    const RunResult agree = runLpv("bench compare-times '" + timing + "' '" + timing + "'");
    EXPECT_EQ(agree.exitCode, 0) << agree.output;
    EXPECT_NE(agree.output.find("settings in both:                         7"), std::string::npos) << agree.output;
    EXPECT_NE(agree.output.find("Spearman rank correlation of the medians: 1.000"), std::string::npos) << agree.output;
    const RunResult notTiming = runLpv("bench compare-times '" + timing + "' '" + (dir / "report.json").string() + "'");
    EXPECT_EQ(notTiming.exitCode, 1) << notTiming.output;
    EXPECT_NE(notTiming.output.find("not a timing file"), std::string::npos) << notTiming.output;
    // A different size is another command: nothing is reused.
    const RunResult other = runLpv("bench report --quick --scene cornell-box --question occlusion --out '" +
                                   dir.string() + "' --width 48 --height 32 --spp 16 --frames 1 --warmup 0 --rounds 2 --resume");
    ASSERT_EQ(other.exitCode, 0) << other.output;
    EXPECT_EQ(other.output.find("(--resume: made by the same sweep command)"), std::string::npos) << other.output;
    fs::remove_all(dir);
}

// Like for like (issue #22): the bounces question runs one sweep per value,
// each against a reference traced with as many bounces; the sky question one
// per value, each against a reference whose sky light follows that value.
TEST(BenchReport, BouncesAndSkyAreMeasuredAgainstTheirOwnReferences) {
    const fs::path dir = fs::temp_directory_path() / ("lpv-bench-report-bounces-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    const RunResult r = runLpv("bench report --scene cornell-box --question bounces --question sky --out '" +
                               dir.string() +
                               "' --width 48 --height 32 --spp 32 --frames 1 --warmup 0 --rounds 1 --radiosity-seconds 5");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const char* ref : {"reference-1-bounce.exr", "reference-2-bounce.exr", "reference-3-bounce.exr",
                            "reference-1-bounce-sky-off.exr", "reference-1-bounce-sky-on.exr"})
        EXPECT_TRUE(fs::exists(dir / "cornell-box" / ref)) << ref;
    EXPECT_NE(r.output.find("--sweep lpv.bounces=2 --reference " + (dir / "cornell-box" / "reference-2-bounce.exr").string()),
              std::string::npos)
        << r.output;
    std::ifstream in(dir / "report.json");
    const auto j = nlohmann::json::parse(in, nullptr, false);
    ASSERT_FALSE(j.is_discarded());
    const auto& runs = j["scenes"][0]["runs"];
    ASSERT_EQ(runs.size(), 5u) << runs.dump();
    std::vector<std::string> settings;
    for (const auto& run : runs) {
        settings.push_back(run["setting"]);
        EXPECT_GT(run["indirectMeanRatio"].get<double>(), 0.0) << run.dump();
    }
    EXPECT_EQ(settings, (std::vector<std::string>{"effects.skyInjection=off", "effects.skyInjection=on",
                                                  "lpv.bounces=1", "lpv.bounces=2", "lpv.bounces=3"}));
    EXPECT_TRUE(runs[2]["projectSettings"].get<bool>()) << "lpv.bounces=1 is the project's";
    EXPECT_FALSE(runs[3]["projectSettings"].get<bool>());
    EXPECT_TRUE(fs::exists(dir / "cornell-box" / "bounces" / "3" / "sweep.md"));
    fs::remove_all(dir);
}

// Issue #28: the report in pieces, as the cluster job runs it (coordinator,
// shards, coordinator, shards, coordinator), gives the errors one process gives.
TEST(BenchReport, ShardedReportMatchesTheOneProcessReport) {
    const fs::path dir = fs::temp_directory_path() / ("lpv-bench-report-shards-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    const std::string options = " --quick --scene cornell-box --question steps --width 48 --height 32 --spp 16 "
                                "--frames 1 --warmup 0 --rounds 1 --radiosity-seconds 5 --out '";
    const std::string sharded = "bench report" + options + (dir / "sharded").string() + "'";
    // A shard before the coordinator made the projects is told to wait for it.
    RunResult r = runLpv(sharded + " --shard 0/2");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.output.find("--merge-shards 2"), std::string::npos) << r.output;
    auto step = [&](const std::string& args) {
        const RunResult s = runLpv(sharded + args);
        EXPECT_EQ(s.exitCode, 0) << args << "\n" << s.output;
        return s.output;
    };
    EXPECT_NE(step(" --merge-shards 2").find("projects made"), std::string::npos);
    step(" --shard 0/2");
    // One shard short: the coordinator names the missing piece and writes no reference.
    r = runLpv(sharded + " --merge-shards 2");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.output.find("reference-1-bounce.shard-1-of-2.exr"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir / "sharded" / "cornell-box" / "reference-1-bounce.exr"));
    step(" --shard 1/2");
    EXPECT_NE(step(" --merge-shards 2").find("references merged"), std::string::npos);
    step(" --shard 1/2");
    step(" --shard 0/2");
    step(" --merge-shards 2");
    ASSERT_TRUE(fs::exists(dir / "sharded" / "report.json"));

    r = runLpv("bench report" + options + (dir / "whole").string() + "'");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    auto runsOf = [](const fs::path& file) {
        std::ifstream in(file);
        const auto j = nlohmann::json::parse(in, nullptr, false);
        return j.is_discarded() ? nlohmann::json() : j["scenes"][0]["runs"];
    };
    const auto a = runsOf(dir / "whole" / "report.json"), b = runsOf(dir / "sharded" / "report.json");
    ASSERT_EQ(a.size(), 3u);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i]["setting"], b[i]["setting"]);
        EXPECT_EQ(a[i]["indirectMare"], b[i]["indirectMare"]) << a[i]["setting"];
        EXPECT_EQ(a[i]["indirectMeanRatio"], b[i]["indirectMeanRatio"]) << a[i]["setting"];
        EXPECT_EQ(a[i]["imageMare"], b[i]["imageMare"]) << a[i]["setting"];
        EXPECT_GT(b[i]["totalMs"].get<double>(), 0.0);
        EXPECT_EQ(b[i]["time"]["rounds"].get<int>(), 1) << "the coordinator timed the settings";
    }
    fs::remove_all(dir);
}
