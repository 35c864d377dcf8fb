// `lpv video`: a camera path rendered offline into an MP4 or PNG sequence
// through lpv_video, with a progress line.
#include "Cli.h"

#include "lpv/scene/CameraSpline.h"
#include "lpv/scene/Project.h"
#include "lpv/video/VideoExport.h"

#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iostream>

#ifdef _WIN32
#include <io.h>
#define LPV_ISATTY(fd) _isatty(fd)
#else
#include <unistd.h>
#define LPV_ISATTY(fd) ::isatty(fd)
#endif

namespace lpv::cli {

namespace fs = std::filesystem;

void printVideoHelp() {
    std::cout << R"(Usage: lpv video PROJECT.lpvproj --path NAME -o OUT.mp4 [options]

Renders the camera path NAME offline, one frame every 1/fps seconds of path
time (not real time), headless (EGL: the GPU where present, Mesa llvmpipe
otherwise), and writes an H.264 MP4 or a PNG sequence. A path of D seconds
gives round(D * fps) frames (2 s at 30 fps: 60 frames, 0 .. 1.967 s).

  -o, --output OUT      .mp4: H.264 (libx264, yuv420p; width and height even)
                        a folder (existing, or ending in / or without
                        extension): frame-00000.png, ... in it
                        NAME-%05d.png (any %0Nd or %d): numbered PNGs
                        Written to a temporary file or folder beside OUT and
                        renamed when complete: OUT never holds a partial video
  --path NAME           Camera path of the project (see `lpv info`), required
  --fps N               Frames per second (default 30; fractions such as 29.97 work)
  --width N             Frame width in pixels (default 1280)
  --height N            Frame height in pixels (default 720)
  --set KEY=VALUE       Override a registry parameter; repeatable (`lpv params`).
                        gi.method=radiosity shows the project's radiosity
                        solution (lpv radiosity); it fails when none matches
  --compare-set KEY=VALUE
                        Side by side: the left half renders with --set, the
                        right half also with these; repeatable. Each half is
                        the whole view at half the width
  --label-a TEXT        Label of the left half (side by side)
  --label-b TEXT        Label of the right half (side by side)
  --crf N               x264 quality, 0 (lossless) .. 51 (default 18)
  --warmup N            Frames rendered and dropped before the first (default 2)

Prints "frame 12/60, 3.1 s elapsed, ~12 s left", in place on a terminal and
every 10% otherwise. Ctrl-C stops cleanly: the temporary output is removed.

Example:
  lpv video sibenik.lpvproj --path tour -o tour.mp4 --fps 30 \
      --set lpv.propagationSteps=2 --compare-set lpv.propagationSteps=8 \
      --label-a "2 steps" --label-b "8 steps"
)";
}

namespace {

volatile std::sig_atomic_t interrupted = 0;
extern "C" void onInterrupt(int) {
    interrupted = 1;
}

// "KEY=VALUE" pairs; false (and the offending text in `bad`) if one has no '='.
bool splitSettings(const std::vector<std::string>& texts,
                   std::vector<std::pair<std::string, std::string>>& out, std::string& bad) {
    for (const std::string& kv : texts) {
        const auto eq = kv.find('=');
        if (eq == std::string::npos || eq == 0) {
            bad = kv;
            return false;
        }
        out.emplace_back(kv.substr(0, eq), kv.substr(eq + 1));
    }
    return true;
}

std::string formatSeconds(double s) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, s < 10.0 ? "%.1f" : "%.0f", s);
    return buffer;
}

} // namespace

int runVideo(Args args) {
    const auto output = args.option("--output", "-o");
    const auto pathName = args.option("--path");
    video::VideoOptions options;
    options.fps = args.real("--fps", 30.0, RealRange::above(0.0));
    options.width = args.integer("--width", 1280, {1});
    options.height = args.integer("--height", 720, {1});
    options.crf = args.integer("--crf", 18, {0, 51});
    options.warmupFrames = args.integer("--warmup", 2, {0});
    const auto labelA = args.option("--label-a");
    const auto labelB = args.option("--label-b");
    const auto sets = args.options("--set");
    const auto compareSets = args.options("--compare-set");
    args.require(pathName.has_value(), "missing --path NAME");
    args.require(output.has_value(), "missing -o OUT.mp4 (or a folder, or NAME-%05d.png)");
    const auto pos = args.expectPositionals(1, "expected exactly one project file");
    if (pos.empty())
        return usageError(*args.error(), "video");

    options.pathName = *pathName;
    options.output = *output;
    std::string bad;
    if (!splitSettings(sets, options.setA, bad))
        return usageError("--set expects KEY=VALUE, got '" + bad + "'", "video");
    if (!compareSets.empty()) {
        // The right half is the left half's settings plus the comparison.
        std::vector<std::pair<std::string, std::string>> b = options.setA;
        if (!splitSettings(compareSets, b, bad))
            return usageError("--compare-set expects KEY=VALUE, got '" + bad + "'", "video");
        options.setB = std::move(b);
    } else if (labelA || labelB) {
        return usageError("--label-a and --label-b label the halves of --compare-set", "video");
    }
    options.labelA = labelA.value_or("");
    options.labelB = labelB.value_or("");
    options.warning = [](const std::string& w) { std::cerr << "lpv: warning: " << w << "\n"; };
    options.projectFile = pos.front(); // gi.method = radiosity shows the solution saved beside it

    const auto project = scene::loadProject(pos.front());
    if (!project) {
        std::cerr << "lpv: " << project.error().describe() << "\n";
        return kFailure;
    }
    printLoadWarnings(pos.front(), project->loadWarnings);
    if (auto ok = video::checkVideoOptions(*project, options); !ok) {
        // A missing path is about the project; everything else about the options given.
        if (ok.error().location == "pathName") {
            std::cerr << "lpv: " << pos.front() << ": " << ok.error().message << "\n";
            return kFailure;
        }
        return usageError(ok.error().describe(), "video");
    }

    const auto format = video::videoOutputFor(options.output);
    const scene::CameraPath* path = nullptr;
    for (const scene::CameraPath& p : project->scene.cameraPaths)
        if (p.name == options.pathName)
            path = &p;
    const scene::CameraSpline spline(*path);
    const int frames = video::videoFrameCount(spline.duration(), options.fps);
    std::printf("%s: path '%s', %g s, %d frames at %g fps, %dx%d%s -> %s (%s)\n", pos.front().c_str(),
                options.pathName.c_str(), double(spline.duration()), frames, options.fps, options.width,
                options.height, options.setB ? " side by side" : "", options.output.string().c_str(),
                format->format == video::VideoFormat::Mp4 ? video::videoEncoderName().c_str() : "PNG");
    std::fflush(stdout);

    const bool terminal = LPV_ISATTY(1) != 0;
    int lastDecile = 0;
    const auto previous = std::signal(SIGINT, onInterrupt);
    interrupted = 0;
    const auto result = video::renderVideo(
        *project, fs::absolute(pos.front()).parent_path(), options, [&](const video::VideoProgress& p) {
            const std::string line = "frame " + std::to_string(p.frame) + "/" + std::to_string(p.frames) +
                                     ", " + formatSeconds(p.elapsedSeconds) + " s elapsed, ~" +
                                     formatSeconds(p.etaSeconds) + " s left";
            if (terminal) {
                std::printf("\r%-60s", line.c_str());
                if (p.frame == p.frames)
                    std::printf("\n");
            } else if (const int decile = p.frame * 10 / p.frames; decile > lastDecile) {
                lastDecile = decile;
                std::printf("%s\n", line.c_str());
            }
            std::fflush(stdout);
            return interrupted == 0;
        });
    std::signal(SIGINT, previous);
    if (!result) {
        if (terminal)
            std::printf("\n");
        std::cerr << "lpv: " << result.error().describe() << "\n";
        return kFailure;
    }
    std::error_code ec;
    const auto bytes = format->format == video::VideoFormat::Mp4 ? fs::file_size(options.output, ec) : 0;
    if (format->format == video::VideoFormat::Mp4 && !ec)
        std::printf("wrote %s (%d frames, %.0f KB)\n", options.output.string().c_str(), frames,
                    double(bytes) / 1024.0);
    else
        std::printf("wrote %d frames into %s\n", frames,
                    (format->folder.empty() ? fs::path(".") : format->folder).string().c_str());
    return kOk;
}

} // namespace lpv::cli
