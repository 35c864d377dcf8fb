#pragma once
// Private to lpv_scene: the project file's JSON document <-> Project
// (docs/project-format.md). The geometry of meshes is not in the JSON; it
// lives in the mesh assets the document refers to.
#include "lpv/scene/CameraPathFile.h"
#include "lpv/scene/Project.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace lpv::scene::detail {

// Ordered, so a saved file lists its fields in the documented order.
using Json = nlohmann::ordered_json;

// A mesh as the document describes it.
struct MeshReference {
    std::string name;
    std::string asset; // relative to the project file's folder, '/'-separated
    std::uint64_t vertices = 0;  // recorded at save time, checked against the asset on load
    std::uint64_t triangles = 0;
};

struct ProjectDocument {
    Project project; // scene.meshes is empty: the loader fills it from the assets
    std::vector<MeshReference> meshes;
};

// Checks format name and version, migrates an older document to
// kProjectFormatVersion, then validates every field (types, finiteness,
// ranges, enum names, parameter keys, indices, parent chains). Error
// locations are JSON paths such as "materials[2].diffuseColor[1]".
Expected<ProjectDocument> projectFromJson(const Json& document, const std::string& file);

// `assetPaths[i]` is the path written for mesh i. Floats are written as the
// shortest decimal that reads back as the same float.
Json projectToJson(const Project& project, const std::vector<std::string>& assetPaths);

// An asset path must stay inside the project's folder: relative, '/'
// separators, no "." or ".." components, no drive letters.
Expected<void> checkAssetPath(const std::string& path, const std::string& file, const std::string& location);

// A camera path file (docs/camera-paths.md): format name and version, then
// the same checks as a project's camera path, the field of view in degrees.
Expected<CameraPath> cameraPathFromDocument(const Json& document, const std::string& file);
Json cameraPathToDocument(const CameraPath& path);

// Parses the text of a project file. Errors: Truncated (empty or cut off),
// NotJson, NonFinite (a number too large for a double, e.g. 1e999); the
// location is a byte offset.
Expected<Json> parseProjectText(const std::string& text, const std::string& file);

} // namespace lpv::scene::detail
