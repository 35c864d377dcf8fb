// fuzz_image's generated seeds (ImageSeeds.h). The valid images are written
// by our own writers (ImageIO.h, OpenImageIO), except the GIF, which is
// written byte by byte (35 bytes, one pixel) since a GIF writer is optional
// in OpenImageIO builds. The bombs are those files with their header
// patched: the decoders must refuse them, or our budget before them.
#include "ImageSeeds.h"

#include "lpv/importers/ImageIO.h"

#include <array>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace lpv::fuzz {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const std::string& what) {
    std::fprintf(stderr, "fuzz_seeds: %s\n", what.c_str());
    std::exit(1);
}

std::string readBytes(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

void writeBytes(const fs::path& file, std::string_view bytes) {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), std::streamsize(bytes.size()));
    if (!out)
        fail("cannot write " + file.string());
}

void putLE(std::string& bytes, std::size_t at, std::uint32_t value, int size) {
    for (int i = 0; i < size; ++i)
        bytes.at(at + std::size_t(i)) = char((value >> (8 * i)) & 0xff);
}
void putBE(std::string& bytes, std::size_t at, std::uint32_t value, int size) {
    for (int i = 0; i < size; ++i)
        bytes.at(at + std::size_t(i)) = char((value >> (8 * (size - 1 - i))) & 0xff);
}

// PNG's chunk checksum (CRC-32, ISO 3309), so a patched IHDR still passes
// libpng's check and reaches the size logic behind it.
std::uint32_t crc32(std::string_view bytes) {
    std::uint32_t crc = 0xffffffffu;
    for (const char c : bytes) {
        crc ^= std::uint8_t(c);
        for (int k = 0; k < 8; ++k)
            crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

// A gradient with some alpha, so every channel carries information.
importers::Image8 gradient(int side, int channels) {
    importers::Image8 img;
    img.width = img.height = side;
    img.channels = channels;
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x)
            for (int c = 0; c < channels; ++c)
                img.pixels.push_back(std::uint8_t((x * 32 + y * 8 + c * 64) & 0xff));
    return img;
}

// One pixel, a two-colour global palette, LZW codes clear, 0, end.
std::string gifOfScreen(std::uint16_t width, std::uint16_t height) {
    std::string gif("GIF89a", 6);
    gif += std::string("\0\0\0\0\x80\0\0", 7); // screen size, global palette of 2, background, aspect
    putLE(gif, 6, width, 2);
    putLE(gif, 8, height, 2);
    gif += std::string("\xff\xff\xff\0\0\0", 6);
    gif += std::string("\x2c\0\0\0\0\x01\0\x01\0\0", 10); // image at 0,0, 1x1
    gif += std::string("\x02\x02\x44\x01\0\x3b", 6);      // LZW size 2, one block, trailer
    return gif;
}

void write(const fs::path& file, const importers::Image8& image) {
    if (auto ok = importers::writeImage(file, image); !ok)
        fail(ok.error().describe());
}

// Sets an EXR header attribute of type box2i (dataWindow, displayWindow).
void patchExrBox(std::string& exr, std::string_view name, std::uint32_t xMax, std::uint32_t yMax) {
    const std::string key = std::string(name) + std::string("\0box2i\0", 7);
    const std::size_t at = exr.find(key);
    if (at == std::string::npos)
        fail("no " + std::string(name) + " in the EXR seed");
    const std::size_t box = at + key.size() + 4; // past the attribute's size
    putLE(exr, box + 8, xMax, 4);
    putLE(exr, box + 12, yMax, 4);
}

} // namespace

std::size_t writeImageSeeds(const fs::path& out) {
    std::error_code ec;
    fs::create_directories(out, ec);
    if (ec)
        fail("cannot create " + out.string() + ": " + ec.message());
    std::size_t count = 0;

    // Valid images, every format a texture or reference arrives in.
    write(out / "grey-8.png", gradient(8, 1));
    write(out / "rgb-8.png", gradient(8, 3));
    write(out / "rgba-8.png", gradient(8, 4));
    write(out / "rgb-8.jpg", gradient(8, 3));
    write(out / "rgb-8.bmp", gradient(8, 3));
    write(out / "rgba-8.tga", gradient(8, 4));
    writeBytes(out / "one-pixel.gif", gifOfScreen(1, 1));
    count += 7;
    std::vector<float> rgba(8 * 8 * 4);
    for (std::size_t i = 0; i < rgba.size(); ++i)
        rgba[i] = float(i % 17) * 0.25f;
    if (auto ok = importers::writeImageFloat(out / "rgba-8.exr", 8, 8, 4, rgba); !ok)
        fail(ok.error().describe());
    importers::FloatChannels layers; // the reference's layout: beauty and named layers
    layers.width = layers.height = 4;
    layers.names = {"R", "G", "B", "indirect.R", "indirect.G", "indirect.B", "samples"};
    layers.pixels.assign(4 * 4 * layers.names.size(), 0.5f);
    if (auto ok = importers::writeImageChannels(out / "layers-4.exr", layers, {{"lpv:scene", "fuzz"}}); !ok)
        fail(ok.error().describe());
    importers::FloatChannels many = layers; // 64 channels, the most readImageChannels reads
    many.names.clear();
    for (int c = 0; c < 64; ++c)
        many.names.push_back("c" + std::to_string(c));
    many.pixels.assign(4 * 4 * 64, 1.0f);
    if (auto ok = importers::writeImageChannels(out / "channels-64.exr", many); !ok)
        fail(ok.error().describe());
    count += 3;

    // The bombs: the same files, headers claiming what the bytes cannot hold.
    writeBytes(out / "bomb-screen-65535.gif", gifOfScreen(65535, 65535));
    writeBytes(out / "bomb-screen-23000.gif", gifOfScreen(23000, 23000));

    std::string png = readBytes(out / "rgba-8.png");
    putBE(png, 16, 16384, 4); // IHDR width and height
    putBE(png, 20, 16384, 4);
    putBE(png, 29, crc32(std::string_view(png).substr(12, 17)), 4);
    writeBytes(out / "bomb-16384.png", png);

    std::string bmp = readBytes(out / "rgb-8.bmp");
    putLE(bmp, 18, 16384, 4);
    putLE(bmp, 22, 16384, 4);
    writeBytes(out / "bomb-16384.bmp", bmp);

    std::string tga = readBytes(out / "rgba-8.tga");
    putLE(tga, 12, 65535, 2);
    putLE(tga, 14, 65535, 2);
    writeBytes(out / "bomb-65535.tga", tga);

    std::string jpg = readBytes(out / "rgb-8.jpg");
    for (const std::string_view sof : {std::string_view("\xff\xc0", 2), std::string_view("\xff\xc2", 2)})
        if (const std::size_t at = jpg.find(sof); at != std::string::npos) {
            putBE(jpg, at + 5, 16384, 2); // height, then width
            putBE(jpg, at + 7, 16384, 2);
            writeBytes(out / "bomb-16384.jpg", jpg);
            break;
        }

    for (const auto& [from, to] : {std::pair{"rgba-8.exr", "bomb-rgba-16384.exr"},
                                   std::pair{"channels-64.exr", "bomb-channels-64-16384.exr"}}) {
        std::string exr = readBytes(out / from);
        patchExrBox(exr, "dataWindow", 16383, 16383);
        patchExrBox(exr, "displayWindow", 16383, 16383);
        writeBytes(out / to, exr);
    }
    count += 8;
    return count;
}

} // namespace lpv::fuzz
