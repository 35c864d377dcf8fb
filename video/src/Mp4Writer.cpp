#include "Mp4Writer.h"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/imgutils.h>
#include <libavutil/log.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include <algorithm>
#include <cmath>
#include <mutex>

namespace lpv::video::detail {
namespace {

std::string avError(int code) {
    char text[AV_ERROR_MAX_STRING_SIZE] = {};
    av_strerror(code, text, sizeof text);
    return text;
}

// x264 reports its settings and statistics at "info" level on every run.
// FFmpeg's log level is process-wide; lowered once, and only from the default.
void quietFfmpegLog() {
    static std::once_flag once;
    std::call_once(once, [] {
        if (av_log_get_level() == AV_LOG_INFO)
            av_log_set_level(AV_LOG_WARNING);
    });
}

// Encoders that run anywhere, best first. Hardware H.264 encoders (nvenc,
// vaapi, qsv) are left out: they are listed whether or not the hardware is there.
const AVCodec* findEncoder() {
    if (const AVCodec* c = avcodec_find_encoder_by_name("libx264"))
        return c;
    if (const AVCodec* c = avcodec_find_encoder_by_name("libopenh264"))
        return c;
    return avcodec_find_encoder(AV_CODEC_ID_MPEG4);
}

} // namespace

std::string chooseEncoderName() {
    const AVCodec* c = findEncoder();
    return c ? c->name : "";
}

struct Mp4Writer::State {
    std::string where;
    AVFormatContext* format = nullptr;
    AVCodecContext* codec = nullptr;
    AVStream* stream = nullptr;
    SwsContext* scaler = nullptr;
    AVFrame* frame = nullptr;
    AVPacket* packet = nullptr;
    std::int64_t nextPts = 0;
    int width = 0, height = 0;
    std::string encoder;

    ~State() {
        // An unfinished file gets no trailer: the caller deletes it, and
        // avformat_free_context releases what the muxer holds.
        if (format && format->pb)
            avio_closep(&format->pb);
        avformat_free_context(format);
        avcodec_free_context(&codec);
        sws_freeContext(scaler);
        av_frame_free(&frame);
        av_packet_free(&packet);
    }

    std::unexpected<scene::Error> fail(const std::string& what, int code) const {
        return scene::makeError(scene::ErrorCode::IoError, where, "", what + ": " + avError(code));
    }

    // Sends a frame (nullptr: flush) and writes every packet the encoder has ready.
    scene::Expected<void> encode(const AVFrame* f) {
        if (const int r = avcodec_send_frame(codec, f); r < 0)
            return fail("the encoder refused a frame", r);
        for (;;) {
            const int r = avcodec_receive_packet(codec, packet);
            if (r == AVERROR(EAGAIN) || r == AVERROR_EOF)
                return {};
            if (r < 0)
                return fail("encoding failed", r);
            av_packet_rescale_ts(packet, codec->time_base, stream->time_base);
            packet->stream_index = stream->index;
            if (const int w = av_interleaved_write_frame(format, packet); w < 0)
                return fail("cannot write to the file", w);
        }
    }
};

Mp4Writer::Mp4Writer() : state_(std::make_unique<State>()) {}
Mp4Writer::Mp4Writer(Mp4Writer&&) noexcept = default;
Mp4Writer& Mp4Writer::operator=(Mp4Writer&&) noexcept = default;
Mp4Writer::~Mp4Writer() = default;

const std::string& Mp4Writer::encoder() const {
    return state_->encoder;
}

scene::Expected<Mp4Writer> Mp4Writer::open(const std::filesystem::path& file, const std::string& where,
                                           int width, int height, double fps, int crf) {
    quietFfmpegLog();
    Mp4Writer writer;
    State& s = *writer.state_;
    s.where = where;
    s.width = width;
    s.height = height;
    const std::string name = file.string();
    // The muxer is named: the temporary file's name has no .mp4 extension.
    if (const int r = avformat_alloc_output_context2(&s.format, nullptr, "mp4", name.c_str());
        r < 0 || !s.format)
        return s.fail("cannot set up the MP4 muxer", r);

    const AVCodec* encoder = findEncoder();
    if (!encoder)
        return scene::makeError(scene::ErrorCode::IoError, where, "",
                                "this FFmpeg has no H.264 (libx264) or MPEG-4 encoder");
    s.encoder = encoder->name;
    s.codec = avcodec_alloc_context3(encoder);
    if (!s.codec)
        return s.fail("cannot allocate the encoder", AVERROR(ENOMEM));
    const AVRational rate = av_d2q(fps, 100000);
    s.codec->width = width;
    s.codec->height = height;
    s.codec->pix_fmt = AV_PIX_FMT_YUV420P;
    s.codec->time_base = av_inv_q(rate);
    s.codec->framerate = rate;
    s.codec->gop_size =
        std::max(1, static_cast<int>(std::lround(fps * 2.0))); // a key frame every 2 s, for seeking
    s.codec->color_range = AVCOL_RANGE_MPEG;
    s.codec->colorspace = AVCOL_SPC_BT709;
    s.codec->color_primaries = AVCOL_PRI_BT709;
    s.codec->color_trc = AVCOL_TRC_IEC61966_2_1; // the frames are sRGB
    if (s.encoder == "libx264") {
        av_opt_set(s.codec->priv_data, "preset", "medium", 0);
        av_opt_set(s.codec->priv_data, "crf", std::to_string(crf).c_str(), 0);
    } else {
        // MPEG-4 Part 2 has no CRF; a fixed quantiser is its nearest equivalent.
        s.codec->flags |= AV_CODEC_FLAG_QSCALE;
        s.codec->global_quality = FF_QP2LAMBDA * std::clamp(crf / 6, 2, 31);
    }
    if (s.format->oformat->flags & AVFMT_GLOBALHEADER)
        s.codec->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    if (const int r = avcodec_open2(s.codec, encoder, nullptr); r < 0)
        return s.fail(std::string("cannot open the ") + encoder->name + " encoder", r);

    s.stream = avformat_new_stream(s.format, nullptr);
    if (!s.stream)
        return s.fail("cannot add the video stream", AVERROR(ENOMEM));
    if (const int r = avcodec_parameters_from_context(s.stream->codecpar, s.codec); r < 0)
        return s.fail("cannot describe the video stream", r);
    s.stream->time_base = s.codec->time_base;
    s.stream->avg_frame_rate = rate;

    if (const int r = avio_open(&s.format->pb, name.c_str(), AVIO_FLAG_WRITE); r < 0)
        return s.fail("cannot create " + name, r);
    AVDictionary* muxerOptions = nullptr;
    av_dict_set(&muxerOptions, "movflags", "+faststart", 0);
    const int header = avformat_write_header(s.format, &muxerOptions);
    av_dict_free(&muxerOptions);
    if (header < 0)
        return s.fail("cannot write the MP4 header", header);

    s.frame = av_frame_alloc();
    s.packet = av_packet_alloc();
    if (!s.frame || !s.packet)
        return s.fail("cannot allocate a frame", AVERROR(ENOMEM));
    s.frame->format = AV_PIX_FMT_YUV420P;
    s.frame->width = width;
    s.frame->height = height;
    if (const int r = av_frame_get_buffer(s.frame, 0); r < 0)
        return s.fail("cannot allocate a frame", r);
    s.scaler = sws_getContext(width, height, AV_PIX_FMT_RGBA, width, height, AV_PIX_FMT_YUV420P, SWS_BICUBIC,
                              nullptr, nullptr, nullptr);
    if (!s.scaler)
        return s.fail("cannot set up the RGB to YUV conversion", AVERROR(EINVAL));
    // BT.709 coefficients from full-range RGB to limited-range YUV (swscale defaults to BT.601).
    const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
    sws_setColorspaceDetails(s.scaler, bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16);
    return writer;
}

scene::Expected<void> Mp4Writer::write(const std::uint8_t* rgba) {
    State& s = *state_;
    if (const int r = av_frame_make_writable(s.frame); r < 0)
        return s.fail("cannot reuse the frame", r);
    const std::uint8_t* source[1] = {rgba};
    const int stride[1] = {s.width * 4};
    sws_scale(s.scaler, source, stride, 0, s.height, s.frame->data, s.frame->linesize);
    s.frame->pts = s.nextPts++;
    return s.encode(s.frame);
}

scene::Expected<void> Mp4Writer::finish() {
    State& s = *state_;
    if (auto flushed = s.encode(nullptr); !flushed)
        return flushed;
    if (const int r = av_write_trailer(s.format); r < 0)
        return s.fail("cannot finish the MP4 file", r);
    // avio_closep flushes without reporting a failed write: flushed and
    // checked here, so a full disk is an error (issue #42).
    avio_flush(s.format->pb);
    if (const int r = s.format->pb->error; r < 0)
        return s.fail("cannot write to the file", r);
    if (const int r = avio_closep(&s.format->pb); r < 0)
        return s.fail("cannot close the MP4 file", r);
    return {};
}

} // namespace lpv::video::detail
