#include "lpv/importers/ImageBudget.h"

#include "ImageHeaderSniff.h"
#include "ImageOpen.h"
#include "lpv/importers/ImageIO.h"
#include "lpv/scene/FileRead.h"

#include <cmath>

namespace lpv::importers {

using scene::ErrorCode;
using scene::makeError;

namespace {

std::string plural(std::int64_t n, const char* word) {
    return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
}

// "65535x65535 pixels, 4 channels of 1 byte (gif, lzw)": the claim, as every message quotes it.
std::string describeClaim(const ImageHeader& h) {
    return std::to_string(h.width) + "x" + std::to_string(h.height) + " pixels, " +
           plural(h.channels, "channel") + " of " + plural(h.bytesPerSample, "byte") + " (" + h.format +
           ", " + h.compression + ")";
}

std::string ratioText(double ratio) {
    return std::to_string(std::llround(ratio)) + ":1";
}

} // namespace

scene::Expected<void> checkImageBudget(const std::filesystem::path& file, const ImageHeader& h,
                                       std::uint64_t fileBytes) {
    const std::string where = file.string();
    if (h.width <= 0 || h.height <= 0 || h.channels <= 0)
        return makeError(ErrorCode::OutOfRange, where, "header",
                         "claims an empty image (" + describeClaim(h) + ")");
    if (h.depth != 1)
        return makeError(ErrorCode::OutOfRange, where, "header",
                         "claims a volume of " + std::to_string(h.depth) +
                             " slices; only flat images are read");
    // Memory first: it is what a lying header costs, and what the user can act on.
    if (h.decodedBytes > kMaxDecodedImageBytes)
        return makeError(ErrorCode::OutOfRange, where, "header",
                         "claims " + describeClaim(h) + ": " + scene::formatBytes(h.decodedBytes) +
                             " to decode; the budget is " + scene::formatBytes(kMaxDecodedImageBytes) +
                             " per image");
    if (h.width > kMaxImageSide || h.height > kMaxImageSide)
        return makeError(ErrorCode::OutOfRange, where, "header",
                         "claims " + describeClaim(h) + "; the limit is " + std::to_string(kMaxImageSide) +
                             " pixels on a side");
    // Compression has a ceiling: a claim far beyond it cannot be true, and
    // believing it would cost the whole canvas before the decoder finds out.
    const double ratio = double(h.storedBytes) / double(std::max<std::uint64_t>(fileBytes, 1));
    if (h.storedBytes > kRatioCheckFromBytes && ratio > h.maxRatio) {
        const std::string ceiling = h.maxRatio <= kUncompressedMaxRatio
                                        ? "an uncompressed file can hold"
                                        : h.compression + " compression can expand";
        return makeError(ErrorCode::OutOfRange, where, "header",
                         "claims " + describeClaim(h) + ": " + scene::formatBytes(h.storedBytes) +
                             " of samples in a file of " + scene::formatBytes(fileBytes) + " (" +
                             ratioText(ratio) + "), more than " + ceiling + " (" + ratioText(h.maxRatio) +
                             ")");
    }
    return {};
}

scene::Expected<ImageHeader> readImageHeader(const std::filesystem::path& file) {
    auto sniffed = sniffImageHeader(file);
    if (!sniffed)
        return std::unexpected(sniffed.error());
    if (*sniffed) {
        const auto size = fileSize(file);
        if (!size)
            return std::unexpected(size.error());
        if (auto ok = checkImageBudget(file, **sniffed, *size); !ok)
            return std::unexpected(ok.error());
        return **sniffed;
    }
    // Not a format we read ourselves: OpenImageIO's header, through the same checks.
    auto opened = openWithinBudget(file, false);
    if (!opened)
        return std::unexpected(opened.error());
    return opened->header;
}

} // namespace lpv::importers
