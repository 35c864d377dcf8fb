#pragma once
// Camera paths on their own, for exchange with other tools
// (docs/camera-paths.md): our JSON schema, read and written, and a CSV of the
// camera at every frame for a chosen frame rate.
#include "lpv/scene/Camera.h"
#include "lpv/scene/CameraSpline.h"
#include "lpv/scene/Error.h"

#include <filesystem>
#include <string>
#include <string_view>

namespace lpv::scene {

inline constexpr const char* kCameraPathFormatName = "lpvstudio-camera-path";
inline constexpr int kCameraPathFormatVersion = 1;

// The JSON text of a path file. Fails (error naming the keyframe field) on
// what the reader would refuse: non-finite numbers, unsorted times, an
// all-zero quaternion, a field of view outside (0, 180) degrees, a name that
// is not UTF-8.
Expected<std::string> cameraPathToJson(const CameraPath& path);

// Parses and validates a path file; `where` names it in errors (the file
// name). Errors locate the field ("keyframes[2].orientation") or, for text
// that is not JSON, the byte offset.
Expected<CameraPath> cameraPathFromJson(std::string_view text, const std::string& where);

// The same through files; saving is atomic (temporary file, rename).
Expected<CameraPath> loadCameraPathFile(const std::filesystem::path& file);
Expected<void> saveCameraPathFile(const CameraPath& path, const std::filesystem::path& file);

// "time,px,py,pz,qx,qy,qz,qw,fovY_deg", then one row per frame at times
// startTime() + i / fps for i = 0 .. floor(duration * fps) (the end included
// when it falls on a frame; a frame within 1e-4 frames of the end counts).
// `fps` must be positive and finite; otherwise only the header is returned.
std::string cameraPathToCsv(const CameraSpline& spline, double fps);

// Number of CSV rows (frames) for a duration: floor(duration * fps + 1e-4) + 1.
int cameraPathCsvRows(double duration, double fps);

} // namespace lpv::scene
