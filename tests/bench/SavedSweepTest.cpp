#include "lpv/bench/SavedSweep.h"

#include "lpv/scene/Project.h"

#include "TestFiles.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace lpv;
using lpv::test::freshTempDir;
namespace fs = std::filesystem;

namespace {

scene::Image8 gradient(int w, int h) {
    scene::Image8 img{w, h, 4, {}};
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            img.pixels.insert(img.pixels.end(), {std::uint8_t(x * 7), std::uint8_t(y * 13), std::uint8_t(x ^ y), 255});
    return img;
}

bench::SavedSweep sample() {
    bench::SavedSweep s;
    s.createdAt = "2026-12-02T17:00:00Z";
    s.machine = "test CPU, 2 cores | llvmpipe | 4.5";
    s.width = 7; // odd sizes: base64 padding of one and two bytes
    s.height = 5;
    s.frames = 3;
    s.warmup = 1;
    s.referenceSpp = 512;
    s.referenceSeconds = 1.25;
    s.referenceNoiseMare = 0.031;
    s.base = {{"lpv.gridSize", "16"}};
    bench::SweepRun a;
    a.settings = {{"lpv.propagationSteps", "4"}};
    a.totalMs = 12.5;
    a.indirect.mare = 0.4;
    bench::SweepRun b;
    b.settings = {{"lpv.propagationSteps", "8"}};
    b.totalMs = 20.0;
    b.indirect.mare = 0.3;
    s.runs = {a, b};
    s.previews = {gradient(7, 5), gradient(5, 3)};
    s.referencePreview = gradient(7, 5);
    return s;
}

} // namespace

TEST(SavedSweep, SavesBesideTheProjectAndReloadsAsSaved) {
    const fs::path dir = freshTempDir("saved-sweep", "roundtrip");
    const fs::path file = bench::savedSweepFileOf(dir / "Room.lpvproj");
    EXPECT_EQ(file, dir / "Room.assets" / "sweep.json");
    const bench::SavedSweep saved = sample();
    ASSERT_TRUE(bench::saveSweep(saved, file).has_value());
    auto loaded = bench::loadSweep(file);
    ASSERT_TRUE(loaded.has_value()) << loaded.error().describe();
    EXPECT_EQ(loaded->createdAt, saved.createdAt);
    EXPECT_EQ(loaded->width, 7);
    EXPECT_EQ(loaded->referenceSpp, 512);
    EXPECT_DOUBLE_EQ(loaded->referenceNoiseMare, 0.031);
    EXPECT_EQ(loaded->base, saved.base);
    ASSERT_EQ(loaded->runs.size(), 2u);
    EXPECT_EQ(loaded->runs[1].settings, saved.runs[1].settings);
    EXPECT_DOUBLE_EQ(loaded->runs[1].indirect.mare, 0.3);
    ASSERT_EQ(loaded->previews.size(), 2u);
    EXPECT_EQ(loaded->previews[0].pixels, saved.previews[0].pixels);
    EXPECT_EQ(loaded->previews[1].pixels, saved.previews[1].pixels);
    EXPECT_EQ(loaded->referencePreview.pixels, saved.referencePreview.pixels);
    fs::remove_all(dir);
}

TEST(SavedSweep, TheDocksQuestionRowsAreKeptAndOptional) {
    const fs::path dir = freshTempDir("saved-sweep", "questions");
    const fs::path file = dir / "sweep.json";
    // A file without rows (as before issue #46) reads with none and writes none.
    ASSERT_TRUE(bench::saveSweep(sample(), file).has_value());
    {
        std::ifstream in(file);
        EXPECT_EQ((std::ostringstream() << in.rdbuf()).str().find("\"questions\""), std::string::npos);
    }
    auto old = bench::loadSweep(file);
    ASSERT_TRUE(old.has_value()) << old.error().describe();
    EXPECT_TRUE(old->questions.empty());

    bench::SavedSweep saved = sample();
    saved.questions = {{"steps", "lpv.propagationSteps=1,3", false},
                       {"grid", "lpv.gridSize=16,32", true},
                       {"custom", "lpv.intensity=0.5", true}};
    ASSERT_TRUE(bench::saveSweep(saved, file).has_value());
    auto loaded = bench::loadSweep(file);
    ASSERT_TRUE(loaded.has_value()) << loaded.error().describe();
    EXPECT_EQ(loaded->questions, saved.questions);
    fs::remove_all(dir);
}

TEST(SavedSweep, ADamagedFileIsAnErrorNamingItNotACrash) {
    const fs::path dir = freshTempDir("saved-sweep", "damaged");
    const fs::path file = dir / "sweep.json";
    ASSERT_TRUE(bench::saveSweep(sample(), file).has_value());
    std::string text;
    {
        std::ifstream in(file);
        text = (std::ostringstream() << in.rdbuf()).str();
    }
    // A preview whose pixels do not match its size, a cut file, another format.
    const auto at = text.find("\"rgb\": \"");
    ASSERT_NE(at, std::string::npos);
    std::string shortPreview = text;
    shortPreview.erase(at + 8, 8);
    for (const std::string& bad : {shortPreview, text.substr(0, text.size() / 2),
                                   std::string(R"({"format": "lpvstudio-project", "version": 1})")}) {
        ASSERT_TRUE(scene::writeFileAtomically(file, bad).has_value());
        auto loaded = bench::loadSweep(file);
        ASSERT_FALSE(loaded.has_value());
        EXPECT_EQ(loaded.error().file, file.string());
    }
    EXPECT_FALSE(bench::loadSweep(dir / "none.json").has_value());
    fs::remove_all(dir);
}

TEST(SavedSweep, ARunsParametersAreItsBasePlusItsSettingsAndDefaultsCompareEqual) {
    const bench::SavedSweep s = sample();
    const scene::ParameterSet p = bench::runParameters(s.base, s.runs[0]);
    EXPECT_EQ(p.getInt("lpv.gridSize"), 16);
    EXPECT_EQ(p.getInt("lpv.propagationSteps"), 4);
    scene::ParameterSet same;
    (void)same.setFromText("lpv.propagationSteps", "4");
    (void)same.setFromText("lpv.gridSize", "16");
    EXPECT_TRUE(bench::sameValues(p, same));
    // A key set to its registry default reads as the key left unset.
    const int defaultCascades = scene::ParameterSet{}.getInt("lpv.cascades");
    (void)same.setFromText("lpv.cascades", std::to_string(defaultCascades));
    EXPECT_TRUE(bench::sameValues(p, same));
    (void)same.setFromText("lpv.propagationSteps", "5");
    EXPECT_FALSE(bench::sameValues(p, same));
    EXPECT_EQ(bench::settingsOf(p), (std::vector<bench::Setting>{{"lpv.gridSize", "16"}, {"lpv.propagationSteps", "4"}}));
}
