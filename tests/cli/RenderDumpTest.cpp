// `lpv render --dump` and `lpv bench render`, run as a user would.
#include "RunLpv.h"

#include "lpv/importers/ImageIO.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <unistd.h>

using namespace lpv::test;
namespace fs = std::filesystem;

namespace {

fs::path tempDir(const std::string& name) {
    fs::path p = fs::temp_directory_path() / ("lpv-dump-" + name + "-" + std::to_string(::getpid()));
    fs::remove_all(p);
    fs::create_directories(p);
    return p;
}

} // namespace

TEST(RenderDump, ShadowMapsAreWrittenAsExrAndPngBesideTheImage) {
    const fs::path dir = tempDir("shadow");
    const RunResult r = runLpv("render " + cornellProject() + " -o " + (dir / "cb.png").string() +
                               " --width 64 --height 64 --frames 2 --set shadow.mapSize=256 --dump shadow");
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
            EXPECT_EQ(image->width, 256) << name << ": one shadow map texel per pixel";
            // A depth view of the Cornell box is not one flat colour.
            int lo = 255, hi = 0;
            for (std::size_t i = 0; i < image->pixels.size(); i += std::size_t(image->channels)) {
                lo = std::min<int>(lo, image->pixels[i]);
                hi = std::max<int>(hi, image->pixels[i]);
            }
            EXPECT_GT(hi - lo, 100) << name;
        }
    }
    EXPECT_GE(pngs, 1u) << r.output;
    EXPECT_EQ(pngs, exrs);
    fs::remove_all(dir);
}

TEST(RenderDump, UnknownImageSetIsAUsageError) {
    const RunResult r = runLpv("render " + cornellProject() + " -o /tmp/never.png --dump shadows");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.output.find("shadows"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists("/tmp/never.png"));
}

TEST(RenderDump, EveryFrameGetsARowOfPassTimes) {
    const fs::path dir = tempDir("frames");
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
    EXPECT_NE(r.output.find("3 frames after 1 warm-up"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("median"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("forward"), std::string::npos) << r.output;
    EXPECT_EQ(runLpv("bench render").exitCode, 2);
    EXPECT_EQ(runLpv("bench render " + cornellProject() + " --frames 0").exitCode, 2);
}
