#include "ResourceDesc.h"

#include <cstdio>

namespace lpv::renderer::graph {

namespace {

const char* formatName(GLenum format) {
    switch (format) {
    case GL_RGBA8: return "RGBA8";
    case GL_SRGB8_ALPHA8: return "SRGB8_ALPHA8";
    case GL_RGBA16F: return "RGBA16F";
    case GL_RGBA32F: return "RGBA32F";
    case GL_R32F: return "R32F";
    case GL_R16F: return "R16F";
    case GL_R32UI: return "R32UI";
    case GL_RG16F: return "RG16F";
    case GL_DEPTH_COMPONENT32F: return "DEPTH32F";
    default: return "format?";
    }
}

const char* kindName(ResourceKind kind) {
    switch (kind) {
    case ResourceKind::Texture2D: return "2D";
    case ResourceKind::Texture2DArray: return "2D array";
    case ResourceKind::Texture3D: return "3D";
    case ResourceKind::CubeMapArray: return "cube array";
    case ResourceKind::Buffer: return "buffer";
    }
    return "?";
}

} // namespace

bool known(const ResourceDesc& desc) {
    return desc.kind == ResourceKind::Buffer ? desc.bytes > 0 : desc.width > 0 && desc.height > 0;
}

std::string describe(const ResourceDesc& desc) {
    if (!known(desc))
        return std::string(kindName(desc.kind)) + " (not allocated)";
    char text[96];
    if (desc.kind == ResourceKind::Buffer && desc.bytes < 1024)
        std::snprintf(text, sizeof text, "buffer %zu bytes", desc.bytes);
    else if (desc.kind == ResourceKind::Buffer)
        std::snprintf(text, sizeof text, "buffer %.1f KiB", double(desc.bytes) / 1024.0);
    else if (desc.kind == ResourceKind::Texture2D)
        std::snprintf(text, sizeof text, "2D %s %dx%d", formatName(desc.format), desc.width, desc.height);
    else
        std::snprintf(text, sizeof text, "%s %s %dx%dx%d", kindName(desc.kind), formatName(desc.format), desc.width,
                      desc.height, desc.layers);
    return text;
}

Texture allocateTexture(const ResourceDesc& desc) {
    Texture t;
    switch (desc.kind) {
    case ResourceKind::Texture2D:
        t = createTexture(GL_TEXTURE_2D);
        glTextureStorage2D(t.id(), 1, desc.format, desc.width, desc.height);
        break;
    case ResourceKind::Texture2DArray:
        t = createTexture(GL_TEXTURE_2D_ARRAY);
        glTextureStorage3D(t.id(), 1, desc.format, desc.width, desc.height, desc.layers);
        break;
    case ResourceKind::Texture3D:
        t = createTexture(GL_TEXTURE_3D);
        glTextureStorage3D(t.id(), 1, desc.format, desc.width, desc.height, desc.layers);
        break;
    case ResourceKind::CubeMapArray:
        t = createTexture(GL_TEXTURE_CUBE_MAP_ARRAY);
        glTextureStorage3D(t.id(), 1, desc.format, desc.width, desc.height, desc.layers);
        break;
    case ResourceKind::Buffer:
        return t; // buffers are imported, never allocated by the graph
    }
    const GLint filter = desc.linearFilter ? GL_LINEAR : GL_NEAREST;
    glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, filter);
    glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, filter);
    glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return t;
}

ResourceDesc queryTexture(GLuint texture) {
    ResourceDesc d;
    if (!texture)
        return d;
    GLint target = 0, format = 0;
    glGetTextureParameteriv(texture, GL_TEXTURE_TARGET, &target);
    switch (target) {
    case GL_TEXTURE_2D_ARRAY: d.kind = ResourceKind::Texture2DArray; break;
    case GL_TEXTURE_3D: d.kind = ResourceKind::Texture3D; break;
    case GL_TEXTURE_CUBE_MAP_ARRAY: d.kind = ResourceKind::CubeMapArray; break;
    default: d.kind = ResourceKind::Texture2D; break;
    }
    glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
    glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_WIDTH, &d.width);
    glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_HEIGHT, &d.height);
    glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_DEPTH, &d.layers);
    d.format = GLenum(format);
    return d;
}

ResourceDesc queryBuffer(GLuint buffer) {
    ResourceDesc d{ResourceKind::Buffer};
    if (!buffer)
        return d;
    GLint64 size = 0;
    glGetNamedBufferParameteri64v(buffer, GL_BUFFER_SIZE, &size);
    d.bytes = std::size_t(size);
    return d;
}

} // namespace lpv::renderer::graph
