// `lpv render --dump` and `lpv bench render`, run as a user would.
#include "RunLpv.h"

#include "lpv/importers/ImageIO.h"
#include "lpv/scene/Project.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>
#include <unistd.h>

using namespace lpv::test;
namespace fs = std::filesystem;

namespace {

} // namespace

TEST(RenderDump, ShadowMapsAreWrittenAsExrAndPngBesideTheImage) {
    const fs::path dir = freshTempDir("dump", "shadow");
    const RunResult r = runLpv("render " + cornellProject() + " -o " + (dir / "cb.png").string() +
                               " --width 64 --height 64 --frames 2 --set shadow.mapSize=256 --dump shadowMaps");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    std::size_t pngs = 0, exrs = 0;
    for (const auto& entry : fs::directory_iterator(dir)) {
        const std::string name = entry.path().filename().string();
        if (!name.starts_with("cb-shadow"))
            continue;
        if (entry.path().extension() == ".exr")
            ++exrs;
        if (entry.path().extension() == ".png") {
            ++pngs;
            auto image = lpv::importers::readImage8(entry.path());
            ASSERT_TRUE(image.has_value()) << image.error().describe();
            // The Cornell lamp is an area light: a cube shadow map at the centre of each
            // quarter, faces of max(mapSize / 2, 128) texels (ShadowPass.cpp), one texel per pixel.
            EXPECT_EQ(image->width, 128) << name << ": one shadow map texel per pixel";
            // The face looking down sees the box: a depth view that is not one flat colour.
            // (The face looking up sees only the ceiling, 1 mm behind the light.)
            int lo = 255, hi = 0;
            for (std::size_t i = 0; i < image->pixels.size(); i += std::size_t(image->channels)) {
                lo = std::min<int>(lo, image->pixels[i]);
                hi = std::max<int>(hi, image->pixels[i]);
            }
            if (name.find("-ny") != std::string::npos) {
                EXPECT_GT(hi - lo, 100) << name;
            }
        }
    }
    EXPECT_EQ(pngs, 24u) << r.output; // the six faces of the four quarters' cubes (issue #46)
    EXPECT_EQ(pngs, exrs);
    fs::remove_all(dir);
}

// `--graph --markdown` prints docs/renderer.md's pass table (issue #44): the
// passes that ran, each with what it read and wrote, as table rows.
TEST(RenderDump, GraphAsMarkdownIsThePassTable) {
    const fs::path dir = freshTempDir("dump", "graph-markdown");
    const RunResult r = runLpv("render " + cornellProject() + " -o " + (dir / "cb.png").string() +
                               " --width 64 --height 48 --frames 1 --graph --markdown");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("| pass | reads | writes |\n|---|---|---|\n"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("| `shading` |"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("`camera.depth`"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("frame graph of the last frame"), std::string::npos) << "the text form as well";
    const RunResult alone = runLpv("render " + cornellProject() + " -o " + (dir / "cb.png").string() +
                                   " --width 64 --height 48 --frames 1 --markdown");
    EXPECT_EQ(alone.exitCode, 2) << alone.output;
    EXPECT_NE(alone.output.find("--markdown goes with --graph"), std::string::npos) << alone.output;
    fs::remove_all(dir);
}

TEST(RenderDump, UnknownImageSetIsAUsageError) {
    const RunResult r = runLpv("render " + cornellProject() + " -o /tmp/never.png --dump shadows");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.output.find("shadows"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists("/tmp/never.png"));
}

TEST(RenderDump, EveryFrameGetsARowOfPassTimes) {
    const fs::path dir = freshTempDir("dump", "frames");
    const RunResult r = runLpv("render " + cornellProject() + " -o " + (dir / "cb.png").string() +
                               " --width 48 --height 48 --frames 4");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const char* row : {"\n    1 ", "\n    2 ", "\n    3 ", "\n    4 "})
        EXPECT_NE(r.output.find(row), std::string::npos) << "no row for frame" << row << "\n" << r.output;
    fs::remove_all(dir);
}

TEST(BenchRender, PrintsMedianPassTimesAfterWarmUp) {
    const RunResult r = runLpv("bench render " + cornellProject() + " --width 64 --height 64 --frames 3 --warmup 1");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    // The default round plan: at least 3 rounds of --frames frames each.
    EXPECT_NE(r.output.find(" rounds of 3 frames (after 1 warm-up frame, "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("median"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("shading"), std::string::npos) << r.output;
    EXPECT_EQ(runLpv("bench render").exitCode, 2);
    EXPECT_EQ(runLpv("bench render " + cornellProject() + " --frames 0").exitCode, 2);
}

TEST(BenchRender, ThesisSettingsPrintTheThesisPhasesBesideItsFigures) {
    // Small frames: the table's rows and its own settings are what is checked.
    const RunResult r = runLpv("bench render " + cornellProject() +
                               " --thesis-settings --width 64 --height 64 --frames 1 --warmup 0 --rounds 2");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    // The thesis settings and gi.method=off are timed against each other in
    // the same rounds; each phase is a median over them with its spread.
    EXPECT_NE(r.output.find("\n== gi.method=off\n"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("timed in 2 interleaved rounds"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("±IQR/2"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("then the median over 2 rounds"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("LPV: 4 cascades of 32^3, 8 steps"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("the thesis application's phases (--thesis-settings: 64x64, its start camera)"),
              std::string::npos)
        << r.output;
    for (const char* row : {"\nshadow maps ", "\nRSM ", "\ninjection ", "\npropagation ", "\nfinal shading ",
                            "\nwhole frame ", "\nLPV off (whole frame) "})
        EXPECT_NE(r.output.find(row), std::string::npos) << "no row" << row << "\n" << r.output;
    // The thesis application's whole frame, 839 ms, stands beside ours.
    EXPECT_NE(r.output.find("839"), std::string::npos) << r.output;
    EXPECT_EQ(runLpv("bench render " + cornellProject() + " --thesis-settings --camera main").exitCode, 2);
}

TEST(BenchRender, ThesisRunPutsThisSessionsFiguresBesideOurs) {
    const fs::path dir = freshTempDir("bench", "thesis-run");
    const fs::path run = dir / "thesis-1.txt";
    std::ofstream(run) << "# thesis application, 5 frames after 2 warm-up\nphase shadow_maps 87.7\n"
                          "phase whole_frame 532.4\nphase lpv_off_whole_frame 393.2\n";
    const std::string thesis = " --thesis-settings --width 64 --height 64 --frames 1 --warmup 0 --rounds 1";
    const RunResult r = runLpv("bench render " + cornellProject() + thesis + " --thesis-run " + run.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("its figures: " + run.string() + " (tools/thesis-app/run.sh)"), std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("           532 "), std::string::npos) << "its whole frame\n" << r.output;
    EXPECT_EQ(r.output.find("           839 "), std::string::npos) << "not issue #25's\n" << r.output;
    // A file that is not run.sh's output fails before any frame, naming itself.
    const fs::path wrong = dir / "ours.txt";
    std::ofstream(wrong) << "total 612.0\n";
    const RunResult bad = runLpv("bench render " + cornellProject() + thesis + " --thesis-run " + wrong.string());
    EXPECT_EQ(bad.exitCode, 1) << bad.output;
    EXPECT_NE(bad.output.find(wrong.string()), std::string::npos) << bad.output;
    EXPECT_EQ(bad.output.find("GPU frame rate"), std::string::npos) << "it rendered first\n" << bad.output;
    EXPECT_EQ(runLpv("bench render " + cornellProject() + thesis + " --thesis-run " + (dir / "none.txt").string())
                  .exitCode,
              1);
    EXPECT_EQ(runLpv("bench render " + cornellProject() + " --thesis-run " + run.string()).exitCode, 2)
        << "--thesis-run without --thesis-settings";
}

TEST(BenchRender, TurnMeasuresFramesWhereOnlyTheCameraTurned) {
    const RunResult r =
        runLpv("bench render " + cornellProject() + " --width 64 --height 64 --frames 4 --warmup 1 --turn 5");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("frames where only the camera turned (+-5 degrees"), std::string::npos) << r.output;
    // Shading follows the view: it runs in every turned frame.
    EXPECT_TRUE(std::regex_search(r.output, std::regex("\nshading +[0-9.]+ +[0-9.]+ +4 of 4\n"))) << r.output;
    EXPECT_NE(r.output.find("whole frame (per frame, every pass that ran): median"), std::string::npos) << r.output;
    // The area light's RSM faces and its cube shadow map, and the whole LPV
    // (its cascades follow the camera's position), are listed as reused in
    // every turned frame (issue #48), from the frame graph's report.
    EXPECT_NE(r.output.find("reused by the frame graph (its output kept):\n"), std::string::npos) << r.output;
    for (const char* pass : {"shadowMaps", "localRsm", "lpvInjection", "geometryVolume", "lpvPropagation"})
        EXPECT_TRUE(std::regex_search(r.output, std::regex(std::string("\n  ") + pass + " +4 of 4  ")))
            << pass << " should be reused in all 4 frames:\n" << r.output;
    // So they have no timing row.
    EXPECT_FALSE(std::regex_search(r.output, std::regex("\nlocalRsm +[0-9]"))) << r.output;
    EXPECT_FALSE(std::regex_search(r.output, std::regex("\nshadowMaps +[0-9]"))) << r.output;
    EXPECT_FALSE(std::regex_search(r.output, std::regex("\nlpvPropagation +[0-9]"))) << r.output;
    for (const char* bad : {" --turn 0", " --turn -3", " --turn abc", " --turn 181"})
        EXPECT_EQ(runLpv("bench render " + cornellProject() + bad).exitCode, 2) << bad;
    // A turning camera is timed frame by frame, not in rounds: round options are refused.
    for (const char* bad : {" --turn 5 --rounds 3", " --turn 5 --time-budget 10", " --turn 5 --csv /tmp/never.csv"}) {
        const RunResult refused = runLpv("bench render " + cornellProject() + bad);
        EXPECT_EQ(refused.exitCode, 2) << bad;
        EXPECT_NE(refused.output.find("--turn"), std::string::npos) << refused.output;
    }
}

TEST(RenderDump, RsmTilesOfACornellBoxUnderASunShowTheRedWallRed) {
    // The Cornell box without its ceiling, lit by a sun slanting in from the
    // green side (-X) towards the red wall (+X): the RSM sees the floor, the
    // blocks and the red wall.
    const fs::path dir = freshTempDir("dump", "rsm");
    auto project = lpv::scene::loadProject(cornellProject());
    ASSERT_TRUE(project.has_value()) << project.error().describe();
    lpv::scene::Light sun;
    sun.name = "sun";
    sun.type = lpv::scene::LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(1.0f, -1.0f, 0.2f));
    // The room mesh's first quads are floor, ceiling, back: collapse the ceiling's two triangles.
    lpv::scene::Mesh& room = project->scene.meshes.front();
    ASSERT_EQ(room.name, "room");
    std::fill(room.indices.begin() + 6, room.indices.begin() + 12, room.indices[6]);
    sun.intensity = 3.0f;
    project->scene.lights = {sun};
    ASSERT_TRUE(lpv::scene::saveProject(*project, dir / "sun.lpvproj").has_value());
    const RunResult r = runLpv("render " + (dir / "sun.lpvproj").string() + " -o " + (dir / "sun.png").string() +
                               " --width 64 --height 64 --frames 1 --set rsm.tileSize=64 --set rsm.cascades=2"
                               " --dump rsm");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (int k = 0; k < 2; ++k)
        for (const char* what : {"position", "normal", "flux"})
            for (const char* ext : {".exr", ".png"}) {
                const fs::path f = dir / ("sun-rsm-" + std::to_string(k) + "-" + what + ext);
                EXPECT_TRUE(fs::exists(f)) << f << "\n" << r.output;
            }
    auto flux = lpv::importers::readImage8(dir / "sun-rsm-1-flux.png");
    ASSERT_TRUE(flux.has_value()) << flux.error().describe();
    EXPECT_EQ(flux->width, 64);
    std::size_t reddish = 0;
    for (std::size_t i = 0; i < flux->pixels.size(); i += std::size_t(flux->channels)) {
        const int red = flux->pixels[i], green = flux->pixels[i + 1];
        if (red > 40 && red > 3 * green)
            ++reddish;
    }
    EXPECT_GT(reddish, 20u) << "the red wall's flux is red";
    if (!HasFailure())
        fs::remove_all(dir);
}

TEST(RenderSweep, AListOfValuesRendersOneImagePerValue) {
    const fs::path dir = freshTempDir("dump", "sweep");
    const RunResult r = runLpv("render " + cornellProject() + " -o " + (dir / "cb.png").string() +
                               " --width 48 --height 48 --frames 1 --set output.exposure=-1,1");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    auto dark = lpv::importers::readImage8(dir / "cb-output.exposure--1.png");
    auto bright = lpv::importers::readImage8(dir / "cb-output.exposure-1.png");
    ASSERT_TRUE(dark.has_value()) << r.output;
    ASSERT_TRUE(bright.has_value()) << r.output;
    long darkSum = 0, brightSum = 0;
    for (std::size_t i = 0; i < dark->pixels.size(); ++i) {
        darkSum += dark->pixels[i];
        brightSum += bright->pixels[i];
    }
    EXPECT_GT(brightSum, darkSum) << "two stops more exposure is brighter";
    EXPECT_NE(r.output.find("total GPU ms"), std::string::npos) << r.output;
    // A bad value in the list is refused before anything renders.
    const RunResult bad = runLpv("render " + cornellProject() + " -o " + (dir / "x.png").string() +
                                 " --set output.exposure=0,banana");
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_FALSE(fs::exists(dir / "x-output.exposure-0.png"));
    fs::remove_all(dir);
}

TEST(BenchRender, SweepsWriteCsvAndMarkdownTables) {
    const fs::path dir = freshTempDir("dump", "bench");
    const RunResult r = runLpv("bench render " + cornellProject() +
                               " --width 32 --height 32 --frames 2 --warmup 1 --set shadow.mapSize=256,512 --csv " +
                               (dir / "t.csv").string() + " --markdown " + (dir / "t.md").string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    std::ifstream csv(dir / "t.csv");
    std::string header, line;
    std::getline(csv, header);
    EXPECT_EQ(header, "shadow.mapSize,pass,median_ms,q1_ms,q3_ms,min_ms,max_ms,rounds,frames,same_cost_as");
    std::size_t rows256 = 0, rows512 = 0;
    while (std::getline(csv, line)) {
        rows256 += line.starts_with("256,") ? 1 : 0;
        rows512 += line.starts_with("512,") ? 1 : 0;
    }
    EXPECT_GE(rows256, 4u) << "shadowMaps, shading, tonemap, total";
    EXPECT_EQ(rows256, rows512);
    std::ifstream md(dir / "t.md");
    const std::string report = (std::ostringstream() << md.rdbuf()).str();
    EXPECT_NE(report.find("Machine: "), std::string::npos) << report;
    EXPECT_NE(report.find("| 512 |"), std::string::npos) << report;
    // Two settings compared: each says which others cost the same within the noise.
    EXPECT_NE(report.find("| same cost as |"), std::string::npos) << report;
    EXPECT_NE(r.output.find("same cost within the noise as"), std::string::npos) << r.output;
    fs::remove_all(dir);
}

namespace {

std::vector<std::string> splitCsv(const std::string& line) {
    std::vector<std::string> fields;
    std::string field;
    for (char c : line) {
        if (c == ',') {
            fields.push_back(field);
            field.clear();
        } else {
            field += c;
        }
    }
    fields.push_back(field);
    return fields;
}

} // namespace

// Issue #43: `lpv bench render` times in interleaved rounds; every pass and
// the total carry their median, quartiles, extremes and rounds, in the CSV,
// the Markdown (headed by the machine, its load and why the rounds stopped)
// and the printed table.
TEST(BenchRender, CornellTemplateInRoundsWritesTheSpread) {
    const fs::path dir = freshTempDir("dump", "rounds");
    const fs::path project = dir / "cb.lpvproj";
    const RunResult made = runLpv("new '" + project.string() + "' --template cornell-box");
    ASSERT_EQ(made.exitCode, 0) << made.output;
    const RunResult r = runLpv("bench render '" + project.string() +
                               "' --width 64 --height 36 --frames 2 --warmup 1 --rounds 2 --csv '" +
                               (dir / "t.csv").string() + "' --markdown '" + (dir / "t.md").string() + "'");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("64x36, 2 rounds of 2 frames (after 1 warm-up frame, and one untimed frame per round)"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("q1-q3"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("timed in 2 interleaved rounds (round limit after 2 rounds); load "), std::string::npos)
        << r.output;

    std::ifstream csv(dir / "t.csv");
    std::string header, line;
    std::getline(csv, header);
    EXPECT_EQ(header, "pass,median_ms,q1_ms,q3_ms,min_ms,max_ms,rounds,frames,same_cost_as");
    std::size_t rows = 0, totals = 0;
    while (std::getline(csv, line)) {
        const std::vector<std::string> f = splitCsv(line);
        ASSERT_EQ(f.size(), 9u) << line;
        ++rows;
        totals += f[0] == "total" ? 1 : 0;
        const double median = std::stod(f[1]), q1 = std::stod(f[2]), q3 = std::stod(f[3]), lo = std::stod(f[4]),
                     hi = std::stod(f[5]);
        EXPECT_LE(lo, q1) << line;
        EXPECT_LE(q1, median) << line;
        EXPECT_LE(median, q3) << line;
        EXPECT_LE(q3, hi) << line;
        EXPECT_GT(median, 0.0) << line;
        EXPECT_EQ(f[6], "2") << "rounds: " << line;
        EXPECT_EQ(f[7], "4") << "frames: 2 rounds of 2: " << line;
    }
    EXPECT_GE(rows, 4u) << "shadowMaps, shading, tonemap, total";
    EXPECT_EQ(totals, 1u);

    std::ifstream md(dir / "t.md");
    const std::string report = (std::ostringstream() << md.rdbuf()).str();
    for (const char* expected : {"Machine: ", "Load: load ", " -> load ",
                                 "Timing: 2 rounds; stopped: round limit after 2 rounds",
                                 "| total | q1-q3 | rounds |", " --rounds 2 "})
        EXPECT_NE(report.find(expected), std::string::npos) << expected << "\n" << report;
    // The one row: "median ±half the IQR" per pass, then the total, its quartiles and 2 rounds.
    EXPECT_NE(report.find(" ±"), std::string::npos) << report;
    EXPECT_NE(report.find(" | 2 |\n"), std::string::npos) << report;
    // One setting: nothing to compare.
    EXPECT_EQ(report.find("same cost"), std::string::npos) << report;
    fs::remove_all(dir);
}

TEST(BenchRender, BadRoundOptionsAreUsageErrors) {
    for (const char* bad : {" --rounds 0", " --rounds x", " --rounds -1", " --time-budget abc", " --time-budget 0",
                            " --time-budget -5", " --spread-target 0", " --spread-target ten"}) {
        const RunResult r = runLpv("bench render " + cornellProject() + bad);
        EXPECT_EQ(r.exitCode, 2) << bad << "\n" << r.output;
        EXPECT_EQ(r.output.find("GPU frame rate"), std::string::npos) << "nothing may render: " << bad;
    }
    EXPECT_EQ(runLpv("bench lpv " + cornellProject() + " --rounds 0").exitCode, 2);
    EXPECT_EQ(runLpv("bench lpv " + cornellProject() + " --time-budget never").exitCode, 2);
}
