// Texture files through OpenImageIO: the formats and oddities the shared
// scenes contain, and the placeholder for what cannot be read.
#include "lpv/importers/ImageIO.h"
#include "TestPaths.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

using namespace lpv;
namespace fs = std::filesystem;

namespace {

fs::path scenes() { return fs::path(test::kSharedScenesDir); }

importers::Image8 readOk(const fs::path& file) {
    auto r = importers::readTextureRgba8(file);
    EXPECT_TRUE(r.has_value()) << (r ? "" : r.error().describe());
    return r ? std::move(*r) : importers::Image8{};
}

bool isGrey(const importers::Image8& img) {
    for (std::size_t i = 0; i < img.pixels.size(); i += 4)
        if (img.pixels[i] != img.pixels[i + 1] || img.pixels[i] != img.pixels[i + 2])
            return false;
    return true;
}

} // namespace

TEST(TextureIo, PalettisedBmpIsExpandedToColour) {
    // 4ds/maps/11.bmp: 512x512, 8-bit palettised (SOURCE.md).
    const auto img = readOk(scenes() / "4ds/maps/11.bmp");
    EXPECT_EQ(img.width, 512);
    EXPECT_EQ(img.height, 512);
    EXPECT_EQ(img.channels, 4);
    EXPECT_FALSE(isGrey(img)) << "palette indices were looked up, not used as grey levels";
}

TEST(TextureIo, NonSquareAndTwentyFourBitBmps) {
    const auto kura = readOk(scenes() / "4ds/maps/^kura02.bmp"); // 256x1024, 8-bit
    EXPECT_EQ(kura.width, 256);
    EXPECT_EQ(kura.height, 1024);
    const auto sky = readOk(scenes() / "4ds/maps/SKY 3 1.BMP"); // 24-bit, spaces in the name
    EXPECT_EQ(sky.width, 256);
    EXPECT_EQ(sky.pixels[3], 255) << "opaque";
}

TEST(TextureIo, ProgressiveJpegsColourAndGrey) {
    const auto relief = readOk(scenes() / "sponza/reljef.JPG"); // progressive RGB, 512x437
    EXPECT_EQ(relief.width, 512);
    EXPECT_EQ(relief.height, 437);
    const auto bump = readOk(scenes() / "sponza/KAMEN-bump.jpg"); // progressive grey, 640x477
    EXPECT_EQ(bump.width, 640);
    EXPECT_EQ(bump.height, 477);
    EXPECT_TRUE(isGrey(bump)) << "one channel expanded to three";
}

TEST(TextureIo, PngWithAlphaKeepsIt) {
    const auto labels = readOk(scenes() / "gltf-small/AlphaBlendModeTest/glTF/AlphaBlendLabels.png");
    EXPECT_EQ(labels.width, 1024);
    bool translucent = false;
    for (std::size_t i = 3; i < labels.pixels.size(); i += 4)
        translucent |= labels.pixels[i] < 255;
    EXPECT_TRUE(translucent);
}

TEST(TextureIo, TgaRoundTrip) {
    const fs::path file = fs::temp_directory_path() / ("lpv-texture-" + std::to_string(::getpid()) + ".tga");
    importers::Image8 img;
    img.width = 3;
    img.height = 2;
    img.channels = 4;
    img.pixels = {10, 20, 30, 255, 40, 50, 60, 128, 70, 80, 90, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
    ASSERT_TRUE(importers::writeImage(file, img).has_value());
    const auto back = readOk(file);
    EXPECT_EQ(back.pixels, img.pixels);
    fs::remove(file);
}

TEST(TextureIo, MissingOrCorruptFileBecomesThePlaceholderWithAWarning) {
    const auto missing = importers::loadTextureOrPlaceholder("/nonexistent/WALL.BMP");
    EXPECT_TRUE(missing.placeholder);
    EXPECT_NE(missing.warning.find("WALL.BMP"), std::string::npos) << missing.warning;
    EXPECT_EQ(missing.image.width, 64);
    EXPECT_EQ(missing.image.pixels[0], 255) << "magenta";
    EXPECT_EQ(missing.image.pixels[1], 0);

    const fs::path corrupt = fs::temp_directory_path() / ("lpv-corrupt-" + std::to_string(::getpid()) + ".png");
    std::ofstream(corrupt, std::ios::binary) << "\x89PNG\r\n\x1a\n but then nothing";
    const auto bad = importers::loadTextureOrPlaceholder(corrupt);
    EXPECT_TRUE(bad.placeholder);
    EXPECT_NE(bad.warning.find(corrupt.filename().string()), std::string::npos) << bad.warning;
    fs::remove(corrupt);

    const auto good = importers::loadTextureOrPlaceholder(scenes() / "4ds/maps/red.bmp");
    EXPECT_FALSE(good.placeholder);
    EXPECT_TRUE(good.warning.empty());
}

// An uncompressed 32-bit DDS written from the format's documentation (no
// DDS sample exists in ../shared/scenes): header, then BGRA pixels.
TEST(TextureIo, UncompressedDds) {
    auto u32 = [](std::string& out, std::uint32_t v) {
        for (int k = 0; k < 4; ++k)
            out += char((v >> (8 * k)) & 0xff);
    };
    std::string dds = "DDS ";
    u32(dds, 124);                            // header size
    u32(dds, 0x1 | 0x2 | 0x4 | 0x1000);       // CAPS | HEIGHT | WIDTH | PIXELFORMAT
    u32(dds, 2);                              // height
    u32(dds, 2);                              // width
    u32(dds, 2 * 4);                          // pitch
    u32(dds, 0);                              // depth
    u32(dds, 0);                              // mip levels
    for (int i = 0; i < 11; ++i)
        u32(dds, 0);                          // reserved
    u32(dds, 32);                             // pixel format size
    u32(dds, 0x40 | 0x1);                     // RGB | ALPHAPIXELS
    u32(dds, 0);                              // no FourCC
    u32(dds, 32);                             // bits per pixel
    u32(dds, 0x00ff0000);                     // red mask
    u32(dds, 0x0000ff00);                     // green mask
    u32(dds, 0x000000ff);                     // blue mask
    u32(dds, 0xff000000);                     // alpha mask
    u32(dds, 0x1000);                         // caps: texture
    for (int i = 0; i < 4; ++i)
        u32(dds, 0);                          // caps2..4, reserved
    // Pixels (r, g, b, a) = (200, 100, 50, 255), (0, 255, 0, 128), (0, 0, 255, 255), (10, 20, 30, 40).
    for (std::uint32_t argb : {0xffc86432u, 0x8000ff00u, 0xff0000ffu, 0x280a141eu})
        u32(dds, argb);
    const fs::path file = fs::temp_directory_path() / ("lpv-texture-" + std::to_string(::getpid()) + ".dds");
    std::ofstream(file, std::ios::binary) << dds;
    const auto img = readOk(file);
    EXPECT_EQ(img.width, 2);
    EXPECT_EQ(img.height, 2);
    const std::vector<std::uint8_t> expected = {200, 100, 50, 255, 0, 255, 0, 128, 0, 0, 255, 255, 10, 20, 30, 40};
    EXPECT_EQ(img.pixels, expected);
    fs::remove(file);
}
