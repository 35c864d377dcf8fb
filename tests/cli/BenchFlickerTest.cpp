// `lpv bench PROJECT --flicker` as a user runs it, on a small imported scene
// with a sun: a static scene renders the same indirect light every frame
// (flicker exactly 0), a turning sun changes it, and bad requests are errors.
#include "RunLpv.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

using namespace lpv::test;
namespace fs = std::filesystem;

namespace {

// flicker_mean of each data row of the CSV, in order.
std::vector<double> flickerColumn(const std::string& csv) {
    std::vector<double> out;
    std::istringstream lines(csv);
    std::string line;
    std::getline(lines, line); // header
    while (std::getline(lines, line)) {
        const auto quote = line.find("\",");
        if (quote != std::string::npos)
            out.push_back(std::stod(line.substr(quote + 2)));
    }
    return out;
}

class BenchFlicker : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = freshTempDir("bench-flicker");
        project_ = dir_ / "box.lpvproj";
        const RunResult imported =
            runLpv("import '" + (fs::path(kSharedScenesDir) / "gltf-small/Box/glTF/Box.gltf").string() +
                   "' -o '" + project_.string() + "'");
        ASSERT_EQ(imported.exitCode, 0) << imported.output;
    }
    void TearDown() override { fs::remove_all(dir_); }

    RunResult bench(const std::string& options) {
        return runLpv("bench '" + project_.string() +
                      "' --flicker --width 64 --height 48 --set lpv.gridSize=16 " +
                      "--set shadow.mapSize=256 " + options);
    }

    fs::path dir_, project_;
};

} // namespace

TEST_F(BenchFlicker, StaticSceneHasNoFlickerAndATurningSunHasSome) {
    const fs::path csv = dir_ / "flicker.csv", md = dir_ / "flicker.md";
    const RunResult still = bench("--sun-rotate 0 --frames 3 --set rsm.tileSize=32,64 --csv '" +
                                  csv.string() + "' --markdown '" + md.string() + "'");
    ASSERT_EQ(still.exitCode, 0) << still.output;
    const std::vector<double> zero = flickerColumn(readText(csv));
    ASSERT_EQ(zero.size(), 2u) << readText(csv); // one row per swept value
    for (double f : zero)
        EXPECT_EQ(f, 0.0) << "the same scene and camera give the same LPV every frame";
    const std::string table = readText(md);
    EXPECT_NE(table.find("Machine: "), std::string::npos);
    EXPECT_NE(table.find(" rsm.tileSize=32 |"), std::string::npos) << table;
    EXPECT_NE(table.find("| lpv.gridSize=16 shadow.mapSize=256 rsm.tileSize=64 |"), std::string::npos) << table;

    const RunResult turning = bench("--sun-rotate 40 --frames 3 --csv '" + csv.string() + "'");
    ASSERT_EQ(turning.exitCode, 0) << turning.output;
    const std::vector<double> some = flickerColumn(readText(csv));
    ASSERT_EQ(some.size(), 1u);
    EXPECT_GT(some[0], 1e-3) << "20 degrees of sun per frame must change the indirect light";
    EXPECT_NE(turning.output.find("pixels kept"), std::string::npos) << turning.output;
}

TEST_F(BenchFlicker, NeedsExactlyOneMotionAndAnExistingPath) {
    EXPECT_EQ(bench("--frames 3").exitCode, 2);
    EXPECT_EQ(bench("--frames 3 --sun-rotate 5 --path tour").exitCode, 2);
    EXPECT_EQ(bench("--frames 1 --sun-rotate 5").exitCode, 2);
    const RunResult missing = bench("--frames 3 --path tour");
    EXPECT_EQ(missing.exitCode, 1);
    EXPECT_NE(missing.output.find("no camera path named 'tour'"), std::string::npos) << missing.output;
}
