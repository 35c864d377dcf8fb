// Texture upload: full mip chains, sRGB for colour and linear for data, rows
// flipped to the bottom-left UV origin, anisotropic filtering where offered,
// and one GL texture per image however many materials share it.
#include "GlFixture.h"

#include "scenegpu/MaterialGpu.h"
#include "scenegpu/TextureGpu.h"

#include <algorithm>
#include <vector>

using namespace lpv;

namespace {

scene::Image8 gradient(int w, int h) {
    scene::Image8 img{w, h, 4, {}};
    for (int row = 0; row < h; ++row)
        for (int x = 0; x < w; ++x)
            img.pixels.insert(img.pixels.end(), {std::uint8_t(x * 4), std::uint8_t(row * 4), 7, 255});
    return img;
}

GLint levelParameter(GLuint texture, GLint level, GLenum what) {
    GLint v = 0;
    glGetTextureLevelParameteriv(texture, level, what, &v);
    return v;
}

} // namespace

class TextureGpu : public GlTest {};

TEST_F(TextureGpu, FullMipChainAndFormatsByUse) {
    const scene::Image8 img = gradient(64, 32);
    const renderer::Texture colour = renderer::uploadTexture(img, renderer::TextureUsage::Color);
    const renderer::Texture data = renderer::uploadTexture(img, renderer::TextureUsage::Data);
    GLint levels = 0;
    glGetTextureParameteriv(colour.id(), GL_TEXTURE_IMMUTABLE_LEVELS, &levels);
    EXPECT_EQ(levels, 7) << "64x32 down to 1x1";
    EXPECT_EQ(levelParameter(colour.id(), 6, GL_TEXTURE_WIDTH), 1);
    EXPECT_EQ(levelParameter(colour.id(), 0, GL_TEXTURE_INTERNAL_FORMAT), GL_SRGB8_ALPHA8);
    EXPECT_EQ(levelParameter(data.id(), 0, GL_TEXTURE_INTERNAL_FORMAT), GL_RGBA8);
    GLint minFilter = 0;
    glGetTextureParameteriv(colour.id(), GL_TEXTURE_MIN_FILTER, &minFilter);
    EXPECT_EQ(minFilter, GL_LINEAR_MIPMAP_LINEAR);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(TextureGpu, AnisotropyFollowsTheParameterWithinTheDriversLimit) {
    const float limit = renderer::maxSupportedAnisotropy();
    if (limit <= 1.0f)
        GTEST_SKIP() << "no anisotropic filtering (GL < 4.6 and no extension)";
    scene::TextureImages images;
    images["a.png"] = gradient(8, 8);
    renderer::TextureCache cache;
    cache.setAnisotropy(8.0f);
    const GLuint t = cache.get(images, "a.png", renderer::TextureUsage::Color);
    auto anisotropyOf = [&] {
        GLfloat aniso = 0.0f;
        glGetTextureParameterfv(t, 0x84FE /* GL_TEXTURE_MAX_ANISOTROPY */, &aniso);
        return aniso;
    };
    EXPECT_FLOAT_EQ(anisotropyOf(), std::min(8.0f, limit)) << "driver limit " << limit;
    cache.setAnisotropy(1.0f);
    EXPECT_FLOAT_EQ(anisotropyOf(), 1.0f);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(TextureGpu, FirstGlRowIsTheImagesBottomRow) {
    const scene::Image8 img = gradient(16, 8);
    const renderer::Texture t = renderer::uploadTexture(img, renderer::TextureUsage::Data);
    std::vector<std::uint8_t> px(16 * 8 * 4);
    glGetTextureImage(t.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(px.size()), px.data());
    // GL row 0 (v = 0) holds the image's last row (row 7: green = 28).
    EXPECT_EQ(int(px[1]), 7 * 4);
    EXPECT_EQ(int(px[(7 * 16) * 4 + 1]), 0);
}

TEST_F(TextureGpu, TallImagesAreFlippedAcrossUploadStrips) {
    // Rows go up in strips of 256 (issue #42: no second full copy); 600
    // rows make three strips, the last one short.
    // One channel, four texels a row: rows of 4 bytes keep GL's default
    // pack alignment out of the way.
    scene::Image8 img{4, 600, 1, {}};
    for (int row = 0; row < 600; ++row)
        img.pixels.insert(img.pixels.end(), {std::uint8_t(row % 251), std::uint8_t(row / 251), 9, 9});
    const renderer::Texture t = renderer::uploadTexture(img, renderer::TextureUsage::Data);
    std::vector<std::uint8_t> px(4 * 600);
    glGetTextureImage(t.id(), 0, GL_RED, GL_UNSIGNED_BYTE, GLsizei(px.size()), px.data());
    for (int glRow = 0; glRow < 600; ++glRow) {
        const int row = 599 - glRow;
        ASSERT_EQ(int(px[std::size_t(glRow) * 4]), row % 251) << "GL row " << glRow;
        ASSERT_EQ(int(px[std::size_t(glRow) * 4 + 1]), row / 251) << "GL row " << glRow;
    }
}

TEST_F(TextureGpu, SharedImagesAreUploadedOncePerUse) {
    scene::Scene s;
    scene::Material a, b, c;
    a.diffuseTexture = b.diffuseTexture = "stone.png";
    b.emissiveTexture = "stone.png"; // also colour: the same GL texture
    c.normalTexture = "stone.png";   // data: a second, linear one
    c.heightTexture = "missing.png"; // absent from the images: no texture, no error
    s.materials = {a, b, c};
    scene::TextureImages images;
    images["stone.png"] = gradient(8, 8);
    const renderer::MaterialGpu materials(s, images);
    EXPECT_EQ(materials.textureCount(), 2u);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}
