#include "lpv/importers/ImageIO.h"

#include "lpv/scene/FileRead.h"

#include "lpv/scene/ProcessId.h"

#include <OpenImageIO/imageio.h>

#include <atomic>

namespace lpv::importers {

using scene::ErrorCode;
using scene::makeError;

namespace {

// Writes through a temporary beside the target, then renames: a failed or
// interrupted write never leaves a half-written image at `file`.
scene::Expected<void> writeAtomically(const std::filesystem::path& file, int width, int height, int channels,
                                      OIIO::TypeDesc type, const void* pixels,
                                      const std::vector<std::string>& channelNames = {},
                                      const std::vector<std::pair<std::string, std::string>>& attributes = {}) {
    static std::atomic<unsigned> counter{0};
    // The temporary keeps the real extension last so OpenImageIO picks the same format.
    std::filesystem::path tmp = file;
    tmp.replace_filename("." + file.stem().string() + ".tmp-" + std::to_string(scene::processId()) + "-" +
                         std::to_string(counter++) + file.extension().string());
    auto out = OIIO::ImageOutput::create(tmp.string());
    if (!out)
        return makeError(ErrorCode::IoError, file.string(), "", "no image writer for this extension: " + OIIO::geterror());
    OIIO::ImageSpec spec(width, height, channels, type);
    // Our pixels are straight (not premultiplied) alpha; say so, or formats
    // with associated alpha (TGA, TIFF) would change the colours.
    spec.attribute("oiio:UnassociatedAlpha", 1);
    if (!channelNames.empty()) {
        spec.channelnames = channelNames;
        spec.alpha_channel = -1; // named layers: none of them is coverage alpha
    }
    for (const auto& [name, value] : attributes)
        spec.attribute(name, value);
    if (!out->open(tmp.string(), spec) || !out->write_image(type, pixels) || !out->close()) {
        std::string err = out->geterror();
        out.reset();
        std::error_code ec;
        std::filesystem::remove(tmp, ec);
        return makeError(ErrorCode::IoError, file.string(), "", "could not write image: " + err);
    }
    out.reset();
    std::error_code ec;
    std::filesystem::rename(tmp, file, ec);
    if (ec) {
        std::filesystem::remove(tmp, ec);
        return makeError(ErrorCode::IoError, file.string(), "", "could not move the image into place: " + ec.message());
    }
    return {};
}

} // namespace

scene::Expected<void> writeImage(const std::filesystem::path& file, const Image8& image) {
    if (image.width <= 0 || image.height <= 0 ||
        image.pixels.size() != std::size_t(image.width) * std::size_t(image.height) * std::size_t(image.channels))
        return makeError(ErrorCode::InvalidValue, file.string(), "", "image size and pixel count disagree");
    return writeAtomically(file, image.width, image.height, image.channels, OIIO::TypeDesc::UINT8,
                           image.pixels.data());
}

scene::Expected<void> writeImageFloat(const std::filesystem::path& file, int width, int height, int channels,
                                      const std::vector<float>& pixels) {
    if (width <= 0 || height <= 0 || channels <= 0 ||
        pixels.size() != std::size_t(width) * std::size_t(height) * std::size_t(channels))
        return makeError(ErrorCode::InvalidValue, file.string(), "", "image size and pixel count disagree");
    return writeAtomically(file, width, height, channels, OIIO::TypeDesc::FLOAT, pixels.data());
}

scene::Expected<void> writeImageChannels(const std::filesystem::path& file, const FloatChannels& image,
                                         const std::vector<std::pair<std::string, std::string>>& attributes) {
    const std::size_t channels = image.names.size();
    if (image.width <= 0 || image.height <= 0 || channels == 0 ||
        image.pixels.size() != std::size_t(image.width) * std::size_t(image.height) * channels)
        return makeError(ErrorCode::InvalidValue, file.string(), "", "image size and pixel count disagree");
    return writeAtomically(file, image.width, image.height, int(channels), OIIO::TypeDesc::FLOAT,
                           image.pixels.data(), image.names, attributes);
}

} // namespace lpv::importers
