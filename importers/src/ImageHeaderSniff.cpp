#include "ImageHeaderSniff.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

namespace lpv::importers {
namespace {

namespace fs = std::filesystem;
using scene::ErrorCode;
using scene::makeError;

std::uint32_t le16(const unsigned char* p) {
    return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8;
}
std::uint32_t le32(const unsigned char* p) {
    return le16(p) | le16(p + 2) << 16;
}
std::uint32_t be16(const unsigned char* p) {
    return std::uint32_t(p[0]) << 8 | std::uint32_t(p[1]);
}
std::uint32_t be32(const unsigned char* p) {
    return be16(p) << 16 | be16(p + 2);
}

// Products of header fields saturate instead of wrapping: a header may claim
// 2^32 x 2^32 pixels, and a wrapped product would pass the budget.
std::uint64_t mulSat(std::uint64_t a, std::uint64_t b) {
    std::uint64_t r = 0;
    return __builtin_mul_overflow(a, b, &r) ? UINT64_MAX : r;
}

std::unexpected<scene::Error> unreadable(const fs::path& file, const std::string& format,
                                         const std::string& why) {
    return makeError(ErrorCode::CorruptAsset, file.string(), "header", format + " header " + why);
}

// Fills the derived sizes from the fields every reader sets.
ImageHeader claim(std::string format, std::string compression, std::int64_t w, std::int64_t h, int channels,
                  int bytesPerSample, std::uint64_t storedBytes, double extraDecodedPerPixel,
                  double maxRatio) {
    ImageHeader c;
    c.format = std::move(format);
    c.compression = std::move(compression);
    c.width = w;
    c.height = h;
    c.channels = channels;
    c.bytesPerSample = bytesPerSample;
    c.storedBytes = storedBytes;
    const double pixels = double(std::max<std::int64_t>(w, 0)) * double(std::max<std::int64_t>(h, 0));
    // Converting a double at or beyond 2^64 to an integer is undefined: saturate first.
    const double decoded = pixels * (double(channels) * bytesPerSample + extraDecodedPerPixel);
    c.decodedBytes = decoded >= 18446744073709551615.0 ? UINT64_MAX : std::uint64_t(decoded);
    c.maxRatio = maxRatio;
    return c;
}

std::uint64_t rowBytes(std::int64_t width, std::uint64_t bitsPerPixel) {
    return (std::uint64_t(std::max<std::int64_t>(width, 0)) * bitsPerPixel + 7) / 8;
}

// GIF: the logical screen (bytes 6..9, little-endian) is the canvas
// OpenImageIO allocates as RGBA inside open(), whatever the frames hold.
ImageHeader gif(const unsigned char* b) {
    const std::int64_t w = le16(b + 6), h = le16(b + 8);
    return claim("gif", "lzw", w, h, 4, 1, std::uint64_t(w) * std::uint64_t(h), 0.0, kLzwMaxRatio); // < 2^32
}

// PNG: IHDR is the first chunk. Stored bytes are the deflate stream's
// output (a filter byte per row, then the packed samples), which deflate
// cannot make more than 1032 times smaller.
scene::Expected<ImageHeader> png(const fs::path& file, const unsigned char* b, std::size_t n) {
    if (n < 29 || std::memcmp(b + 12, "IHDR", 4) != 0)
        return unreadable(file, "PNG", "has no IHDR chunk first");
    const std::int64_t w = be32(b + 16), h = be32(b + 20);
    const int bits = b[24], type = b[25];
    int stored = 0, decoded = 0; // channels
    switch (type) {
    case 0:
        stored = 1, decoded = 1;
        break;
    case 2:
        stored = 3, decoded = 3;
        break;
    case 3:
        stored = 1, decoded = 4;
        break; // palette indices, expanded to RGB(A)
    case 4:
        stored = 2, decoded = 2;
        break;
    case 6:
        stored = 4, decoded = 4;
        break;
    default:
        return unreadable(file, "PNG",
                          "has colour type " + std::to_string(type) + ", which PNG does not define");
    }
    if (bits != 1 && bits != 2 && bits != 4 && bits != 8 && bits != 16)
        return unreadable(file, "PNG",
                          "has bit depth " + std::to_string(bits) + ", which PNG does not define");
    const std::uint64_t storedBytes =
        mulSat(std::uint64_t(h), 1 + rowBytes(w, std::uint64_t(stored) * std::uint64_t(bits)));
    return claim("png", "deflate", w, h, decoded, bits == 16 ? 2 : 1, storedBytes, 0.0, kDeflateMaxRatio);
}

// JPEG: walk the marker segments to the first SOFn. A progressive or
// multi-scan frame makes libjpeg keep every DCT coefficient of the image
// (2 bytes a sample) from jpeg_start_decompress() on: that counts as decoded.
scene::Expected<ImageHeader> jpeg(const fs::path& file, std::ifstream& in) {
    in.clear();
    in.seekg(2);
    for (int segment = 0; segment < 4096; ++segment) {
        int c = in.get();
        while (c != EOF && c != 0xFF)
            c = in.get(); // bytes between segments: tolerated, as libjpeg does with a warning
        while (c == 0xFF)
            c = in.get();
        if (c == EOF)
            break;
        const int marker = c;
        if (marker == 0x01 || (marker >= 0xD0 && marker <= 0xD8))
            continue; // no length follows
        if (marker == 0xD9 || marker == 0xDA)
            return unreadable(file, "JPEG", "has no frame (SOF) before its image data");
        unsigned char len[2];
        if (!in.read(reinterpret_cast<char*>(len), 2))
            break;
        const std::uint32_t length = be16(len);
        if (length < 2)
            return unreadable(file, "JPEG", "has a segment of length " + std::to_string(length));
        const bool sof =
            marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC;
        if (!sof) {
            in.seekg(std::streamoff(length - 2), std::ios::cur);
            continue;
        }
        unsigned char f[6];
        if (length < 8 || !in.read(reinterpret_cast<char*>(f), 6))
            break;
        const int precision = f[0], components = f[5];
        const std::int64_t h = be16(f + 1), w = be16(f + 3);
        if (components < 1 || components > 4)
            return unreadable(file, "JPEG", "has " + std::to_string(components) + " components");
        const int bytes = precision > 8 ? 2 : 1;
        // SOF2/6/10/14 are progressive; SOF1..3 with several scans buffer too,
        // but only progressive frames can be told from the marker alone.
        const bool progressive = (marker & 0x03) == 0x02;
        return claim("jpeg", progressive ? "progressive DCT" : "DCT", w, h, components, bytes,
                     std::uint64_t(w) * std::uint64_t(h) * std::uint64_t(components) * std::uint64_t(bytes),
                     progressive ? 2.0 * components : 0.0, kDeflateMaxRatio);
    }
    return unreadable(file, "JPEG", "ends before its frame (SOF) header");
}

// BMP: the info header's size tells OS/2 (12 bytes, 16-bit sides) from
// Windows ones (32-bit sides, a negative height meaning top-down rows).
scene::Expected<ImageHeader> bmp(const fs::path& file, const unsigned char* b, std::size_t n) {
    if (n < 26)
        return unreadable(file, "BMP", "is truncated");
    const std::uint32_t infoSize = le32(b + 14);
    std::int64_t w = 0, h = 0;
    std::uint32_t bpp = 0, compression = 0;
    if (infoSize == 12) {
        w = le16(b + 18), h = le16(b + 20), bpp = le16(b + 24);
    } else if (infoSize >= 16 && n >= 34) {
        w = std::int32_t(le32(b + 18)), h = std::int32_t(le32(b + 22)), bpp = le16(b + 28);
        compression = infoSize >= 20 ? le32(b + 30) : 0;
    } else {
        return unreadable(file, "BMP", "has an info header of " + std::to_string(infoSize) + " bytes");
    }
    h = h < 0 ? -h : h;
    const bool rle = compression == 1 || compression == 2;
    const bool uncompressed = compression == 0 || compression == 3 || compression == 6;
    const std::uint64_t stored = mulSat(std::uint64_t(h), (rowBytes(w, bpp) + 3) / 4 * 4);
    // OpenImageIO decodes to RGB (RGBA from 32 bits) and unpacks RLE into a
    // byte per pixel first.
    return claim("bmp",
                 rle            ? "rle"
                 : uncompressed ? "none"
                                : "embedded",
                 w, h, bpp == 32 ? 4 : 3, 1, stored, rle ? 1.0 : 0.0,
                 uncompressed ? kUncompressedMaxRatio : kDeflateMaxRatio);
}

// TGA has no signature: it is recognised by its extension (as OpenImageIO
// does) and an image type TGA defines.
std::optional<ImageHeader> tga(const unsigned char* b, std::size_t n) {
    if (n < 18)
        return std::nullopt;
    const int type = b[2], bpp = b[16];
    if (!(type == 1 || type == 2 || type == 3 || type == 9 || type == 10 || type == 11) || bpp == 0 ||
        bpp > 32)
        return std::nullopt;
    const std::int64_t w = le16(b + 12), h = le16(b + 14);
    const bool rle = type >= 9;
    return claim("tga", rle ? "rle" : "none", w, h, 4, 1,
                 std::uint64_t(w) * std::uint64_t(h) * ((bpp + 7) / 8), 0.0,
                 rle ? kDeflateMaxRatio : kUncompressedMaxRatio);
}

double exrMaxRatio(int compression) {
    switch (compression) {
    case 0:
        return kUncompressedMaxRatio;
    case 1:
        return kExrRleMaxRatio;
    case 5:
        return kPxr24MaxRatio;
    case 8:
    case 9:
        return kDwaMaxRatio;
    default:
        return kDeflateMaxRatio; // ZIPS, ZIP, PIZ, B44, B44A (B44 cannot pass 32:3)
    }
}

const char* exrCompressionName(int compression) {
    static constexpr std::array<const char*, 10> kNames = {"none",  "rle", "zips", "zip",  "piz",
                                                           "pxr24", "b44", "b44a", "dwaa", "dwab"};
    return compression >= 0 && compression < int(kNames.size()) ? kNames[std::size_t(compression)]
                                                                : "unknown";
}

// The bytes OpenEXR 3.1 reads for the value of an attribute of a known,
// fixed-size type, whatever size the attribute declares (its typed readers
// ignore the declared size); -1 for the types whose value it reads at the
// declared size (strings, vectors, manifests, and types it does not know,
// which it keeps as "opaque" bytes allocated at that size).
std::int64_t exrFixedValueBytes(const std::string& type) {
    static const std::pair<const char*, int> kFixed[] = {
        {"box2i", 16},      {"box2f", 16},   {"chromaticities", 32},
        {"compression", 1}, {"double", 8},   {"envmap", 1},
        {"float", 4},       {"int", 4},      {"keycode", 28},
        {"lineOrder", 1},   {"m33f", 36},    {"m33d", 72},
        {"m44f", 64},       {"m44d", 128},   {"rational", 8},
        {"tiledesc", 9},    {"timecode", 8}, {"v2i", 8},
        {"v2f", 8},         {"v2d", 16},     {"v3i", 12},
        {"v3f", 12},        {"v3d", 24},     {"deepImageState", 1}};
    for (const auto& [name, bytes] : kFixed)
        if (type == name)
            return bytes;
    return -1;
}

// OpenEXR: attributes (name, type, size, value) until an empty name, walked
// as OpenEXR walks them (fixed-size types at their own size, a channel list
// up to its empty name, a preview at its width x height), so that every
// allocation OpenEXR makes while opening is weighed against the bytes left:
// it allocates strings, vectors and attributes of unknown types at the size
// their header claims, and a preview at width x height x 4. The first
// part's channels, compression and data window make the claim.
scene::Expected<ImageHeader> exr(const fs::path& file, std::ifstream& in) {
    in.clear();
    in.seekg(0, std::ios::end);
    const std::int64_t fileBytes = std::int64_t(in.tellg());
    in.seekg(5);
    const bool multiPart = (in.get() & 0x10) != 0; // version flags, bit 12
    in.seekg(8);
    const auto left = [&] { return fileBytes - std::int64_t(in.tellg()); };
    auto readName = [&](std::string& out) {
        out.clear();
        for (int c = in.get(); c != EOF; c = in.get()) {
            if (c == 0)
                return true;
            if (out.size() >= 255)
                return false;
            out.push_back(char(c));
        }
        return false;
    };
    const auto tooLarge = [&](const std::string& name, std::int64_t bytes) {
        return unreadable(file, "OpenEXR",
                          "gives attribute '" + name + "' " + std::to_string(bytes) +
                              " bytes, more than the rest of the file holds");
    };
    int channels = 0, compression = -1;
    std::uint64_t bytesPerPixel = 0;
    std::int64_t w = -1, h = -1;
    std::string name, type;
    // One header; `first` keeps what the claim needs.
    auto walkHeader = [&](bool first) -> scene::Expected<void> {
        for (int attribute = 0; attribute < 4096; ++attribute) {
            if (!readName(name))
                return unreadable(file, "OpenEXR", "is truncated in its attributes");
            if (name.empty())
                return {};
            unsigned char sizeBytes[4];
            if (!readName(type) || !in.read(reinterpret_cast<char*>(sizeBytes), 4))
                return unreadable(file, "OpenEXR", "is truncated in attribute '" + name + "'");
            const std::int64_t size = std::int32_t(le32(sizeBytes));
            if (size < 0)
                return unreadable(file, "OpenEXR", "gives attribute '" + name + "' a negative size");
            if (type == "chlist") {
                // name, then type, pLinear, reserved, xSampling, ySampling: 16 bytes
                for (std::string channel;;) {
                    if (!readName(channel))
                        return unreadable(file, "OpenEXR", "is truncated in its channel list");
                    if (channel.empty())
                        break;
                    unsigned char entry[16];
                    if (!in.read(reinterpret_cast<char*>(entry), 16))
                        return unreadable(file, "OpenEXR", "is truncated in its channel list");
                    if (first && name == "channels") {
                        bytesPerPixel += le32(entry) == 1 ? 2 : 4; // HALF, else UINT or FLOAT
                        ++channels;
                    }
                }
            } else if (type == "preview") {
                unsigned char wh[8];
                if (!in.read(reinterpret_cast<char*>(wh), 8))
                    return unreadable(file, "OpenEXR", "is truncated in attribute '" + name + "'");
                const std::int64_t pixelBytes = std::int64_t(le32(wh)) * std::int64_t(le32(wh + 4)) * 4;
                if (pixelBytes > left())
                    return tooLarge(name, pixelBytes);
                in.seekg(pixelBytes, std::ios::cur);
            } else if (const std::int64_t fixed = exrFixedValueBytes(type); fixed >= 0) {
                unsigned char value[128];
                if (!in.read(reinterpret_cast<char*>(value), fixed))
                    return unreadable(file, "OpenEXR", "is truncated in attribute '" + name + "'");
                if (first && name == "compression")
                    compression = value[0];
                if (first && name == "dataWindow" && type == "box2i") {
                    const auto at = [&](int i) { return std::int64_t(std::int32_t(le32(value + 4 * i))); };
                    w = at(2) - at(0) + 1;
                    h = at(3) - at(1) + 1;
                }
            } else {
                if (size > left())
                    return tooLarge(name, size);
                in.seekg(size, std::ios::cur);
            }
            if (!in)
                return unreadable(file, "OpenEXR", "is truncated in attribute '" + name + "'");
        }
        return unreadable(file, "OpenEXR", "has more than 4096 attributes in one header");
    };
    if (auto walked = walkHeader(true); !walked)
        return std::unexpected(walked.error());
    if (channels == 0 || compression < 0 || w < 0 || h < 0)
        return unreadable(file, "OpenEXR", "lacks its channels, compression or data window");
    // A multi-part file's further headers follow, up to an empty one; OpenEXR
    // reads them all when it opens the file, so they are walked too.
    for (int part = 1; multiPart && in.peek() != 0 && in.peek() != EOF; ++part) {
        if (part >= 4096)
            return unreadable(file, "OpenEXR", "has more than 4096 parts");
        if (auto walked = walkHeader(false); !walked)
            return std::unexpected(walked.error());
    }
    ImageHeader c = claim("openexr", exrCompressionName(compression), w, h, channels, 4,
                          mulSat(mulSat(std::uint64_t(w), std::uint64_t(h)), bytesPerPixel), 0.0,
                          exrMaxRatio(compression));
    // In the file's own sample format: half channels decode to 2 bytes each.
    c.bytesPerSample = int(bytesPerPixel / std::uint64_t(channels));
    c.decodedBytes = c.storedBytes;
    return c;
}

std::string lowerExtension(const fs::path& file) {
    std::string ext = file.extension().string();
    for (char& ch : ext)
        ch = char(std::tolower(static_cast<unsigned char>(ch)));
    return ext;
}

} // namespace

scene::Expected<std::optional<ImageHeader>> sniffImageHeader(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in)
        return std::optional<ImageHeader>{};
    unsigned char b[64] = {};
    in.read(reinterpret_cast<char*>(b), sizeof b);
    const std::size_t n = std::size_t(in.gcount());
    auto is = [&](const char* magic, std::size_t len) { return n >= len && std::memcmp(b, magic, len) == 0; };
    auto wrap = [](scene::Expected<ImageHeader> h) -> scene::Expected<std::optional<ImageHeader>> {
        if (!h)
            return std::unexpected(h.error());
        return std::optional<ImageHeader>(std::move(*h));
    };
    // giflib accepts any file that starts with "GIF" (it does not check the
    // version), so every such file is weighed as one.
    if (is("GIF", 3)) {
        if (n < 10)
            return unreadable(file, "GIF", "is truncated");
        return std::optional<ImageHeader>(gif(b));
    }
    if (is("\x89PNG\r\n\x1a\n", 8))
        return wrap(png(file, b, n));
    if (is("\xFF\xD8\xFF", 3))
        return wrap(jpeg(file, in));
    if (is("BM", 2))
        return wrap(bmp(file, b, n));
    if (is("\x76\x2f\x31\x01", 4))
        return wrap(exr(file, in));
    if (const std::string ext = lowerExtension(file); ext == ".tga" || ext == ".tpic")
        return tga(b, n);
    return std::optional<ImageHeader>{};
}

} // namespace lpv::importers
