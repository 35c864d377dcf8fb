// The whole export on a headless context (llvmpipe in CI): an MP4 read back
// through FFmpeg, a cancelled export that leaves nothing behind, PNG
// sequences, and side-by-side frames of two parameter sets.
#include "VideoTestSupport.h"

#include "lpv/importers/ImageIO.h"
#include "lpv/video/VideoExport.h"

#include <gtest/gtest.h>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libswscale/swscale.h>
}

#include <chrono>
#include <cstdio>
#include <set>
#include <system_error>

#include <unistd.h>

using namespace lpv;
using namespace lpv::test;
namespace fs = std::filesystem;

namespace {

class VideoExport : public testing::Test {
  protected:
    void SetUp() override {
        const auto* info = testing::UnitTest::GetInstance()->current_test_info();
        dir_ = fs::path(testing::TempDir()) /
               ("lpv-video-" + std::string(info->name()) + "-" + std::to_string(::getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override {
        std::error_code ignored;
        fs::remove_all(dir_, ignored);
    }

    // Every entry under dir_, relative, sorted (folders too, and hidden files).
    std::set<std::string> entries() const {
        std::set<std::string> out;
        for (const auto& e : fs::recursive_directory_iterator(dir_))
            out.insert(e.path().lexically_relative(dir_).generic_string());
        return out;
    }

    fs::path dir_;
};

struct DecodedVideo {
    int frames = 0;
    int width = 0, height = 0;
    std::string codec;
    double fps = 0.0;
    std::vector<std::uint8_t> firstFrameRgb; // width * height * 3
    std::string error;
};

// Decodes every frame of `file` with libavformat/libavcodec, as a player would.
DecodedVideo decode(const fs::path& file) {
    DecodedVideo out;
    AVFormatContext* format = nullptr;
    if (avformat_open_input(&format, file.c_str(), nullptr, nullptr) < 0) {
        out.error = "cannot open";
        return out;
    }
    AVCodecContext* codec = nullptr;
    AVFrame* frame = av_frame_alloc();
    AVPacket* packet = av_packet_alloc();
    const auto receiveAll = [&] {
        while (avcodec_receive_frame(codec, frame) == 0) {
            if (out.frames == 0) {
                out.firstFrameRgb.resize(std::size_t(frame->width) * std::size_t(frame->height) * 3);
                SwsContext* sws =
                    sws_getContext(frame->width, frame->height, AVPixelFormat(frame->format), frame->width,
                                   frame->height, AV_PIX_FMT_RGB24, SWS_BILINEAR, nullptr, nullptr, nullptr);
                std::uint8_t* dst[1] = {out.firstFrameRgb.data()};
                const int stride[1] = {frame->width * 3};
                sws_scale(sws, frame->data, frame->linesize, 0, frame->height, dst, stride);
                sws_freeContext(sws);
            }
            ++out.frames;
            if (frame->width != out.width || frame->height != out.height)
                out.error = "a frame of another size";
        }
    };
    do {
        if (avformat_find_stream_info(format, nullptr) < 0) {
            out.error = "no stream info";
            break;
        }
        const AVCodec* decoder = nullptr;
        const int stream = av_find_best_stream(format, AVMEDIA_TYPE_VIDEO, -1, -1, &decoder, 0);
        if (stream < 0 || !decoder) {
            out.error = "no video stream";
            break;
        }
        const AVStream* s = format->streams[stream];
        out.width = s->codecpar->width;
        out.height = s->codecpar->height;
        out.codec = avcodec_get_name(s->codecpar->codec_id);
        out.fps = av_q2d(s->avg_frame_rate);
        codec = avcodec_alloc_context3(decoder);
        avcodec_parameters_to_context(codec, s->codecpar);
        if (avcodec_open2(codec, decoder, nullptr) < 0) {
            out.error = "cannot open the decoder";
            break;
        }
        while (av_read_frame(format, packet) >= 0) {
            if (packet->stream_index == stream && avcodec_send_packet(codec, packet) == 0)
                receiveAll();
            av_packet_unref(packet);
        }
        avcodec_send_packet(codec, nullptr);
        receiveAll();
    } while (false);
    av_packet_free(&packet);
    av_frame_free(&frame);
    avcodec_free_context(&codec);
    avformat_close_input(&format);
    return out;
}

double meanLuma(const scene::Image8& image, int x0, int x1) {
    double sum = 0.0;
    for (int y = 0; y < image.height; ++y)
        for (int x = x0; x < x1; ++x) {
            const std::size_t i = (std::size_t(y) * std::size_t(image.width) + std::size_t(x)) * 4;
            sum += 0.2126 * image.pixels[i] + 0.7152 * image.pixels[i + 1] + 0.0722 * image.pixels[i + 2];
        }
    return sum / (double(image.height) * (x1 - x0));
}

} // namespace

TEST_F(VideoExport, TwoSecondsAt30FpsIs60DecodableFramesOfTheRightSize) {
    const scene::Project project = cornellWithPath(2.0f);
    video::VideoOptions options;
    options.pathName = "dolly";
    options.output = dir_ / "cornell.mp4";
    options.width = 160;
    options.height = 120;
    options.fps = 30.0;
    std::vector<video::VideoProgress> reports;
    const auto start = std::chrono::steady_clock::now();
    const auto ok = video::renderVideo(project, cornellDir(), options, [&](const video::VideoProgress& p) {
        reports.push_back(p);
        return true;
    });
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ASSERT_TRUE(ok) << ok.error().describe();
    std::printf("exported 60 frames of 160x120 in %.2f s with %s\n", seconds,
                video::videoEncoderName().c_str());
    EXPECT_EQ(entries(), std::set<std::string>{"cornell.mp4"}) << "no temporary file left";

    ASSERT_EQ(reports.size(), 60u);
    for (std::size_t i = 0; i < reports.size(); ++i) {
        EXPECT_EQ(reports[i].frame, int(i) + 1);
        EXPECT_EQ(reports[i].frames, 60);
        EXPECT_GE(reports[i].etaSeconds, 0.0);
    }
    EXPECT_EQ(reports.back().etaSeconds, 0.0);
    EXPECT_GE(reports.back().elapsedSeconds, reports.front().elapsedSeconds);

    const DecodedVideo v = decode(options.output);
    ASSERT_TRUE(v.error.empty()) << v.error;
    EXPECT_EQ(v.frames, 60);
    EXPECT_EQ(v.width, 160);
    EXPECT_EQ(v.height, 120);
    EXPECT_EQ(v.codec, video::videoEncoderName() == "mpeg4" ? "mpeg4" : "h264");
    EXPECT_NEAR(v.fps, 30.0, 1e-6);
    // Colours survive RGB -> yuv420p -> RGB: the red wall on the left, the green one on the right.
    ASSERT_EQ(v.firstFrameRgb.size(), 160u * 120u * 3u);
    const auto pixel = [&](int x, int y, int c) {
        return int(v.firstFrameRgb[(std::size_t(y) * 160 + std::size_t(x)) * 3 + std::size_t(c)]);
    };
    EXPECT_GT(pixel(35, 60, 0), pixel(35, 60, 1) + 20) << "left wall red";
    EXPECT_GT(pixel(125, 60, 1), pixel(125, 60, 0) + 20) << "right wall green";
}

TEST_F(VideoExport, CancelledExportLeavesNoFileAndNoTemporaryFile) {
    const scene::Project project = cornellWithPath(2.0f);
    video::VideoOptions options;
    options.pathName = "dolly";
    options.output = dir_ / "cancelled.mp4";
    options.width = 96;
    options.height = 64;
    options.warmupFrames = 0;
    int calls = 0;
    const auto result =
        video::renderVideo(project, cornellDir(), options, [&](const video::VideoProgress& p) {
            ++calls;
            return p.frame < 5;
        });
    ASSERT_FALSE(result);
    EXPECT_EQ(result.error().code, scene::ErrorCode::Cancelled);
    EXPECT_EQ(calls, 5);
    EXPECT_FALSE(fs::exists(options.output));
    EXPECT_TRUE(entries().empty()) << "left behind: " << *entries().begin();

    // The same for a PNG sequence into a new folder and into an existing one.
    fs::create_directories(dir_ / "existing");
    for (const fs::path& out : {dir_ / "frames", dir_ / "existing" / "f-%03d.png"}) {
        options.output = out;
        const auto png = video::renderVideo(project, cornellDir(), options,
                                            [&](const video::VideoProgress& p) { return p.frame < 5; });
        ASSERT_FALSE(png);
        EXPECT_EQ(png.error().code, scene::ErrorCode::Cancelled);
        EXPECT_EQ(entries(), std::set<std::string>{"existing"}) << out;
    }
}

TEST_F(VideoExport, PngSequenceHasOneFilePerFrame) {
    const scene::Project project = cornellWithPath(1.0f);
    video::VideoOptions options;
    options.pathName = "dolly";
    options.output = dir_ / "frames";
    options.width = 81; // odd sizes are fine for PNG
    options.height = 47;
    options.fps = 10.0;
    options.warmupFrames = 0;
    ASSERT_TRUE(video::renderVideo(project, cornellDir(), options, nullptr));
    std::set<std::string> expected;
    for (int i = 0; i < 10; ++i)
        expected.insert("frames/" + video::frameFileName("frame-%05d.png", i));
    expected.insert("frames");
    EXPECT_EQ(entries(), expected);
    const auto first = importers::readImage8(dir_ / "frames" / "frame-00000.png");
    ASSERT_TRUE(first) << first.error().describe();
    EXPECT_EQ(first->width, 81);
    EXPECT_EQ(first->height, 47);

    // A numbered name into an existing folder: other files there stay.
    fs::create_directories(dir_ / "shots");
    const std::string keep = "keep me";
    std::FILE* f = std::fopen((dir_ / "shots" / "notes.txt").c_str(), "w");
    std::fputs(keep.c_str(), f);
    std::fclose(f);
    options.output = dir_ / "shots" / "take-%d.png";
    options.fps = 5.0;
    ASSERT_TRUE(video::renderVideo(project, cornellDir(), options, nullptr));
    std::set<std::string> shots;
    for (const auto& e : fs::directory_iterator(dir_ / "shots"))
        shots.insert(e.path().filename().string());
    EXPECT_EQ(shots, (std::set<std::string>{"notes.txt", "take-0.png", "take-1.png", "take-2.png",
                                            "take-3.png", "take-4.png"}));
}

TEST_F(VideoExport, SideBySideHalvesDifferWhenTheSetsDo) {
    const scene::Project project = cornellWithPath(1.0f);
    video::VideoOptions options;
    options.pathName = "dolly";
    options.output = dir_ / "ab-%02d.png";
    options.width = 160;
    options.height = 60;
    options.fps = 2.0;
    options.warmupFrames = 1;
    options.setA = {{"output.exposure", "-4"}};
    options.setB = std::vector<std::pair<std::string, std::string>>{{"output.exposure", "2"}};
    options.labelA = "EV -4";
    options.labelB = "EV +2";
    ASSERT_TRUE(video::renderVideo(project, cornellDir(), options, nullptr));
    EXPECT_EQ(entries(), (std::set<std::string>{"ab-00.png", "ab-01.png"}));
    const auto frame = importers::readImage8(dir_ / "ab-01.png");
    ASSERT_TRUE(frame) << frame.error().describe();
    ASSERT_EQ(frame->width, 160);
    const double left = meanLuma(*frame, 1, 79), right = meanLuma(*frame, 81, 159);
    EXPECT_GT(right, left + 40.0) << "left " << left << ", right " << right;

    // The same sets on both sides: the halves match (labels and divider aside).
    options.setB = options.setA;
    options.labelA.clear();
    options.labelB.clear();
    options.output = dir_ / "same-%02d.png";
    ASSERT_TRUE(video::renderVideo(project, cornellDir(), options, nullptr));
    const auto same = importers::readImage8(dir_ / "same-01.png");
    ASSERT_TRUE(same);
    EXPECT_NEAR(meanLuma(*same, 1, 79), meanLuma(*same, 81, 159), 0.5);
}
