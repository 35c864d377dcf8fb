#pragma once
// The path-traced reference on disk: one multi-layer EXR (reference/
// ReferenceImage.h names the channels) with the settings it was traced with
// in its header, and the renderer's float images `lpv compare` reads.
#include "lpv/reference/ReferenceImage.h"
#include "lpv/scene/Error.h"
#include "lpv/scene/Image.h"
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

// A linear image to look at: x / (x + key) per channel, then gamma 2.2 (RGBA8);
// one key for several images gives them one exposure. The rectangle
// [x0, x0 + w) x [y0, y0 + h) of the `width` x `height` image.
scene::Image8 previewImage(const std::vector<glm::vec3>& pixels, int width, int x0, int y0, int w, int h,
                           float key);
// The mean luminance of `pixels` where `mask` > 0.5: a key for previewImage.
float meanLuminance(const std::vector<glm::vec3>& pixels, const std::vector<float>& mask);

// What a reference's header records so that pieces traced apart can be
// checked to belong together (`lpv merge`): the XXH3 of the project file's
// bytes (which name every mesh asset by its checksum), and of the effective
// parameter overrides (the project's and --set's, sorted), as 16 hex digits.
scene::Expected<std::string> projectContentHash(const std::filesystem::path& projectFile);
std::string parametersHash(const scene::ParameterSet& parameters);

} // namespace lpv::cli
