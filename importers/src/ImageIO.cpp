#include "lpv/importers/ImageIO.h"

#include <OpenImageIO/imageio.h>

#include <atomic>
#include <unistd.h>

namespace lpv::importers {

using scene::ErrorCode;
using scene::makeError;

scene::Expected<void> writeImage(const std::filesystem::path& file, const Image8& image) {
    if (image.width <= 0 || image.height <= 0 ||
        image.pixels.size() != std::size_t(image.width) * std::size_t(image.height) * std::size_t(image.channels))
        return makeError(ErrorCode::InvalidValue, file.string(), "", "image size and pixel count disagree");
    static std::atomic<unsigned> counter{0};
    // The temporary keeps the real extension last so OpenImageIO picks the same format.
    std::filesystem::path tmp = file;
    tmp.replace_filename("." + file.stem().string() + ".tmp-" + std::to_string(::getpid()) + "-" +
                         std::to_string(counter++) + file.extension().string());
    auto out = OIIO::ImageOutput::create(tmp.string());
    if (!out)
        return makeError(ErrorCode::IoError, file.string(), "", "no image writer for this extension: " + OIIO::geterror());
    OIIO::ImageSpec spec(image.width, image.height, image.channels, OIIO::TypeDesc::UINT8);
    if (!out->open(tmp.string(), spec) || !out->write_image(OIIO::TypeDesc::UINT8, image.pixels.data()) ||
        !out->close()) {
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

scene::Expected<Image8> readImage8(const std::filesystem::path& file) {
    if (!std::filesystem::exists(file))
        return makeError(ErrorCode::FileNotFound, file.string(), "", "no such file");
    auto in = OIIO::ImageInput::open(file.string());
    if (!in)
        return makeError(ErrorCode::UnknownFormat, file.string(), "", "not a readable image: " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    // Guards against headers that claim absurd sizes before we allocate.
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0 || spec.width > 65536 || spec.height > 65536 ||
        spec.nchannels > 4)
        return makeError(ErrorCode::OutOfRange, file.string(), "header",
                         "unsupported image size " + std::to_string(spec.width) + "x" + std::to_string(spec.height) +
                             "x" + std::to_string(spec.nchannels));
    Image8 img;
    img.width = spec.width;
    img.height = spec.height;
    img.channels = spec.nchannels;
    img.pixels.resize(std::size_t(img.width) * std::size_t(img.height) * std::size_t(img.channels));
    if (!in->read_image(0, 0, 0, img.channels, OIIO::TypeDesc::UINT8, img.pixels.data()))
        return makeError(ErrorCode::CorruptAsset, file.string(), "", "could not decode: " + in->geterror());
    return img;
}

} // namespace lpv::importers
