#pragma once
// The path-traced reference on disk: one multi-layer EXR (reference/
// ReferenceImage.h names the channels) with the settings it was traced with
// in its header, and the renderer's float images `lpv compare` reads.
#include "lpv/reference/ReferenceImage.h"
#include "lpv/scene/Error.h"
#include "lpv/scene/ParameterRegistry.h"

#include <filesystem>
#include <map>
#include <string>

namespace lpv::cli {

scene::Expected<void> writeReferenceExr(const std::filesystem::path& file,
                                        const reference::ReferenceImage& image,
                                        const std::map<std::string, std::string>& attributes);

struct LoadedReference {
    reference::ReferenceImage image;
    std::map<std::string, std::string> attributes; // "lpv:spp", "lpv:project", ...
};
scene::Expected<LoadedReference> readReferenceExr(const std::filesystem::path& file);

// An RGB float image (the first three channels R, G, B of any EXR), plus the
// header's "lpv:outputView" when `lpv render` wrote it.
struct RgbImage {
    int width = 0;
    int height = 0;
    std::vector<glm::vec3> pixels;
    std::string outputView; // final, indirect, direct; empty if unknown
};
scene::Expected<RgbImage> readRgbExr(const std::filesystem::path& file);

// What ties pieces made apart together, as 16 hex digits of XXH3: of a
// file's bytes (a reference shard's project file, which names every mesh
// asset by its checksum; the reference a sweep shard measured against), and
// of the effective parameter overrides (the project's and --set's, sorted).
scene::Expected<std::string> fileContentHash(const std::filesystem::path& file);
std::string parametersHash(const scene::ParameterSet& parameters);

} // namespace lpv::cli
