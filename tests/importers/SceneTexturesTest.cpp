// Textures of a whole scene: decoded once, colour keys, height maps turned
// into normal maps, placeholders for missing files, and real shared scenes.
#include "lpv/importers/ImageIO.h"
#include "lpv/importers/Importer.h"
#include "lpv/importers/SceneTextures.h"
#include "lpv/scene/ProjectTextures.h"
#include "TestPaths.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

using namespace lpv;
namespace fs = std::filesystem;

namespace {

fs::path scenes() { return fs::path(test::kSharedScenesDir); }

fs::path tempDir(const std::string& name) {
    const fs::path d = fs::temp_directory_path() / ("lpv-scenetex-" + name + "-" + std::to_string(::getpid()));
    fs::create_directories(d);
    return d;
}

// Decoded tangent-space normal of texel (x, row).
glm::vec3 normalAt(const scene::Image8& img, int x, int row) {
    const std::uint8_t* p = &img.pixels[(std::size_t(row) * std::size_t(img.width) + std::size_t(x)) * 4];
    return glm::vec3(p[0], p[1], p[2]) / 255.0f * 2.0f - 1.0f;
}

scene::Image8 greyImage(int w, int h, auto heightOf) {
    scene::Image8 img{w, h, 4, {}};
    for (int row = 0; row < h; ++row)
        for (int x = 0; x < w; ++x) {
            const std::uint8_t v = std::uint8_t(heightOf(x, row));
            img.pixels.insert(img.pixels.end(), {v, v, v, 255});
        }
    return img;
}

// An 8-bit palettised BMP (BITMAPINFOHEADER, 256-entry palette), rows bottom to top.
void writePalettisedBmp(const fs::path& file, int w, int h, const std::vector<std::array<std::uint8_t, 3>>& palette,
                        const std::vector<std::uint8_t>& indicesTopToBottom) {
    const int stride = (w + 3) & ~3;
    const std::uint32_t paletteBytes = 256 * 4, dataOffset = 14 + 40 + paletteBytes;
    const std::uint32_t fileSize = dataOffset + std::uint32_t(stride * h);
    std::vector<std::uint8_t> b;
    auto u16 = [&](std::uint32_t v) { b.insert(b.end(), {std::uint8_t(v), std::uint8_t(v >> 8)}); };
    auto u32 = [&](std::uint32_t v) { u16(v & 0xffff); u16(v >> 16); };
    b.push_back('B');
    b.push_back('M');
    u32(fileSize); u32(0); u32(dataOffset);
    u32(40); u32(std::uint32_t(w)); u32(std::uint32_t(h)); u16(1); u16(8); u32(0); u32(std::uint32_t(stride * h));
    u32(2835); u32(2835); u32(256); u32(0);
    for (int i = 0; i < 256; ++i) {
        const auto c = i < int(palette.size()) ? palette[std::size_t(i)] : std::array<std::uint8_t, 3>{0, 0, 0};
        b.insert(b.end(), {c[2], c[1], c[0], 0});
    }
    for (int row = h - 1; row >= 0; --row) {
        for (int x = 0; x < w; ++x)
            b.push_back(indicesTopToBottom[std::size_t(row * w + x)]);
        for (int x = w; x < stride; ++x)
            b.push_back(0);
    }
    std::ofstream(file, std::ios::binary).write(reinterpret_cast<const char*>(b.data()), std::streamsize(b.size()));
}

} // namespace

TEST(HeightToNormal, FlatHeightGivesStraightUpNormals) {
    const auto n = importers::heightToNormalMap(greyImage(8, 8, [](int, int) { return 100; }));
    for (int row = 0; row < 8; ++row)
        for (int x = 0; x < 8; ++x)
            EXPECT_GT(normalAt(n, x, row).z, 0.99f);
}

TEST(HeightToNormal, RampTiltsNormalsAwayFromTheRise) {
    // Height rising towards +u (right): the surface faces -u.
    const auto right = importers::heightToNormalMap(greyImage(16, 16, [](int x, int) { return 40 + 10 * x; }), 2.0f);
    const glm::vec3 nr = normalAt(right, 8, 8);
    // slope = strength * 10/255 per texel (central difference of a linear ramp)
    const float expected = 2.0f * 10.0f / 255.0f;
    EXPECT_NEAR(nr.x / nr.z, -expected, 0.02f) << "n = " << nr.x << "," << nr.y << "," << nr.z;
    EXPECT_NEAR(nr.y, 0.0f, 0.01f);
    // Height rising towards the top of the image (+v, rows are top to bottom): the surface faces -v.
    const auto up = importers::heightToNormalMap(greyImage(16, 16, [](int, int row) { return 200 - 10 * row; }), 2.0f);
    const glm::vec3 nu = normalAt(up, 8, 8);
    EXPECT_LT(nu.y, -0.05f) << "n.y = " << nu.y;
    EXPECT_NEAR(nu.x, 0.0f, 0.01f);
}

TEST(ColorKey, FirstPaletteEntryOfAnEightBitBmpBecomesTransparent) {
    const fs::path dir = tempDir("key");
    // Palette entry 0 is a green that also appears (as entry 2) at another
    // index: keying compares colours, so both vanish; red (entry 1) stays.
    writePalettisedBmp(dir / "leaf.bmp", 4, 2, {{20, 200, 40}, {250, 10, 10}, {20, 200, 40}},
                       {0, 1, 1, 0, 2, 1, 1, 1});
    const auto key = importers::bmpFirstPaletteColour(dir / "leaf.bmp");
    ASSERT_TRUE(key.has_value());
    EXPECT_EQ((*key)[0], 20);
    EXPECT_EQ((*key)[1], 200);
    EXPECT_EQ((*key)[2], 40);

    scene::Scene s;
    scene::Material keyed;
    keyed.diffuseTexture = "leaf.bmp";
    keyed.colorKey = true;
    keyed.alphaMode = scene::AlphaMode::Mask;
    scene::Material plain;
    plain.diffuseTexture = (dir / "leaf.bmp").string(); // absolute path: a second key
    s.materials = {keyed, plain};
    const auto t = importers::loadSceneTextures(s, dir);
    EXPECT_TRUE(t.warnings.empty());
    ASSERT_TRUE(t.images.contains(std::string("leaf.bmp") + importers::kColorKeySuffix));
    const scene::Image8& img = t.images.at(std::string("leaf.bmp") + importers::kColorKeySuffix);
    ASSERT_EQ(img.width, 4);
    const std::vector<int> expectedAlpha = {0, 255, 255, 0, 0, 255, 255, 255};
    for (std::size_t i = 0; i < expectedAlpha.size(); ++i)
        EXPECT_EQ(int(img.pixels[i * 4 + 3]), expectedAlpha[i]) << "pixel " << i;
    // The unkeyed file stays opaque.
    for (std::size_t i = 0; i < 8; ++i)
        EXPECT_EQ(int(t.images.at(plain.diffuseTexture).pixels[i * 4 + 3]), 255);
    fs::remove_all(dir);
}

TEST(ColorKey, TrueColourImagesAreKeyedByBlack) {
    const fs::path dir = tempDir("black");
    scene::Image8 img{2, 1, 4, {0, 0, 0, 255, 30, 60, 90, 255}};
    ASSERT_TRUE(importers::writeImage(dir / "glow.png", img).has_value());
    scene::Scene s;
    scene::Material m;
    m.diffuseTexture = "glow.png";
    m.colorKey = true;
    s.materials = {m};
    const auto t = importers::loadSceneTextures(s, dir);
    const scene::Image8& keyed = t.images.at(std::string("glow.png") + importers::kColorKeySuffix);
    EXPECT_EQ(keyed.pixels[3], 0);
    EXPECT_EQ(keyed.pixels[7], 255);
    // The cut-out texel took its visible neighbour's colour: filtering blends no black in.
    EXPECT_EQ(keyed.pixels[0], 30);
    EXPECT_EQ(keyed.pixels[1], 60);
    EXPECT_EQ(keyed.pixels[2], 90);
    fs::remove_all(dir);
}

TEST(SceneTextures, MissingFileIsAPlaceholderWithAWarningNamingIt) {
    scene::Scene s;
    scene::Material m;
    m.diffuseTexture = "no-such-texture.png";
    m.normalTexture = "no-such-texture.png"; // decoded (and warned about) once
    s.materials = {m, m};
    const auto t = importers::loadSceneTextures(s, fs::temp_directory_path());
    ASSERT_EQ(t.warnings.size(), 1u);
    EXPECT_NE(t.warnings[0].find("no-such-texture.png"), std::string::npos) << t.warnings[0];
    ASSERT_TRUE(t.images.contains("no-such-texture.png"));
    EXPECT_EQ(t.images.at("no-such-texture.png").width, importers::placeholderTexture().width);
}

TEST(SceneTextures, Sibenik4dsFindsEveryTexture) {
    auto imported = importers::importScene(scenes() / "4ds/sibenik.4ds");
    ASSERT_TRUE(imported.has_value()) << imported.error().describe();
    const auto t = importers::loadSceneTextures(imported->scene, scenes() / "4ds");
    EXPECT_TRUE(t.warnings.empty()) << t.warnings.size() << " warnings, first: " << t.warnings.front();
    std::size_t slots = 0;
    for (const scene::Material& m : imported->scene.materials)
        for (const std::string* p : scene::textureSlots(m))
            if (!p->empty()) {
                ++slots;
                const std::string key = p == &m.heightTexture ? *p + importers::kHeightNormalSuffix : *p;
                EXPECT_TRUE(t.images.contains(key)) << key;
            }
    EXPECT_GT(slots, 3u) << "diffuse, normal (_ddn) and specular (_spec) maps";
}

TEST(SceneTextures, SponzaBumpMapsBecomeNormalMaps) {
    auto imported = importers::importScene(scenes() / "sponza/sponza.obj");
    ASSERT_TRUE(imported.has_value()) << imported.error().describe();
    const auto t = importers::loadSceneTextures(imported->scene, scenes() / "sponza");
    EXPECT_TRUE(t.warnings.empty()) << t.warnings.size() << " warnings, first: " << t.warnings.front();
    std::size_t heightMaps = 0;
    for (const scene::Material& m : imported->scene.materials)
        if (!m.heightTexture.empty()) {
            ++heightMaps;
            const scene::Image8& n = t.images.at(m.heightTexture + importers::kHeightNormalSuffix);
            EXPECT_GT(n.width, 0);
        }
    EXPECT_GE(heightMaps, 5u);
}
