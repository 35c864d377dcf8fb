#pragma once
// Move-only RAII handles for GL objects, with an explicit empty state (0).
// They must be destroyed while their context is current.
#include <epoxy/gl.h>

#include <utility>

namespace lpv::renderer {

template <class Deleter>
class GlHandle {
public:
    GlHandle() = default;
    explicit GlHandle(GLuint id) : id_(id) {}
    GlHandle(const GlHandle&) = delete;
    GlHandle& operator=(const GlHandle&) = delete;
    GlHandle(GlHandle&& o) noexcept : id_(std::exchange(o.id_, 0)) {}
    GlHandle& operator=(GlHandle&& o) noexcept {
        if (this != &o) {
            reset();
            id_ = std::exchange(o.id_, 0);
        }
        return *this;
    }
    ~GlHandle() { reset(); }

    GLuint id() const { return id_; }
    explicit operator bool() const { return id_ != 0; }
    void reset() {
        if (id_)
            Deleter{}(id_);
        id_ = 0;
    }

private:
    GLuint id_ = 0;
};

struct BufferDeleter {
    void operator()(GLuint id) const { glDeleteBuffers(1, &id); }
};
struct TextureDeleter {
    void operator()(GLuint id) const { glDeleteTextures(1, &id); }
};
struct FramebufferDeleter {
    void operator()(GLuint id) const { glDeleteFramebuffers(1, &id); }
};
struct VertexArrayDeleter {
    void operator()(GLuint id) const { glDeleteVertexArrays(1, &id); }
};
struct ProgramDeleter {
    void operator()(GLuint id) const { glDeleteProgram(id); }
};
struct ShaderDeleter {
    void operator()(GLuint id) const { glDeleteShader(id); }
};
struct QueryDeleter {
    void operator()(GLuint id) const { glDeleteQueries(1, &id); }
};

using Buffer = GlHandle<BufferDeleter>;
using Texture = GlHandle<TextureDeleter>;
using Framebuffer = GlHandle<FramebufferDeleter>;
using VertexArray = GlHandle<VertexArrayDeleter>;
using Program = GlHandle<ProgramDeleter>;
using Shader = GlHandle<ShaderDeleter>;
using Query = GlHandle<QueryDeleter>;

// DSA creation helpers (OpenGL 4.5).
inline Buffer createBuffer() {
    GLuint id = 0;
    glCreateBuffers(1, &id);
    return Buffer(id);
}
inline Texture createTexture(GLenum target) {
    GLuint id = 0;
    glCreateTextures(target, 1, &id);
    return Texture(id);
}
inline Framebuffer createFramebuffer() {
    GLuint id = 0;
    glCreateFramebuffers(1, &id);
    return Framebuffer(id);
}
inline VertexArray createVertexArray() {
    GLuint id = 0;
    glCreateVertexArrays(1, &id);
    return VertexArray(id);
}
inline Query createQuery(GLenum target) {
    GLuint id = 0;
    glCreateQueries(target, 1, &id);
    return Query(id);
}

} // namespace lpv::renderer
