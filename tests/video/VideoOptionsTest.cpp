// What renderVideo decides before it renders anything: output kind and
// names, frame counts, and the option checks with their errors.
#include "VideoTestSupport.h"
#include "TestFiles.h"

#include "lpv/video/VideoExport.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <limits>

using namespace lpv;
using namespace lpv::video;
namespace fs = std::filesystem;

namespace {

using lpv::test::contains;

VideoOptions smallOptions() {
    VideoOptions o;
    o.pathName = "dolly";
    o.output = fs::path(testing::TempDir()) / "never-written.mp4";
    o.width = 160;
    o.height = 120;
    return o;
}

scene::Error checkFails(const VideoOptions& options) {
    const auto ok = checkVideoOptions(lpv::test::cornellWithPath(), options);
    if (ok) {
        ADD_FAILURE() << "the options were accepted";
        return {};
    }
    EXPECT_FALSE(ok.error().message.empty());
    return ok.error();
}

} // namespace

TEST(VideoOutput, KindFollowsTheName) {
    auto mp4 = videoOutputFor("out/clip.MP4");
    ASSERT_TRUE(mp4);
    EXPECT_EQ(mp4->format, VideoFormat::Mp4);
    EXPECT_EQ(mp4->folder, fs::path("out"));
    EXPECT_EQ(mp4->pattern, "clip.MP4");

    auto folder = videoOutputFor("out/frames/");
    ASSERT_TRUE(folder);
    EXPECT_EQ(folder->format, VideoFormat::PngSequence);
    EXPECT_EQ(folder->folder, fs::path("out/frames"));
    EXPECT_EQ(folder->pattern, "frame-%05d.png");

    auto bare = videoOutputFor("out/frames");
    ASSERT_TRUE(bare);
    EXPECT_EQ(bare->format, VideoFormat::PngSequence);
    EXPECT_EQ(bare->folder, fs::path("out/frames"));

    auto numbered = videoOutputFor("shots/take-%05d.png");
    ASSERT_TRUE(numbered);
    EXPECT_EQ(numbered->format, VideoFormat::PngSequence);
    EXPECT_EQ(numbered->folder, fs::path("shots"));
    EXPECT_EQ(numbered->pattern, "take-%05d.png");
}

TEST(VideoOutput, UnsupportedNamesAreInvalidValue) {
    for (const char* name : {"clip.mov", "take-%05d.jpg", "take-%s.png", "a-%d-%d.png", ""}) {
        const auto out = videoOutputFor(name);
        ASSERT_FALSE(out) << name;
        EXPECT_EQ(out.error().code, scene::ErrorCode::InvalidValue) << name;
        EXPECT_EQ(out.error().location, "output") << name;
    }
    EXPECT_TRUE(contains(videoOutputFor("clip.mov").error().message, "use .mp4, a folder"))
        << "names the choices";
}

TEST(VideoOutput, FrameFileNamesArePadded) {
    EXPECT_EQ(frameFileName("frame-%05d.png", 0), "frame-00000.png");
    EXPECT_EQ(frameFileName("frame-%05d.png", 123456), "frame-123456.png");
    EXPECT_EQ(frameFileName("%d.png", 42), "42.png");
    EXPECT_EQ(frameFileName("x%03dy.png", 7), "x007y.png");
}

TEST(VideoOutput, FrameCountCoversTheDuration) {
    EXPECT_EQ(videoFrameCount(2.0, 30.0), 60);
    EXPECT_EQ(videoFrameCount(2.0f, 29.97), 60); // 59.94 rounds up
    EXPECT_EQ(videoFrameCount(2.1f, 30.0), 63);  // 2.1f * 30 = 62.99999...
    EXPECT_EQ(videoFrameCount(2.01, 30.0), 61);
    EXPECT_EQ(videoFrameCount(0.0, 30.0), 1);
    EXPECT_EQ(videoFrameCount(1.0, 0.0), 1);
}

TEST(VideoOptions, TheCornellPathIsAccepted) {
    const auto ok = checkVideoOptions(lpv::test::cornellWithPath(), smallOptions());
    EXPECT_TRUE(ok) << ok.error().describe();
}

TEST(VideoOptions, OddSizeForMp4IsInvalidValue) {
    VideoOptions o = smallOptions();
    o.width = 161;
    const scene::Error e = checkFails(o);
    EXPECT_EQ(e.code, scene::ErrorCode::InvalidValue);
    EXPECT_EQ(e.location, "width");
    EXPECT_TRUE(contains(e.message, "even width and height; 161x120 is not")) << e.message;
    o.width = 160;
    o.height = 7;
    EXPECT_EQ(checkFails(o).location, "height");
    o.output = "frames/"; // PNG takes any size
    EXPECT_TRUE(checkVideoOptions(lpv::test::cornellWithPath(), o));
}

TEST(VideoOptions, UnknownPathNamesTheOnesThereAre) {
    VideoOptions o = smallOptions();
    o.pathName = "tour";
    const scene::Error e = checkFails(o);
    EXPECT_EQ(e.code, scene::ErrorCode::InvalidValue);
    EXPECT_EQ(e.location, "pathName");
    EXPECT_TRUE(contains(e.message, "no camera path named \"tour\" (paths: \"dolly\")")) << e.message;

    scene::Project empty = lpv::test::cornellWithPath();
    empty.scene.cameraPaths[0].keyframes.clear();
    const auto ok = checkVideoOptions(empty, smallOptions());
    ASSERT_FALSE(ok);
    EXPECT_TRUE(contains(ok.error().message, "has no keyframes")) << ok.error().message;
}

TEST(VideoOptions, BadOverridesAreTheRegistrysErrors) {
    VideoOptions o = smallOptions();
    o.setA = {{"lpv.noSuchKey", "1"}};
    scene::Error e = checkFails(o);
    EXPECT_EQ(e.code, scene::ErrorCode::UnknownParameter);
    EXPECT_EQ(e.location, "setA[0]");
    EXPECT_TRUE(contains(e.message, "lpv.noSuchKey")) << e.message;

    o.setA.clear();
    o.setB =
        std::vector<std::pair<std::string, std::string>>{{"output.exposure", "0"}, {"output.exposure", "99"}};
    e = checkFails(o);
    EXPECT_EQ(e.code, scene::ErrorCode::OutOfRange);
    EXPECT_EQ(e.location, "setB[1]");
}

TEST(VideoOptions, FrameRateAndSizesAreChecked) {
    VideoOptions o = smallOptions();
    o.fps = 0.0;
    EXPECT_EQ(checkFails(o).location, "fps");
    o.fps = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(checkFails(o).location, "fps");
    o.fps = 30.0;
    o.width = 0;
    EXPECT_EQ(checkFails(o).code, scene::ErrorCode::OutOfRange);
    o.width = 160;
    o.crf = 60;
    EXPECT_EQ(checkFails(o).location, "crf");
}

TEST(VideoOptions, EncoderIsH264WhereDebianShipsIt) {
    // Debian 12's libavcodec59 links libx264; elsewhere MPEG-4 Part 2 is the fallback.
    const std::string name = videoEncoderName();
    EXPECT_TRUE(name == "libx264" || name == "libopenh264" || name == "mpeg4") << name;
    std::printf("MP4 encoder: %s\n", name.c_str());
}
