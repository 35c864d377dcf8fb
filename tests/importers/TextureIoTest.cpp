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
