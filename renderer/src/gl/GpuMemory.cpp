#include "gl/GpuMemoryLedger.h"

#include <algorithm>
#include <cstdio>

namespace lpv::renderer {

std::uint64_t GpuMemory::bytesOf(std::string_view prefix) const {
    std::uint64_t sum = 0;
    for (const GpuAllocation& a : allocations)
        if (a.name.starts_with(prefix))
            sum += a.bytes;
    return sum;
}

const GpuAllocation* GpuMemory::find(std::string_view name) const {
    for (const GpuAllocation& a : allocations)
        if (a.name == name)
            return &a;
    return nullptr;
}

std::uint64_t bytesPerTexel(GLenum internalFormat) {
    // Formats whose size is what they say; packed depth formats a driver
    // rounds up (DEPTH24, DEPTH32F_STENCIL8) are left out rather than guessed.
    switch (internalFormat) {
    case GL_RGBA32F:
    case GL_RGBA32UI:
    case GL_RGBA32I:
        return 16;
    case GL_RGB32F:
    case GL_RGB32UI:
    case GL_RGB32I:
        return 12;
    case GL_RGBA16F:
    case GL_RGBA16:
    case GL_RGBA16UI:
    case GL_RGBA16I:
    case GL_RG32F:
    case GL_RG32UI:
    case GL_RG32I:
        return 8;
    case GL_RGBA8:
    case GL_SRGB8_ALPHA8:
    case GL_RGBA8UI:
    case GL_RGBA8I:
    case GL_RGB10_A2:
    case GL_R11F_G11F_B10F:
    case GL_RG16F:
    case GL_RG16:
    case GL_RG16UI:
    case GL_R32F:
    case GL_R32UI:
    case GL_R32I:
    case GL_DEPTH_COMPONENT32F:
        return 4;
    case GL_R16F:
    case GL_R16:
    case GL_R16UI:
    case GL_RG8:
    case GL_DEPTH_COMPONENT16:
        return 2;
    case GL_R8:
    case GL_R8UI:
        return 1;
    default:
        return 0;
    }
}

std::string formatBytes(std::uint64_t bytes) {
    if (bytes < 1024)
        return std::to_string(bytes) + " B";
    const char* units[] = {"KiB", "MiB", "GiB", "TiB"};
    double value = double(bytes) / 1024.0;
    std::size_t unit = 0;
    while (value >= 1024.0 && unit + 1 < std::size(units)) {
        value /= 1024.0;
        ++unit;
    }
    char text[32];
    std::snprintf(text, sizeof text, "%.1f", value);
    std::string number = text;
    if (number.ends_with(".0"))
        number.resize(number.size() - 2);
    return number + " " + units[unit];
}

std::uint64_t textureBytes(const graph::ResourceDesc& desc, int levels) {
    if (desc.kind == graph::ResourceKind::Buffer)
        return desc.bytes;
    const std::uint64_t texel = bytesPerTexel(desc.format);
    std::uint64_t sum = 0;
    for (int level = 0; level < std::max(levels, 1); ++level) {
        const std::uint64_t w = std::uint64_t(std::max(desc.width >> level, 1));
        const std::uint64_t h = std::uint64_t(std::max(desc.height >> level, 1));
        // Array layers (and a cube array's layer-faces) stay; a 3D texture's depth halves.
        const std::uint64_t d = desc.kind == graph::ResourceKind::Texture3D
                                    ? std::uint64_t(std::max(desc.layers >> level, 1))
                                    : std::uint64_t(std::max(desc.layers, 1));
        sum += w * h * d * texel;
    }
    return sum;
}

namespace {

int mipLevels(GLuint texture) {
    GLint immutable = 0, levels = 0;
    glGetTextureParameteriv(texture, GL_TEXTURE_IMMUTABLE_FORMAT, &immutable);
    if (immutable) {
        glGetTextureParameteriv(texture, GL_TEXTURE_IMMUTABLE_LEVELS, &levels);
        return std::max(levels, 1);
    }
    // Mutable storage: the levels that were given an image.
    for (GLint width = 1; levels < 32; ++levels) {
        glGetTextureLevelParameteriv(texture, levels, GL_TEXTURE_WIDTH, &width);
        if (width == 0)
            break;
    }
    return std::max(levels, 1);
}

} // namespace

void GpuMemoryLedger::addTexture(std::string_view name, GLuint texture) {
    if (texture)
        add(name, false, texture, graph::queryTexture(texture), mipLevels(texture));
}

void GpuMemoryLedger::addBuffer(std::string_view name, GLuint buffer) {
    if (buffer)
        add(name, true, buffer, graph::queryBuffer(buffer), 1);
}

void GpuMemoryLedger::addResource(std::string_view name, GLuint id, const graph::ResourceDesc& desc) {
    if (!id)
        return;
    const bool buffer = desc.kind == graph::ResourceKind::Buffer;
    add(name, buffer, id, desc, buffer ? 1 : mipLevels(id));
}

void GpuMemoryLedger::add(std::string_view name, bool buffer, GLuint id, const graph::ResourceDesc& desc,
                          int levels) {
    if (!seen_.insert({buffer, id}).second)
        return;
    std::string what = graph::describe(desc);
    if (levels > 1)
        what += ", " + std::to_string(levels) + " levels";
    const std::uint64_t bytes = textureBytes(desc, levels);
    if (!buffer && bytesPerTexel(desc.format) == 0) {
        char hex[16];
        std::snprintf(hex, sizeof hex, "0x%04X", unsigned(desc.format));
        what += std::string(" (format ") + hex + " unknown to bytesPerTexel: not counted)";
    }
    auto it = entries_.find(name);
    if (it == entries_.end()) {
        order_.emplace_back(name);
        it = entries_.emplace(std::string(name), std::vector<Entry>{}).first;
    }
    for (Entry& e : it->second)
        if (e.what == what && e.bytes == bytes) {
            ++e.count;
            return;
        }
    it->second.push_back({std::move(what), bytes, 1});
}

GpuMemory GpuMemoryLedger::finish() const {
    GpuMemory memory;
    for (const std::string& name : order_) {
        GpuAllocation a;
        a.name = name;
        for (const Entry& e : entries_.find(name)->second) {
            if (!a.what.empty())
                a.what += ", ";
            a.what += (e.count > 1 ? std::to_string(e.count) + " x " : std::string()) + e.what;
            a.bytes += e.bytes * std::uint64_t(e.count);
        }
        memory.totalBytes += a.bytes;
        memory.allocations.push_back(std::move(a));
    }
    std::stable_sort(memory.allocations.begin(), memory.allocations.end(),
                     [](const GpuAllocation& a, const GpuAllocation& b) { return a.bytes > b.bytes; });
    return memory;
}

} // namespace lpv::renderer
