// `lpv reference`, `lpv compare` and `lpv bench PROJECT --sweep` as a user
// runs them, on the built-in Cornell box at a tiny size: the reference EXR
// has its layers and settings, the LPV's indirect view compares against it,
// and the sweep writes its tables and plots.
#include "RunLpv.h"

#include "lpv/importers/ImageIO.h"
#include "lpv/scene/Project.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

using namespace lpv::test;
namespace fs = std::filesystem;

namespace {

// The number after "key": in a one-line JSON object.
double jsonNumber(const std::string& json, const std::string& key) {
    const auto at = json.find("\"" + key + "\": ");
    return at == std::string::npos ? std::nan("") : std::atof(json.c_str() + at + key.size() + 4);
}

class ReferenceCommand : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        dir_ = freshTempDir("reference");
        // The built-in box has only its ceiling spot; the LPV injects sunlight,
        // so a sun shines in through the open front, down onto the floor.
        auto project = lpv::scene::loadProject(cornellProject());
        ASSERT_TRUE(project) << project.error().describe();
        lpv::scene::Light sun;
        sun.name = "sun";
        sun.direction = glm::normalize(glm::vec3(0.2f, -0.6f, 1.0f));
        sun.intensity = 3.0f;
        project->scene.lights.push_back(sun);
        project_ = (dir_ / "cornell-sun.lpvproj").string();
        ASSERT_TRUE(lpv::scene::saveProject(*project, project_));
        traced_ = runLpv("reference '" + project_ + "' -o '" + (dir_ / "ref.exr").string() +
                         "' --width 40 --height 30 --spp 8 --bounces 3");
    }
    static void TearDownTestSuite() { fs::remove_all(dir_); }
    static inline fs::path dir_;
    static inline std::string project_;
    static inline RunResult traced_;
};

TEST_F(ReferenceCommand, WritesEveryLayerAndItsSettings) {
    ASSERT_EQ(traced_.exitCode, 0) << traced_.output;
    EXPECT_NE(traced_.output.find("8/8 spp"), std::string::npos) << traced_.output;
    auto image = lpv::importers::readImageChannels(dir_ / "ref.exr");
    ASSERT_TRUE(image) << image.error().describe();
    EXPECT_EQ(image->width, 40);
    EXPECT_EQ(image->height, 30);
    for (const char* name :
         {"R", "indirect1.G", "indirect.B", "variance.R", "indirect.variance.G", "coverage.Y"})
        EXPECT_NE(std::ranges::find(image->names, name), image->names.end()) << name;
    const auto spp = std::ranges::find(image->attributes, std::string("lpv:spp"),
                                       &std::pair<std::string, std::string>::first);
    ASSERT_NE(spp, image->attributes.end());
    EXPECT_EQ(spp->second, "8");
    for (float v : image->pixels)
        ASSERT_TRUE(std::isfinite(v));
}

TEST_F(ReferenceCommand, ComparesTheLpvIndirectViewWithTheReference) {
    ASSERT_EQ(traced_.exitCode, 0) << traced_.output;
    const fs::path lpvExr = dir_ / "lpv.exr";
    const RunResult rendered = runLpv("render '" + project_ + "' -o '" + lpvExr.string() +
                                      "' --width 40 --height 30 --frames 2 --set output.view=indirect");
    ASSERT_EQ(rendered.exitCode, 0) << rendered.output;
    const RunResult compared = runLpv("compare '" + lpvExr.string() + "' '" + (dir_ / "ref.exr").string() +
                                      "' --layer indirect1 --json");
    ASSERT_EQ(compared.exitCode, 0) << compared.output;
    EXPECT_NE(compared.output.find("\"layer\": \"indirect1\""), std::string::npos) << compared.output;
    const double ssim = jsonNumber(compared.output, "ssim");
    EXPECT_TRUE(std::isfinite(jsonNumber(compared.output, "mare"))) << compared.output;
    EXPECT_GT(jsonNumber(compared.output, "noiseMare"), 0.0) << "8 spp leave measurable noise";
    EXPECT_GE(ssim, -1.0);
    EXPECT_LE(ssim, 1.0);
    // Units agree: the LPV injects sunlight reflected once, so its mean
    // irradiance is close to the reference's one-bounce layer (0.94x at
    // 160x120, 256 spp, docs/reference.md). A slip of pi or of the albedo
    // (about 0.7 here) in either would put the ratio outside 0.6..1.6.
    const double ratio =
        jsonNumber(compared.output, "meanTest") / jsonNumber(compared.output, "meanReference");
    EXPECT_GT(ratio, 0.6) << compared.output;
    EXPECT_LT(ratio, 1.6) << compared.output;
    // FLIP on the two images as displayed (one exposure), and the figure the
    // reference's 8-spp noise alone gives.
    const double flip = jsonNumber(compared.output, "flip");
    EXPECT_GT(flip, 0.0) << compared.output;
    EXPECT_LT(flip, 1.0) << compared.output;
    EXPECT_GT(jsonNumber(compared.output, "noiseFlip"), 0.0) << compared.output;
    EXPECT_LT(jsonNumber(compared.output, "noiseSsim"), 1.0) << compared.output;
}

TEST_F(ReferenceCommand, RefusesImagesOfAnotherSize) {
    ASSERT_EQ(traced_.exitCode, 0) << traced_.output;
    const fs::path small = dir_ / "small.exr";
    ASSERT_EQ(
        runLpv("render '" + project_ + "' -o '" + small.string() + "' --width 20 --height 15 --frames 1")
            .exitCode,
        0);
    const RunResult r = runLpv("compare '" + small.string() + "' '" + (dir_ / "ref.exr").string() + "'");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.output.find("20x15"), std::string::npos) << r.output;
    EXPECT_EQ(runLpv("compare '" + small.string() + "' '" + small.string() + "'").exitCode, 1)
        << "an image without reference layers is not a reference";
    EXPECT_EQ(runLpv("reference '" + project_ + "' -o x.png").exitCode, 2);
}

TEST_F(ReferenceCommand, SweepWritesTablesPlotsAndTheCheapestSettings) {
    ASSERT_EQ(traced_.exitCode, 0) << traced_.output;
    const fs::path out = dir_ / "sweep";
    const RunResult r = runLpv("bench '" + project_ + "' --sweep lpv.propagationSteps=0,4 --reference '" +
                               (dir_ / "ref.exr").string() + "' --out '" + out.string() +
                               "' --width 40 --height 30 --frames 2 --warmup 1");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const char* file : {"sweep.csv", "sweep.json", "sweep.md", "time-lpv.propagationSteps.png",
                             "error-time.png", "crops.png"})
        EXPECT_TRUE(fs::exists(out / file)) << file;
    const std::string csv = readText(out / "sweep.csv");
    EXPECT_EQ(std::ranges::count(csv, '\n'), 3) << csv; // header + two settings
    EXPECT_NE(csv.find("lpvPropagation_median_ms"), std::string::npos) << csv;
    const std::string md = readText(out / "sweep.md");
    EXPECT_NE(md.find("| propagationSteps=4 |"), std::string::npos) << md;
    EXPECT_TRUE(md.find("Cheapest unbiased setting within 10.0% of the lowest unbiased error") != std::string::npos ||
                md.find("No setting of this sweep has its mean within 0.8-1.25x") != std::string::npos)
        << md;
    EXPECT_TRUE(fs::exists(out / "frames.png"));
    EXPECT_TRUE(fs::exists(out / "error-memory.png"));
    auto plot = lpv::importers::readImage8(out / "error-time.png");
    ASSERT_TRUE(plot);
    EXPECT_EQ(plot->width, 800);
}

TEST_F(ReferenceCommand, SweepMeasuresEachBounceCountLikeForLike) {
    // The reference was traced with --bounces 3: an LPV with lpv.bounces=1 is measured
    // against its indirect1 layer, one with lpv.bounces=3 against its 3-bounce layer.
    ASSERT_EQ(traced_.exitCode, 0) << traced_.output;
    const fs::path out = dir_ / "sweep-bounces";
    const RunResult r = runLpv("bench '" + project_ + "' --sweep lpv.bounces=1,3 --reference '" +
                               (dir_ / "ref.exr").string() + "' --out '" + out.string() +
                               "' --width 40 --height 30 --frames 1 --warmup 0");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const std::string json = readText(out / "sweep.json");
    const auto one = json.find("\"lpv.bounces\": \"1\"");
    const auto three = json.find("\"lpv.bounces\": \"3\"");
    ASSERT_NE(one, std::string::npos) << json;
    ASSERT_NE(three, std::string::npos) << json;
    auto metric = [&](std::size_t from, const std::string& layer, const std::string& key) {
        const auto at = json.find("\"" + layer + "\": {", from);
        return jsonNumber(json.substr(at, json.find('}', at) - at + 1), key);
    };
    const double oneRef = metric(one, "indirect", "meanReference");
    const double oneBounceLayer = metric(one, "indirectOneBounce", "meanReference");
    const double threeRef = metric(three, "indirect", "meanReference");
    ASSERT_GT(oneBounceLayer, 0.0) << json;
    EXPECT_DOUBLE_EQ(oneRef, oneBounceLayer) << "lpv.bounces=1 against indirect1";
    EXPECT_GT(threeRef, 1.05 * oneBounceLayer) << "lpv.bounces=3 against the 3-bounce layer, which holds more light";
    EXPECT_NE(readText(out / "sweep.csv").find("lpv_bounces"), std::string::npos);
    EXPECT_NE(readText(out / "sweep.md").find("| indirect mean |"), std::string::npos);
}

TEST_F(ReferenceCommand, SweepRefusesABounceCountTheReferenceWasNotTracedWith) {
    ASSERT_EQ(traced_.exitCode, 0) << traced_.output;
    const RunResult r = runLpv("bench '" + project_ + "' --sweep lpv.bounces=2 --reference '" +
                               (dir_ / "ref.exr").string() + "' --out '" + (dir_ / "sweep-2").string() +
                               "' --width 40 --height 30 --frames 1 --warmup 0");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("lpv.bounces=2 is measured against a reference with 2 bounces, and " +
                            (dir_ / "ref.exr").string() + " has 3"),
              std::string::npos)
        << r.output;
}

TEST_F(ReferenceCommand, PrintsWhichLightsTheReferenceTraces) {
    ASSERT_EQ(traced_.exitCode, 0) << traced_.output;
    // The Cornell box is closed (no sky in the LPV) and its lamp is an area light.
    EXPECT_NE(traced_.output.find("reference: sky light off (auto: the LPV does not inject it"), std::string::npos)
        << traced_.output;
    EXPECT_NE(traced_.output.find("reference: emissive surfaces off (auto: the LPV does not inject it"),
              std::string::npos)
        << traced_.output;
}

} // namespace

// Issue #28: `lpv reference --shard I/N` and `lpv merge`, as a cluster job runs them.
namespace {

std::vector<float> pixelsOf(const fs::path& exr) {
    auto image = lpv::importers::readImageChannels(exr);
    return image ? image->pixels : std::vector<float>{};
}

} // namespace

TEST_F(ReferenceCommand, ShardsMergeIntoTheBitsOfOneProcessAndABadSetIsRefused) {
    const std::string common = " --width 40 --height 30 --spp 4 --bounces 2";
    const fs::path whole = dir_ / "whole.exr";
    ASSERT_EQ(runLpv("reference '" + project_ + "' -o '" + whole.string() + "'" + common).exitCode, 0);
    std::string shards;
    for (int i = 0; i < 3; ++i) {
        const fs::path shard = dir_ / ("shard" + std::to_string(i) + ".exr");
        const RunResult r = runLpv("reference '" + project_ + "' -o '" + shard.string() + "'" + common +
                                   " --shard " + std::to_string(i) + "/3");
        ASSERT_EQ(r.exitCode, 0) << r.output;
        EXPECT_NE(r.output.find("shard " + std::to_string(i) + "/3"), std::string::npos) << r.output;
        shards += " '" + shard.string() + "'";
    }
    const fs::path merged = dir_ / "merged.exr";
    const RunResult m = runLpv("merge '" + merged.string() + "'" + shards);
    ASSERT_EQ(m.exitCode, 0) << m.output;
    const auto a = pixelsOf(whole), b = pixelsOf(merged);
    ASSERT_FALSE(a.empty());
    ASSERT_EQ(a.size(), b.size());
    EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(float)), 0) << "the merge must be bit-identical";

    // Incomplete: the error names what is missing and nothing is written.
    const fs::path out = dir_ / "incomplete.exr";
    RunResult r = runLpv("merge '" + out.string() + "' '" + (dir_ / "shard0.exr").string() + "' '" +
                         (dir_ / "shard2.exr").string() + "'");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.output.find("missing shard 1/3"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out));

    // Another setting (one more bounce) is not of the same reference.
    const fs::path other = dir_ / "other1.exr";
    ASSERT_EQ(runLpv("reference '" + project_ + "' -o '" + other.string() +
                     "' --width 40 --height 30 --spp 4 --bounces 3 --shard 1/3")
                  .exitCode,
              0);
    r = runLpv("merge '" + out.string() + "' '" + (dir_ / "shard0.exr").string() + "' '" + other.string() +
               "' '" + (dir_ / "shard2.exr").string() + "'");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.output.find("not of one reference"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out));

    // A shard cut short (as a copy interrupted mid-file would be) is refused, not merged.
    const fs::path cut = dir_ / "cut1.exr";
    {
        const std::string bytes = readText(dir_ / "shard1.exr");
        std::ofstream(cut, std::ios::binary) << bytes.substr(0, bytes.size() / 2);
    }
    r = runLpv("merge '" + out.string() + "' '" + (dir_ / "shard0.exr").string() + "' '" + cut.string() + "' '" +
               (dir_ / "shard2.exr").string() + "'");
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_FALSE(fs::exists(out));

    // A time budget would stop shards at different sample counts.
    r = runLpv("reference '" + project_ + "' -o '" + (dir_ / "t.exr").string() + "'" + common +
               " --max-seconds 5 --shard 0/2");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.output.find("time budget"), std::string::npos) << r.output;
    EXPECT_EQ(runLpv("reference '" + project_ + "' -o x.exr --shard 2/2").exitCode, 2);
}

namespace {

// sweep.csv as rows of cells, the header first.
std::vector<std::vector<std::string>> csvRows(const fs::path& file) {
    std::vector<std::vector<std::string>> rows;
    std::istringstream in(readText(file));
    for (std::string line; std::getline(in, line);) {
        std::vector<std::string> cells;
        std::istringstream cellsIn(line);
        for (std::string cell; std::getline(cellsIn, cell, ',');)
            cells.push_back(cell);
        rows.push_back(cells);
    }
    return rows;
}

} // namespace

TEST_F(ReferenceCommand, ASweepInShardsMergesIntoTheSameErrorsAndABadSetIsRefused) {
    ASSERT_EQ(traced_.exitCode, 0) << traced_.output;
    const std::string sweep = "bench '" + project_ + "' --sweep lpv.propagationSteps=0,4,8 --reference '" +
                              (dir_ / "ref.exr").string() + "' --width 40 --height 30 --frames 2 --warmup 1";
    const fs::path whole = dir_ / "sweep-whole";
    RunResult r = runLpv(sweep + " --out '" + whole.string() + "'");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    std::string shards;
    for (int i = 0; i < 2; ++i) {
        const fs::path dir = dir_ / ("sweep-shard" + std::to_string(i));
        r = runLpv(sweep + " --out '" + dir.string() + "' --shard " + std::to_string(i) + "/2");
        ASSERT_EQ(r.exitCode, 0) << r.output;
        EXPECT_TRUE(fs::exists(dir / "shard.json"));
        EXPECT_FALSE(fs::exists(dir / "sweep.csv")) << "a shard writes its part, not a sweep";
        shards += " '" + dir.string() + "'";
    }
    const fs::path merged = dir_ / "sweep-merged";
    r = runLpv("bench merge '" + merged.string() + "'" + shards);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto a = csvRows(whole / "sweep.csv"), b = csvRows(merged / "sweep.csv");
    ASSERT_EQ(a.size(), 4u);
    ASSERT_EQ(a.size(), b.size());
    ASSERT_EQ(a[0], b[0]) << "the same columns";
    int compared = 0;
    for (std::size_t row = 1; row < a.size(); ++row)
        for (std::size_t c = 0; c < a[0].size(); ++c) {
            if (a[0][c].ends_with("_ms") || a[0][c] == "rounds" || a[0][c] == "same_cost_as") {
                // timings: measured anew, present in both (each shard times its own settings in rounds)
                if (a[0][c] == "same_cost_as")
                    continue;
                EXPECT_FALSE(b[row][c].empty()) << a[0][c];
                continue;
            }
            EXPECT_EQ(a[row][c], b[row][c]) << a[0][c] << " of row " << row;
            ++compared;
        }
    EXPECT_GE(compared, 3 * 12);
    EXPECT_EQ(readText(whole / "crops.png"), readText(merged / "crops.png")) << "the same indirect images";
    EXPECT_EQ(readText(whole / "frames.png"), readText(merged / "frames.png")) << "the same final frames";
    EXPECT_TRUE(fs::exists(merged / "sweep.md"));
    EXPECT_TRUE(fs::exists(merged / "error-time.png"));

    // One shard missing: named.
    const fs::path out = dir_ / "sweep-bad";
    r = runLpv("bench merge '" + out.string() + "' '" + (dir_ / "sweep-shard1").string() + "'");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.output.find("missing shard 0/2"), std::string::npos) << r.output;
    // A shard of another sweep.
    const fs::path other = dir_ / "sweep-other1";
    ASSERT_EQ(runLpv("bench '" + project_ + "' --sweep lpv.propagationSteps=0,4,16 --reference '" +
                     (dir_ / "ref.exr").string() + "' --width 40 --height 30 --frames 2 --warmup 1 --out '" +
                     other.string() + "' --shard 1/2")
                  .exitCode,
              0);
    r = runLpv("bench merge '" + out.string() + "' '" + (dir_ / "sweep-shard0").string() + "' '" +
               other.string() + "'");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.output.find("not a shard of the same sweep"), std::string::npos) << r.output;
    // A shard that did not finish has no shard.json.
    fs::remove(other / "shard.json");
    r = runLpv("bench merge '" + out.string() + "' '" + (dir_ / "sweep-shard0").string() + "' '" +
               other.string() + "'");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.output.find("did not finish"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out / "sweep.csv"));
    // Shards are measured against one reference, so one must be given.
    r = runLpv("bench '" + project_ + "' --sweep lpv.propagationSteps=0,4 --width 40 --height 30 --shard 0/2");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.output.find("--shard needs --reference"), std::string::npos) << r.output;
}

// Two display images (the FLIP authors' published pairs are PNGs): FLIP
// alone, over every pixel. Green against blue is the largest difference
// FLIP knows (1); an image against itself 0; the heat map has the image's size.
TEST(CompareDisplayImages, ReportsFlipOfTwoPngs) {
    const fs::path dir = fs::temp_directory_path() / ("lpv-compare-png-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    auto solid = [&](const char* name, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
        lpv::importers::Image8 image{16, 12, 3, {}};
        for (int i = 0; i < 16 * 12; ++i)
            image.pixels.insert(image.pixels.end(), {r, g, b});
        EXPECT_TRUE(lpv::importers::writeImage(dir / name, image));
        return "'" + (dir / name).string() + "'";
    };
    const std::string green = solid("green.png", 0, 255, 0), blue = solid("blue.png", 0, 0, 255);
    const RunResult far = runLpv("compare " + green + " " + blue + " --json --flip-map '" +
                                 (dir / "map.png").string() + "'");
    ASSERT_EQ(far.exitCode, 0) << far.output;
    EXPECT_NEAR(jsonNumber(far.output, "flip"), 1.0, 1e-3) << far.output;
    const auto map = lpv::importers::readImage8(dir / "map.png");
    ASSERT_TRUE(map) << map.error().describe();
    EXPECT_EQ(map->width, 16);
    EXPECT_EQ(map->height, 12);
    const RunResult same = runLpv("compare " + green + " " + green);
    ASSERT_EQ(same.exitCode, 0) << same.output;
    EXPECT_NE(same.output.find("FLIP 0.000000"), std::string::npos) << same.output;
    EXPECT_EQ(runLpv("compare " + green + " " + blue + " --ppd 0").exitCode, 2);
    EXPECT_EQ(runLpv("compare " + green + " " + blue + " --layer image").exitCode, 2);
    const RunResult mixed = runLpv("compare " + green + " '" + (dir / "x.exr").string() + "'");
    EXPECT_EQ(mixed.exitCode, 2) << mixed.output;
    EXPECT_NE(mixed.output.find("two EXR images"), std::string::npos) << mixed.output;
    fs::remove_all(dir);
}
