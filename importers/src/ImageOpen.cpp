#include "ImageOpen.h"

#include "ImageHeaderSniff.h"
#include "lpv/scene/FileRead.h"

#include <exception>
#include <new>
#include <stdexcept>
#include <system_error>

namespace lpv::importers {

using scene::ErrorCode;
using scene::makeError;

namespace {

ImageHeader headerFromSpec(const OIIO::ImageSpec& spec, const std::string& format,
                           const ImageHeader* sniffed) {
    ImageHeader h;
    h.format = format;
    h.width = spec.width;
    h.height = spec.height;
    h.depth = spec.depth;
    h.channels = spec.nchannels;
    const std::uint64_t pixelBytes = spec.nchannels > 0 ? spec.pixel_bytes(true) : 0;
    h.bytesPerSample = spec.nchannels > 0 ? int(pixelBytes / std::uint64_t(spec.nchannels)) : 1;
    const double pixels =
        double(std::max(spec.width, 0)) * double(std::max(spec.height, 0)) * double(std::max(spec.depth, 1));
    h.storedBytes = h.decodedBytes = std::uint64_t(pixels * double(pixelBytes));
    // The ratio rule weighs the samples as the file stores them (palette
    // indices, not the RGB they expand to): our reading knows those.
    if (sniffed)
        h.storedBytes = sniffed->storedBytes;
    // Our reading of the compression is the better one where we have it;
    // elsewhere LZW's ceiling, the highest of the common lossless codecs.
    h.compression =
        sniffed ? sniffed->compression : std::string(spec.get_string_attribute("compression", "unknown"));
    h.maxRatio = sniffed ? sniffed->maxRatio : kLzwMaxRatio;
    return h;
}

} // namespace

scene::Expected<std::uint64_t> fileSize(const std::filesystem::path& file) {
    if (const auto why = scene::notARegularFile(file))
        return makeError(*why == "no such file" ? ErrorCode::FileNotFound : ErrorCode::IoError, file.string(),
                         "", *why);
    std::error_code ec;
    const std::uintmax_t size = std::filesystem::file_size(file, ec);
    if (ec)
        return makeError(ErrorCode::IoError, file.string(), "", "cannot read its size: " + ec.message());
    return std::uint64_t(size);
}

std::unexpected<scene::Error> libraryThrew(const std::filesystem::path& file) {
    std::string what = "an unknown exception";
    try {
        throw;
    } catch (const std::bad_alloc&) {
        what = "out of memory (std::bad_alloc)";
    } catch (const std::length_error& e) {
        what = std::string("std::length_error: ") + e.what();
    } catch (const std::exception& e) {
        what = e.what();
    } catch (...) {
    }
    return makeError(ErrorCode::CorruptAsset, file.string(), "", "could not decode: " + what);
}

scene::Expected<OpenedImage> openWithinBudget(const std::filesystem::path& file, bool straightAlpha) {
    const auto size = fileSize(file);
    if (!size)
        return std::unexpected(size.error());
    const auto sniffed = sniffImageHeader(file);
    if (!sniffed)
        return std::unexpected(sniffed.error());
    if (*sniffed)
        if (auto ok = checkImageBudget(file, **sniffed, *size); !ok)
            return std::unexpected(ok.error());
    try {
        OIIO::ImageSpec config;
        if (straightAlpha)
            config.attribute("oiio:UnassociatedAlpha", 1);
        OpenedImage opened;
        opened.input = OIIO::ImageInput::open(file.string(), &config);
        if (!opened.input)
            return makeError(ErrorCode::UnknownFormat, file.string(), "",
                             "not a readable image: " + OIIO::geterror());
        const OIIO::ImageSpec& spec = opened.input->spec();
        if (spec.deep)
            return makeError(ErrorCode::UnknownFormat, file.string(), "header",
                             "deep images (several samples a pixel) are not read");
        const ImageHeader* claim = *sniffed ? &**sniffed : nullptr;
        opened.header = headerFromSpec(spec, claim ? claim->format : opened.input->format_name(), claim);
        if (auto ok = checkImageBudget(file, opened.header, *size); !ok)
            return std::unexpected(ok.error());
        return opened;
    } catch (...) {
        return libraryThrew(file);
    }
}

} // namespace lpv::importers
