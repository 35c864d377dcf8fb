// renderVideo: camera path -> frames at fixed time steps -> MP4 or PNGs,
// never leaving a half-written result at the target path.
#include "lpv/video/VideoExport.h"

#include "Mp4Writer.h"
#include "lpv/importers/ImageIO.h"
#include "lpv/importers/SceneTextures.h"
#include "lpv/radiosity/BakedSolution.h"
#include "lpv/renderer/ForwardRenderer.h"
#include "lpv/renderer/GlContext.h"
#include "lpv/renderer/SceneAnalysis.h"
#include "lpv/scene/CameraSpline.h"
#include "lpv/scene/FramingCamera.h"
#include "lpv/scene/Project.h"
#include "lpv/scene/ValueChecks.h"
#include "lpv/video/FrameLabels.h"

#include <algorithm>
#include <atomic>
#include <cctype>
#include <chrono>
#include <cmath>
#include <optional>
#include <system_error>

#ifdef _WIN32
#include <process.h>
#else
#include <fcntl.h>
#include <unistd.h>
#endif

namespace lpv::video {
namespace {

namespace fs = std::filesystem;
using scene::ErrorCode;
using scene::makeError;

constexpr int kMaxSide = 16384;
constexpr double kMaxFps = 1000.0;
constexpr const char* kFolderPattern = "frame-%05d.png";

std::atomic<unsigned> tempCounter{0};

std::string tempSuffix() {
#ifdef _WIN32
    const int pid = _getpid();
#else
    const int pid = static_cast<int>(::getpid());
#endif
    return ".tmp-" + std::to_string(pid) + "-" + std::to_string(tempCounter.fetch_add(1));
}

std::string lower(std::string s) {
    for (char& c : s)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

// The one "%0Nd" or "%d" of a sequence pattern: where it starts, how long it
// is, and the zero-padded width (0 for "%d").
struct Placeholder {
    std::size_t at = 0, length = 0;
    int width = 0;
};
std::optional<Placeholder> findPlaceholder(const std::string& pattern) {
    const std::size_t at = pattern.find('%');
    if (at == std::string::npos || pattern.find('%', at + 1) != std::string::npos)
        return std::nullopt;
    std::size_t i = at + 1;
    int width = 0;
    if (i < pattern.size() && pattern[i] == '0') {
        ++i;
        const std::size_t digits = i;
        while (i < pattern.size() && std::isdigit(static_cast<unsigned char>(pattern[i])) && i - digits < 2)
            width = width * 10 + (pattern[i++] - '0');
        if (i == digits)
            return std::nullopt;
    }
    if (i >= pattern.size() || pattern[i] != 'd')
        return std::nullopt;
    return Placeholder{at, i + 1 - at, width};
}

const scene::CameraPath* findPath(const scene::Scene& s, const std::string& name) {
    for (const scene::CameraPath& p : s.cameraPaths)
        if (p.name == name)
            return &p;
    return nullptr;
}

// The project's parameters with `overrides` applied; errors are located at
// "setA[i]" (`name`) of `file` (the output) and keep the registry's message.
scene::Expected<scene::ParameterSet>
withOverrides(const scene::ParameterSet& base,
              const std::vector<std::pair<std::string, std::string>>& overrides, const std::string& file,
              const std::string& name) {
    scene::ParameterSet out = base;
    for (std::size_t i = 0; i < overrides.size(); ++i)
        if (auto ok = out.setFromText(overrides[i].first, overrides[i].second, file); !ok) {
            scene::Error e = ok.error();
            e.file = file;
            e.location = name + "[" + std::to_string(i) + "]";
            return std::unexpected(e);
        }
    return out;
}

// Makes the renamed file or folder durable (POSIX; best effort).
void syncPath([[maybe_unused]] const fs::path& path, [[maybe_unused]] bool folder) {
#ifndef _WIN32
    const int fd = ::open(path.empty() ? "." : path.c_str(),
                          folder ? (O_RDONLY | O_DIRECTORY | O_CLOEXEC) : (O_RDONLY | O_CLOEXEC));
    if (fd >= 0) {
        ::fsync(fd);
        ::close(fd);
    }
#endif
}

// Where frames go while rendering, and how they reach the target. Removes
// the temporary file or folder unless commit() succeeded.
class PendingOutput {
  public:
    PendingOutput(const PendingOutput&) = delete;
    PendingOutput& operator=(const PendingOutput&) = delete;
    ~PendingOutput() {
        if (!committed_ && !temp_.empty()) {
            std::error_code ignored;
            fs::remove_all(temp_, ignored);
        }
    }

    static scene::Expected<std::unique_ptr<PendingOutput>> create(const VideoOutput& out,
                                                                  const std::string& where) {
        auto p = std::unique_ptr<PendingOutput>(new PendingOutput());
        p->out_ = out;
        p->where_ = where;
        const fs::path folder = out.folder.empty() ? fs::path(".") : out.folder;
        std::error_code ec;
        if (out.format == VideoFormat::Mp4) {
            fs::create_directories(folder, ec);
            if (ec)
                return makeError(ErrorCode::IoError, where, "",
                                 "cannot create the folder " + folder.string() + ": " + ec.message());
            p->target_ = folder / out.pattern;
            p->temp_ = folder / (out.pattern + tempSuffix());
            return p;
        }
        // PNG sequence: a new folder is renamed into place as a whole; into an
        // existing one the finished files are moved one by one.
        p->target_ = folder;
        p->folderExisted_ = fs::is_directory(folder, ec);
        if (p->folderExisted_) {
            p->temp_ = folder / (".lpv-video" + tempSuffix());
        } else {
            fs::path name = folder.filename();
            p->temp_ = folder.parent_path() / (name.string() + tempSuffix());
            if (!folder.parent_path().empty())
                fs::create_directories(folder.parent_path(), ec);
        }
        fs::create_directory(p->temp_, ec);
        if (ec)
            return makeError(ErrorCode::IoError, where, "",
                             "cannot create the folder " + p->temp_.string() + ": " + ec.message());
        return p;
    }

    // The MP4 file or the PNG folder being written.
    const fs::path& temp() const { return temp_; }

    scene::Expected<void> commit() {
        std::error_code ec;
        if (out_.format == VideoFormat::Mp4) {
            // A failed sync is a failed write (issue #42): the file is not renamed into place.
            if (auto synced = scene::syncFileToDisk(temp_); !synced)
                return makeError(ErrorCode::IoError, where_, "", synced.error().message);
            fs::rename(temp_, target_, ec);
        } else if (!folderExisted_) {
            fs::rename(temp_, target_, ec);
        } else {
            for (const auto& entry : fs::directory_iterator(temp_, ec)) {
                fs::rename(entry.path(), target_ / entry.path().filename(), ec);
                if (ec)
                    break;
            }
            if (!ec)
                fs::remove(temp_, ec);
        }
        if (ec)
            return makeError(ErrorCode::IoError, where_, "",
                             "cannot move the finished video into place: " + ec.message());
        committed_ = true;
        syncPath(target_.parent_path(), true);
        return {};
    }

  private:
    PendingOutput() = default;
    VideoOutput out_;
    std::string where_;
    fs::path target_, temp_;
    bool folderExisted_ = false;
    bool committed_ = false;
};

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

} // namespace

std::string frameFileName(const std::string& pattern, int frame) {
    const auto p = findPlaceholder(pattern);
    if (!p)
        return pattern;
    std::string number = std::to_string(frame);
    if (static_cast<int>(number.size()) < p->width)
        number.insert(0, static_cast<std::size_t>(p->width) - number.size(), '0');
    return pattern.substr(0, p->at) + number + pattern.substr(p->at + p->length);
}

scene::Expected<VideoOutput> videoOutputFor(const fs::path& output) {
    const std::string where = output.string();
    if (output.empty())
        return makeError(ErrorCode::InvalidValue, where, "output", "no output file or folder given");
    const std::string name = output.filename().string();
    if (name.empty()) // "frames/": a folder
        return VideoOutput{VideoFormat::PngSequence, output.parent_path(), kFolderPattern};
    if (name.find('%') != std::string::npos) {
        if (!findPlaceholder(name))
            return makeError(
                ErrorCode::InvalidValue, where, "output",
                "a numbered file name needs exactly one %d or %0Nd (N up to 99), such as frame-%05d.png");
        if (!lower(name).ends_with(".png"))
            return makeError(ErrorCode::InvalidValue, where, "output",
                             "numbered frames are written as PNG: end the name with .png");
        return VideoOutput{VideoFormat::PngSequence, output.parent_path(), name};
    }
    const std::string extension = lower(output.extension().string());
    if (extension == ".mp4")
        return VideoOutput{VideoFormat::Mp4, output.parent_path(), name};
    std::error_code ec;
    if (extension.empty() || fs::is_directory(output, ec))
        return VideoOutput{VideoFormat::PngSequence, output, kFolderPattern};
    return makeError(ErrorCode::InvalidValue, where, "output",
                     "cannot write a video as \"" + extension +
                         "\": use .mp4, a folder, or a numbered PNG name such as frame-%05d.png");
}

int videoFrameCount(double duration, double fps) {
    if (!(duration > 0.0) || !(fps > 0.0) || !std::isfinite(duration * fps))
        return 1;
    const double n = duration * fps;
    const double whole = std::round(n);
    const double count = std::abs(n - whole) < 1e-4 ? whole : std::ceil(n);
    return static_cast<int>(std::clamp(count, 1.0, 1e9));
}

std::string videoEncoderName() {
    return detail::chooseEncoderName();
}

scene::Expected<void> checkVideoOptions(const scene::Project& project, const VideoOptions& options) {
    const std::string where = options.output.string();
    const auto output = videoOutputFor(options.output);
    if (!output)
        return std::unexpected(output.error());
    const scene::CameraPath* path = findPath(project.scene, options.pathName);
    if (!path) {
        std::string names;
        for (const scene::CameraPath& p : project.scene.cameraPaths)
            names += (names.empty() ? "\"" : ", \"") + p.name + "\"";
        return makeError(ErrorCode::InvalidValue, where, "pathName",
                         "the project has no camera path named \"" + options.pathName +
                             "\" (paths: " + (names.empty() ? std::string("none") : names) + ")");
    }
    if (path->keyframes.empty())
        return makeError(ErrorCode::InvalidValue, where, "pathName",
                         "the camera path \"" + options.pathName + "\" has no keyframes");
    // Before any frame is planned: a key at 1e30 s once planned 10^9 frames (issue #42).
    if (options.fps > 0.0 && options.fps <= kMaxFps)
        if (auto why = scene::checkPlannedFrames(double(scene::CameraSpline(*path).duration()), options.fps))
            return makeError(ErrorCode::OutOfRange, where, "pathName",
                             "the camera path \"" + options.pathName + "\": " + *why);
    const std::string size = std::to_string(options.width) + "x" + std::to_string(options.height);
    if (options.width < 1 || options.height < 1 || options.width > kMaxSide || options.height > kMaxSide)
        return makeError(ErrorCode::OutOfRange, where,
                         options.width < 1 || options.width > kMaxSide ? "width" : "height",
                         "the frame size " + size + " is outside 1.." + std::to_string(kMaxSide));
    if (options.setB && options.width < 2)
        return makeError(ErrorCode::OutOfRange, where, "width", "side by side needs a width of at least 2");
    // yuv420p stores colour at half resolution in both directions.
    if (output->format == VideoFormat::Mp4 && (options.width % 2 != 0 || options.height % 2 != 0))
        return makeError(ErrorCode::InvalidValue, where, options.width % 2 != 0 ? "width" : "height",
                         "H.264 video (yuv420p) needs an even width and height; " + size + " is not");
    if (!(options.fps > 0.0) || !(options.fps <= kMaxFps))
        return makeError(ErrorCode::OutOfRange, where, "fps",
                         "the frame rate must be above 0 and at most " + std::to_string(int(kMaxFps)));
    if (options.crf < 0 || options.crf > 51)
        return makeError(ErrorCode::OutOfRange, where, "crf", "the quality (CRF) must be within 0..51");
    if (options.warmupFrames < 0)
        return makeError(ErrorCode::OutOfRange, where, "warmupFrames", "cannot be negative");
    if (auto a = withOverrides(project.parameters, options.setA, where, "setA"); !a)
        return std::unexpected(a.error());
    if (options.setB)
        if (auto b = withOverrides(project.parameters, *options.setB, where, "setB"); !b)
            return std::unexpected(b.error());
    return {};
}

scene::Expected<void> renderVideo(const scene::Project& project, const fs::path& projectDir,
                                  const VideoOptions& options,
                                  const std::function<bool(const VideoProgress&)>& progress) {
    const auto began = std::chrono::steady_clock::now();
    if (auto ok = checkVideoOptions(project, options); !ok)
        return ok;
    const std::string where = options.output.string();
    const VideoOutput output = *videoOutputFor(options.output);
    const scene::CameraSpline spline(*findPath(project.scene, options.pathName));
    const scene::ParameterSet paramsA = *withOverrides(project.parameters, options.setA, where, "setA");
    const std::optional<scene::ParameterSet> paramsB =
        options.setB ? std::optional(*withOverrides(project.parameters, *options.setB, where, "setB"))
                     : std::nullopt;
    // Near and far planes (the path has none) from the camera the project would render with.
    const scene::Camera base =
        project.scene.cameras.empty() ? scene::framingCamera(project.scene) : project.scene.cameras.front();
    const int frames = videoFrameCount(spline.duration(), options.fps);
    const int widthA = paramsB ? options.width / 2 : options.width;
    const int widthB = options.width - widthA;

    // Our own context, current on this thread, so a caller's (the editor's viewport) is never touched.
    auto context = renderer::HeadlessContext::create();
    if (!context)
        return std::unexpected(context.error());
    std::vector<renderer::ForwardRenderer> renderers;
    for (int i = 0; i < (paramsB ? 2 : 1); ++i) {
        auto r = renderer::ForwardRenderer::create();
        if (!r)
            return std::unexpected(r.error());
        renderers.push_back(std::move(*r));
    }
    const auto textures = importers::loadSceneTextures(project.scene, projectDir);
    if (options.warning)
        for (const std::string& w : textures.warnings)
            options.warning(w);
    // gi.method = radiosity in either half: the saved solution, checked against this scene.
    std::shared_ptr<const radiosity::BakedSolution> baked;
    if (renderer::showsBakedRadiosity(paramsA) || (paramsB && renderer::showsBakedRadiosity(*paramsB))) {
        auto loaded = radiosity::loadBakedSolution(project.scene, textures.images, options.projectFile);
        if (!loaded)
            return std::unexpected(loaded.error());
        baked = std::make_shared<const radiosity::BakedSolution>(std::move(*loaded));
    }
    for (renderer::ForwardRenderer& r : renderers) {
        r.setScene(project.scene, textures.images);
        r.setBakedRadiosity(baked);
        // Auto exposure adapts by one frame's time per frame: the same path gives the same video.
        r.setExposureTimeStep(1.0 / double(options.fps));
    }

    auto pending = PendingOutput::create(output, where);
    if (!pending)
        return std::unexpected(pending.error());
    std::optional<detail::Mp4Writer> mp4;
    if (output.format == VideoFormat::Mp4) {
        auto writer = detail::Mp4Writer::open((*pending)->temp(), where, options.width, options.height,
                                              options.fps, options.crf);
        if (!writer)
            return std::unexpected(writer.error());
        mp4.emplace(std::move(*writer));
    }

    // Renders the frame at `time` into `out` (RGBA, rows top to bottom).
    const auto renderFrame = [&](float time, scene::Image8& out) -> scene::Expected<void> {
        const scene::Camera camera = spline.cameraAt(time, base);
        if (auto ok = renderers[0].render(project.scene, paramsA, camera, widthA, options.height); !ok)
            return ok;
        if (!paramsB) {
            out = scene::Image8{options.width, options.height, 4, renderers[0].readDisplay()};
            return {};
        }
        if (auto ok = renderers[1].render(project.scene, *paramsB, camera, widthB, options.height); !ok)
            return ok;
        out = sideBySide(renderers[0].readDisplay(), widthA, renderers[1].readDisplay(), widthB,
                         options.height, options.labelA, options.labelB);
        return {};
    };

    scene::Image8 image;
    for (int i = 0; i < options.warmupFrames; ++i)
        if (auto ok = renderFrame(spline.startTime(), image); !ok)
            return ok;
    const double setupSeconds = secondsSince(began);
    for (int i = 0; i < frames; ++i) {
        const float time = static_cast<float>(static_cast<double>(spline.startTime()) + i / options.fps);
        if (auto ok = renderFrame(time, image); !ok)
            return ok;
        if (mp4) {
            if (auto ok = mp4->write(image.pixels.data()); !ok)
                return ok;
        } else if (auto ok =
                       importers::writeImage((*pending)->temp() / frameFileName(output.pattern, i), image);
                   !ok) {
            return ok;
        }
        const double elapsed = secondsSince(began);
        const double perFrame = (elapsed - setupSeconds) / (i + 1);
        const VideoProgress p{i + 1, frames, elapsed, perFrame * (frames - i - 1)};
        if (progress && !progress(p))
            return makeError(ErrorCode::Cancelled, where, "",
                             "cancelled after frame " + std::to_string(i + 1) + " of " +
                                 std::to_string(frames));
    }
    if (mp4)
        if (auto ok = mp4->finish(); !ok)
            return ok;
    mp4.reset();
    return (*pending)->commit();
}

} // namespace lpv::video
