#pragma once
// H.264 in MP4 through FFmpeg's libraries (internal to lpv_video). One
// RGBA frame at a time is converted to yuv420p (BT.709, limited range, as
// players expect) and encoded; finish() flushes the encoder and writes the
// index at the front of the file (+faststart) so it plays while downloading.
#include "lpv/scene/Error.h"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

namespace lpv::video::detail {

class Mp4Writer {
  public:
    // `file` is written (the temporary name); `where` names the output in errors.
    static scene::Expected<Mp4Writer> open(const std::filesystem::path& file, const std::string& where,
                                           int width, int height, double fps, int crf);

    Mp4Writer(Mp4Writer&&) noexcept;
    Mp4Writer& operator=(Mp4Writer&&) noexcept;
    ~Mp4Writer(); // closes the file; an unfinished one is incomplete and must be removed by the caller

    // Rows top to bottom, width * height * 4 bytes.
    scene::Expected<void> write(const std::uint8_t* rgba);
    scene::Expected<void> finish();
    const std::string& encoder() const;

  private:
    Mp4Writer();
    struct State;
    std::unique_ptr<State> state_;
};

// The encoder open() picks: libx264, FFmpeg's default H.264 encoder, or mpeg4.
std::string chooseEncoderName();

} // namespace lpv::video::detail
