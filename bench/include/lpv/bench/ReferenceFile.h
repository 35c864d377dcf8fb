#pragma once
// The path-traced reference on disk: one multi-layer EXR (reference/
// ReferenceImage.h names the channels) with the settings it was traced with
// in its header, and the renderer's float images `lpv compare` reads.
//
// It lives in lpv_bench rather than lpv_reference because it is a file
// format over OpenImageIO (through lpv_importers): lpv_reference stays free
// of files and image libraries, and radiosity, which links it, with it.
#include "lpv/reference/ReferenceImage.h"
#include "lpv/scene/Error.h"

#include <glm/vec3.hpp>

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace lpv::bench {

scene::Expected<void> writeReferenceExr(const std::filesystem::path& file,
                                        const reference::ReferenceImage& image,
                                        const std::map<std::string, std::string>& attributes);

// A reference read back. The image's samplesPerPixel and seconds come from
// the header's "lpv:spp" and "lpv:seconds" (0 where absent or unreadable).
struct LoadedReference {
    reference::ReferenceImage image;
    std::map<std::string, std::string> attributes; // "lpv:spp", "lpv:project", ...

    // The header's "lpv:bounces", or nullopt where absent or not a whole number.
    std::optional<int> bounces() const;
};
scene::Expected<LoadedReference> readReferenceExr(const std::filesystem::path& file);

// "320x180, 4096 spp in 61.2 s", or "unreadable": a reference as a report names it.
std::string describeReferenceFile(const std::filesystem::path& file);

// An RGB float image (the first three channels R, G, B of any EXR), plus the
// header's "lpv:outputView" when `lpv render` wrote it.
struct RgbImage {
    int width = 0;
    int height = 0;
    std::vector<glm::vec3> pixels;
    std::string outputView; // final, indirect, direct; empty if unknown
};
scene::Expected<RgbImage> readRgbExr(const std::filesystem::path& file);

} // namespace lpv::bench
