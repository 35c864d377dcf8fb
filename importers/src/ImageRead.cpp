#include "lpv/importers/ImageIO.h"

#include "ImageOpen.h"
#include "StripDecode.h"
#include "lpv/scene/FileRead.h"

namespace lpv::importers {

// Every reader opens through openWithinBudget (the header weighed before
// OpenImageIO sees the file) and catches at its boundary what OpenImageIO
// throws while decoding (issue #42: std::length_error and std::bad_alloc
// aborted `lpv compare` and `lpv merge`).

using scene::ErrorCode;
using scene::makeError;

scene::Expected<FloatChannels> readImageChannels(const std::filesystem::path& file) {
    auto opened = openWithinBudget(file, false);
    if (!opened)
        return std::unexpected(opened.error());
    try {
        OIIO::ImageInput& in = *opened->input;
        const OIIO::ImageSpec& spec = in.spec();
        if (spec.nchannels > kMaxImageChannels)
            return makeError(ErrorCode::OutOfRange, file.string(), "header",
                             "claims " + std::to_string(spec.nchannels) + " channels; the limit is " +
                                 std::to_string(kMaxImageChannels));
        // Half channels double as floats: the file's budget does not bound ours.
        const std::uint64_t bytes = std::uint64_t(spec.width) * std::uint64_t(spec.height) *
                                    std::uint64_t(spec.nchannels) * sizeof(float);
        if (bytes > kMaxDecodedImageBytes)
            return makeError(ErrorCode::OutOfRange, file.string(), "header",
                             "reading " + std::to_string(spec.width) + "x" + std::to_string(spec.height) +
                                 " pixels of " + std::to_string(spec.nchannels) +
                                 " channels as 32-bit floats takes " + scene::formatBytes(bytes) +
                                 "; the budget is " + scene::formatBytes(kMaxDecodedImageBytes) +
                                 " per image");
        FloatChannels img;
        img.width = spec.width;
        img.height = spec.height;
        for (int c = 0; c < spec.nchannels; ++c)
            img.names.push_back(spec.channel_name(c));
        img.pixels.resize(std::size_t(img.width) * std::size_t(img.height) * img.names.size());
        if (!in.read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, img.pixels.data()))
            return makeError(ErrorCode::CorruptAsset, file.string(), "",
                             "could not decode: " + in.geterror());
        for (const OIIO::ParamValue& p : spec.extra_attribs)
            if (p.type() == OIIO::TypeDesc::STRING)
                img.attributes.emplace_back(p.name().string(), p.get_string());
        return img;
    } catch (...) {
        return libraryThrew(file);
    }
}

scene::Expected<Image8> readImage8(const std::filesystem::path& file) {
    // Textures are used with straight alpha: keep the file's values as they are.
    auto opened = openWithinBudget(file, true);
    if (!opened)
        return std::unexpected(opened.error());
    try {
        OIIO::ImageInput& in = *opened->input;
        const OIIO::ImageSpec& spec = in.spec();
        if (spec.nchannels > 4)
            return makeError(ErrorCode::OutOfRange, file.string(), "header",
                             "claims " + std::to_string(spec.nchannels) +
                                 " channels; an 8-bit image has at most 4");
        Image8 img;
        img.width = spec.width;
        img.height = spec.height;
        img.channels = spec.nchannels;
        img.pixels.resize(std::size_t(img.width) * std::size_t(img.height) * std::size_t(img.channels));
        if (!in.read_image(0, 0, 0, img.channels, OIIO::TypeDesc::UINT8, img.pixels.data()))
            return makeError(ErrorCode::CorruptAsset, file.string(), "",
                             "could not decode: " + in.geterror());
        return img;
    } catch (...) {
        return libraryThrew(file);
    }
}

scene::Expected<Image8> readTextureRgba8(const std::filesystem::path& file, int shrink) {
    auto opened = openWithinBudget(file, true);
    if (!opened)
        return std::unexpected(opened.error());
    try {
        return readRgba8InStrips(*opened->input, file, shrink);
    } catch (...) {
        return libraryThrew(file);
    }
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

LoadedTexture loadTextureOrPlaceholder(const std::filesystem::path& file, int shrink) {
    auto img = readTextureRgba8(file, shrink);
    if (img)
        return {std::move(*img), false, {}};
    return {placeholderTexture(), true, img.error().describe() + "; drawn as a magenta checkerboard"};
}

} // namespace lpv::importers
