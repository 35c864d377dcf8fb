#pragma once
// Offline video of a camera path (docs/camera-paths.md): every frame rendered
// at a fixed time step along the path's CameraSpline (never real time) on a
// headless GL context of its own, then encoded as an MP4 (H.264 through
// FFmpeg's libavcodec) or written as a PNG sequence. Qt-free, so the editor
// runs it on a worker thread and the CLI calls it directly.
#include "lpv/scene/Error.h"
#include "lpv/scene/Project.h"

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace lpv::video {

using scene::Expected;

struct VideoOptions {
    std::string pathName; // a camera path of the project
    // ".mp4": H.264 (libx264, yuv420p; see videoEncoderName()). A folder (one
    // that exists, a name ending in '/', or a name without extension): PNG
    // files "frame-00000.png"... in it. A file name containing %05d (any
    // %0Nd or %d) and ending in ".png": a PNG sequence numbered from 0.
    std::filesystem::path output;
    int width = 1280, height = 720; // MP4 needs both even (yuv420p halves them); checked, not rounded
    double fps = 30.0;
    std::vector<std::pair<std::string, std::string>> setA; // key=value overrides of the project's parameters
    // Side by side: the left half renders with setA, the right half with
    // setB; each half is the whole view at half the width (same vertical
    // field of view), labelled at its top-left corner.
    std::optional<std::vector<std::pair<std::string, std::string>>> setB;
    std::string labelA, labelB;
    int warmupFrames = 2; // rendered at the first frame's camera and thrown away, so temporal state settles
    // Added: x264 constant rate factor (0 = lossless, 18 = visually lossless, 23 = x264's default).
    int crf = 18;
    // The project's file. With gi.method = radiosity (in setA or setB) the
    // radiosity solution saved beside it is shown as the indirect light; none
    // saved, a damaged one or one solved for another scene is an error, as
    // is an empty path then.
    std::filesystem::path projectFile;
    // Added: called with each texture that could not be read (it renders as
    // the magenta placeholder). May be empty.
    std::function<void(const std::string&)> warning;
};

struct VideoProgress {
    int frame;             // frames finished so far, 1..frames
    int frames;            // total
    double elapsedSeconds; // since renderVideo began (context, textures and warm-up included)
    double etaSeconds;     // estimated time left, from the mean time per frame so far
};

// Renders options.pathName of `project` (texture paths relative to
// `projectDir`) into options.output. Frame i shows time startTime() + i / fps;
// there are videoFrameCount(duration, fps) frames, so a 2 s path at 30 fps is
// 60 frames (0 .. 1.967 s) and plays for exactly 2 s. `progress` is called
// after every frame (on the calling thread); returning false cancels. The
// output is written to a temporary file (PNG: folder) beside the target and
// renamed on success; on error or cancel it is removed, so the target path
// never holds a half-written video. Cancelling returns ErrorCode::Cancelled.
// Creates and destroys its own GL context on the calling thread.
Expected<void> renderVideo(const scene::Project& project, const std::filesystem::path& projectDir,
                           const VideoOptions& options,
                           const std::function<bool(const VideoProgress&)>& progress);

// Everything renderVideo checks before it opens a context: the path exists
// and has keys, sizes, frame rate, output kind, parameter overrides. Errors
// name the option ("width", "setB[0]") and, for bad overrides, the registry's
// complaint.
Expected<void> checkVideoOptions(const scene::Project& project, const VideoOptions& options);

enum class VideoFormat { Mp4, PngSequence };

struct VideoOutput {
    VideoFormat format = VideoFormat::Mp4;
    std::filesystem::path folder; // where the files go (PNG) / the file's folder (MP4)
    std::string pattern;          // PNG: file name with one %0Nd/%d; MP4: the file name
};
// How `output` will be written, or why it cannot be.
Expected<VideoOutput> videoOutputFor(const std::filesystem::path& output);
// `pattern` with its %0Nd / %d replaced by `frame`.
std::string frameFileName(const std::string& pattern, int frame);

// round(duration * fps) when within 1e-4 of a whole number, else rounded up;
// at least 1.
int videoFrameCount(double duration, double fps);

// The encoder MP4 export uses: "libx264" (Debian 12's libavcodec59 links it),
// else FFmpeg's default H.264 encoder, else "mpeg4" (MPEG-4 Part 2).
std::string videoEncoderName();

} // namespace lpv::video
