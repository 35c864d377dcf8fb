// Camera path files: JSON through the project format's reader and writer
// (ProjectJson.cpp), so a path is validated the same way in both; CSV here.
#include "lpv/scene/CameraPathFile.h"

#include "FileText.h"
#include "ProjectJson.h"
#include "lpv/scene/Project.h"
#include "lpv/scene/ProjectLimits.h"
#include "lpv/scene/ValueChecks.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numbers>

namespace lpv::scene {

Expected<std::string> cameraPathToJson(const CameraPath& path) {
    const detail::Json document = detail::cameraPathToDocument(path);
    // Written only if it reads back: a NaN, unsorted keys or a zero
    // quaternion in memory must not become a file that cannot be opened.
    if (auto valid = detail::cameraPathFromDocument(document, path.name); !valid)
        return std::unexpected(valid.error());
    try {
        return document.dump(2) + "\n";
    } catch (const detail::Json::exception& e) {
        return makeError(ErrorCode::InvalidValue, path.name, "name",
                         std::string("cannot write the camera path: ") + e.what());
    }
}

Expected<CameraPath> cameraPathFromJson(std::string_view text, const std::string& where) {
    const auto document = detail::parseProjectText(std::string(text), where);
    if (!document)
        return std::unexpected(document.error());
    return detail::cameraPathFromDocument(*document, where);
}

Expected<CameraPath> loadCameraPathFile(const std::filesystem::path& file) {
    const auto text = detail::readFileBytes(file, detail::kCameraPathFileLimit);
    if (!text)
        return std::unexpected(text.error());
    return cameraPathFromJson(*text, file.string());
}

Expected<void> saveCameraPathFile(const CameraPath& path, const std::filesystem::path& file) {
    auto text = cameraPathToJson(path);
    if (!text) {
        text.error().file = file.string();
        return std::unexpected(text.error());
    }
    // What loadCameraPathFile would refuse is not written (issue #42).
    if (auto fits = checkWriteFits(text->size(), detail::kCameraPathFileLimit, file.string()); !fits)
        return fits;
    return writeFileAtomically(file, *text);
}

namespace {

// Shortest text that reads back as the same value.
template <class T> void appendNumber(std::string& out, T v) {
    char buffer[64];
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
    out.append(buffer, ec == std::errc() ? end : buffer);
}

} // namespace

int cameraPathCsvRows(double duration, double fps) {
    if (!(fps > 0.0) || !std::isfinite(fps) || !(duration > 0.0))
        return 1;
    // Clamped before the cast: 1e30 s once printed "-2147483647 rows" (issue #42).
    const double frames = std::floor(duration * fps + 1e-4);
    const double kept =
        std::isfinite(frames) ? std::clamp(frames, 0.0, kMaxPlannedFrames) : kMaxPlannedFrames;
    return static_cast<int>(kept) + 1;
}

std::string cameraPathToCsv(const CameraSpline& spline, double fps) {
    std::string out = "time,px,py,pz,qx,qy,qz,qw,fovY_deg\n";
    if (!(fps > 0.0) || !std::isfinite(fps))
        return out;
    const int rows = cameraPathCsvRows(spline.duration(), fps);
    for (int i = 0; i < rows; ++i) {
        const double time = static_cast<double>(spline.startTime()) + i / fps;
        const CameraKeyframe k = spline.sample(static_cast<float>(time));
        appendNumber(out, time);
        for (const float v :
             {k.position.x, k.position.y, k.position.z, k.orientation.x, k.orientation.y, k.orientation.z,
              k.orientation.w, static_cast<float>(k.fovY * (180.0 / std::numbers::pi))}) {
            out += ',';
            appendNumber(out, v);
        }
        out += '\n';
    }
    return out;
}

} // namespace lpv::scene
