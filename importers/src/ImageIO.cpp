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

namespace {
// readImage8's and readImageChannels' refusal of what is not a regular file
// (scene::notARegularFile says why).
std::unexpected<scene::Error> notReadable(const std::filesystem::path& file, const std::string& why) {
    return makeError(why == "no such file" ? ErrorCode::FileNotFound : ErrorCode::IoError, file.string(), "", why);
}
} // namespace

scene::Expected<FloatChannels> readImageChannels(const std::filesystem::path& file) {
    if (const auto why = scene::notARegularFile(file))
        return notReadable(file, *why);
    auto in = OIIO::ImageInput::open(file.string());
    if (!in)
        return makeError(ErrorCode::UnknownFormat, file.string(), "", "not a readable image: " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0 || spec.width > kMaxImageSide ||
        spec.height > kMaxImageSide || spec.nchannels > 64)
        return makeError(ErrorCode::OutOfRange, file.string(), "header",
                         "unsupported image size " + std::to_string(spec.width) + "x" + std::to_string(spec.height) +
                             "x" + std::to_string(spec.nchannels));
    FloatChannels img;
    img.width = spec.width;
    img.height = spec.height;
    for (int c = 0; c < spec.nchannels; ++c)
        img.names.push_back(spec.channel_name(c));
    img.pixels.resize(std::size_t(img.width) * std::size_t(img.height) * img.names.size());
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, img.pixels.data()))
        return makeError(ErrorCode::CorruptAsset, file.string(), "", "could not decode: " + in->geterror());
    for (const OIIO::ParamValue& p : spec.extra_attribs)
        if (p.type() == OIIO::TypeDesc::STRING)
            img.attributes.emplace_back(p.name().string(), p.get_string());
    return img;
}

scene::Expected<Image8> readImage8(const std::filesystem::path& file) {
    if (const auto why = scene::notARegularFile(file))
        return notReadable(file, *why);
    // Textures are used with straight alpha: keep the file's values as they are.
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto in = OIIO::ImageInput::open(file.string(), &config);
    if (!in)
        return makeError(ErrorCode::UnknownFormat, file.string(), "", "not a readable image: " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    // Guards against headers that claim absurd sizes before we allocate.
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0 || spec.width > kMaxImageSide ||
        spec.height > kMaxImageSide || spec.nchannels > 4)
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

scene::Expected<Image8> readTextureRgba8(const std::filesystem::path& file) {
    auto img = readImage8(file);
    if (!img || img->channels == 4)
        return img;
    Image8 rgba;
    rgba.width = img->width;
    rgba.height = img->height;
    rgba.channels = 4;
    const std::size_t count = std::size_t(img->width) * std::size_t(img->height);
    rgba.pixels.resize(count * 4);
    const int c = img->channels;
    for (std::size_t i = 0; i < count; ++i) {
        const std::uint8_t* src = &img->pixels[i * std::size_t(c)];
        std::uint8_t* dst = &rgba.pixels[i * 4];
        // grey, grey + alpha, or RGB
        dst[0] = src[0];
        dst[1] = c >= 3 ? src[1] : src[0];
        dst[2] = c >= 3 ? src[2] : src[0];
        dst[3] = c == 2 ? src[1] : 255;
    }
    return rgba;
}

Image8 placeholderTexture() {
    constexpr int kSize = 64, kCheck = 8;
    Image8 img;
    img.width = img.height = kSize;
    img.channels = 4;
    img.pixels.resize(std::size_t(kSize) * kSize * 4);
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const bool magenta = ((x / kCheck) + (y / kCheck)) % 2 == 0;
            std::uint8_t* p = &img.pixels[(std::size_t(y) * kSize + std::size_t(x)) * 4];
            p[0] = magenta ? 255 : 0;
            p[1] = 0;
            p[2] = magenta ? 255 : 0;
            p[3] = 255;
        }
    return img;
}

LoadedTexture loadTextureOrPlaceholder(const std::filesystem::path& file) {
    auto img = readTextureRgba8(file);
    if (img)
        return {std::move(*img), false, {}};
    return {placeholderTexture(), true, img.error().describe() + "; drawn as a magenta checkerboard"};
}

} // namespace lpv::importers
