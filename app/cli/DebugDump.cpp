#include "DebugDump.h"

#include "lpv/importers/ImageIO.h"
#include "lpv/renderer/viz/TileImages.h"

#include <iostream>

namespace lpv::cli {

std::vector<std::uint8_t> debugImageToRgba8(const renderer::DebugImage& image) {
    // The same picture the editor's viewers show.
    return renderer::viz::debugImageView(image).pixels;
}

std::vector<std::filesystem::path> writeDebugImages(const std::vector<renderer::DebugImage>& images,
                                                    const std::filesystem::path& output, bool& ok) {
    ok = true;
    std::vector<std::filesystem::path> written;
    for (const renderer::DebugImage& image : images) {
        std::filesystem::path base = output;
        base.replace_filename(output.stem().string() + "-" + image.name);
        const std::filesystem::path exr = base.string() + ".exr", png = base.string() + ".png";
        if (auto r = importers::writeImageFloat(exr, image.width, image.height, image.channels, image.pixels); !r) {
            std::cerr << "lpv: " << r.error().describe() << "\n";
            ok = false;
            return written;
        }
        written.push_back(exr);
        if (auto r = importers::writeImage(png, {image.width, image.height, 4, debugImageToRgba8(image)}); !r) {
            std::cerr << "lpv: " << r.error().describe() << "\n";
            ok = false;
            return written;
        }
        written.push_back(png);
    }
    return written;
}

} // namespace lpv::cli
