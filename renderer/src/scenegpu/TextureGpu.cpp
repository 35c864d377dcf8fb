#include "scenegpu/TextureGpu.h"

#include <algorithm>
#include <bit>
#include <vector>

namespace lpv::renderer {
namespace {

// GL 4.6 core or GL_{EXT,ARB}_texture_filter_anisotropic share these enum values.
constexpr GLenum kMaxAnisotropy = 0x84FE;
constexpr GLenum kMaxAnisotropyLimit = 0x84FF;

GLenum pixelFormat(int channels) {
    switch (channels) {
    case 1: return GL_RED;
    case 2: return GL_RG;
    case 3: return GL_RGB;
    default: return GL_RGBA;
    }
}

} // namespace

Texture uploadTexture(const scene::Image8& image, TextureUsage usage) {
    const int w = std::max(image.width, 1), h = std::max(image.height, 1), c = std::clamp(image.channels, 1, 4);
    const std::size_t row = std::size_t(w) * std::size_t(c);
    const bool valid = image.width > 0 && image.height > 0 && image.pixels.size() >= row * std::size_t(h);
    const GLsizei levels = GLsizei(std::bit_width(unsigned(std::max(w, h))));
    Texture t = createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(t.id(), levels, usage == TextureUsage::Color ? GL_SRGB8_ALPHA8 : GL_RGBA8, w, h);
    GLint alignment = 4;
    glGetIntegerv(GL_UNPACK_ALIGNMENT, &alignment);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    // GL's first row is the bottom one: rows go up reversed, a strip at a
    // time, so a large texture never costs a second full copy (issue #42).
    constexpr int kStripRows = 256;
    std::vector<std::uint8_t> strip(row * std::size_t(std::min(h, kStripRows)), 255);
    for (int y0 = 0; y0 < h; y0 += kStripRows) {
        const int rows = std::min(kStripRows, h - y0);
        if (valid)
            for (int y = 0; y < rows; ++y)
                std::copy_n(image.pixels.begin() + std::ptrdiff_t(std::size_t(h - 1 - (y0 + y)) * row), row,
                            strip.begin() + std::ptrdiff_t(std::size_t(y) * row));
        glTextureSubImage2D(t.id(), 0, 0, y0, w, rows, pixelFormat(c), GL_UNSIGNED_BYTE, strip.data());
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, alignment);
    if (c == 1) { // grey masks read the same from every channel
        const GLint swizzle[] = {GL_RED, GL_RED, GL_RED, GL_ONE};
        glTextureParameteriv(t.id(), GL_TEXTURE_SWIZZLE_RGBA, swizzle);
    }
    glGenerateTextureMipmap(t.id());
    glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, GL_REPEAT);
    return t;
}

float maxSupportedAnisotropy() {
    static const float value = [] {
        if (epoxy_gl_version() < 46 && !epoxy_has_gl_extension("GL_EXT_texture_filter_anisotropic") &&
            !epoxy_has_gl_extension("GL_ARB_texture_filter_anisotropic"))
            return 1.0f;
        GLfloat limit = 1.0f;
        glGetFloatv(kMaxAnisotropyLimit, &limit);
        return std::max(limit, 1.0f);
    }();
    return value;
}

void TextureCache::setAnisotropy(float wanted) {
    const float a = std::clamp(wanted, 1.0f, maxSupportedAnisotropy());
    if (a == anisotropy_)
        return;
    anisotropy_ = a;
    for (const auto& [key, texture] : uploaded_)
        glTextureParameterf(texture.id(), kMaxAnisotropy, a);
}

GLuint TextureCache::get(const scene::TextureImages& images, const std::string& key, TextureUsage usage) {
    if (key.empty())
        return 0;
    const auto image = images.find(key);
    if (image == images.end())
        return 0;
    auto [it, inserted] = uploaded_.try_emplace({key, usage});
    if (inserted) {
        it->second = uploadTexture(image->second, usage);
        if (anisotropy_ > 1.0f)
            glTextureParameterf(it->second.id(), kMaxAnisotropy, anisotropy_);
    }
    return it->second.id();
}

} // namespace lpv::renderer
