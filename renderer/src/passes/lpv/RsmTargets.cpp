#include "passes/lpv/RsmTargets.h"

#include "gl/ImageRows.h"

#include <algorithm>

namespace lpv::renderer {
namespace {

Texture makeArray(GLenum format, int size, int layers) {
    Texture t = createTexture(GL_TEXTURE_2D_ARRAY);
    glTextureStorage3D(t.id(), 1, format, size, size, layers);
    // Texel-exact reads: every texel is one VPL.
    glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return t;
}

constexpr GLenum kAttachments[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2,
                                   GL_DEPTH_ATTACHMENT};

} // namespace

bool RsmTargets::allocate(int size, int layers) {
    release();
    while (glGetError() == GL_OUT_OF_MEMORY) {
    }
    position_ = makeArray(GL_RGBA32F, size, layers);
    normal_ = makeArray(GL_RGBA16F, size, layers);
    // 32-bit: a texel's flux (W) goes with its area, so it spans the
    // square of the scene's unit; half floats lost a 2 cm box's light
    // (below 6e-8 W) and would overflow a kilometre scene's (issue #41).
    flux_ = makeArray(GL_RGBA32F, size, layers);
    depth_ = makeArray(GL_DEPTH_COMPONENT32F, size, layers);
    fbo_ = createFramebuffer();
    const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
    glNamedFramebufferDrawBuffers(fbo_.id(), 3, buffers);
    if (glGetError() == GL_OUT_OF_MEMORY) {
        release();
        return false;
    }
    size_ = size;
    layers_ = layers;
    return true;
}

void RsmTargets::release() {
    fbo_.reset();
    position_.reset();
    normal_.reset();
    flux_.reset();
    depth_.reset();
    size_ = layers_ = 0;
}

void RsmTargets::attachAllLayers() {
    const GLuint targets[] = {position_.id(), normal_.id(), flux_.id(), depth_.id()};
    for (int a = 0; a < 4; ++a)
        glNamedFramebufferTexture(fbo_.id(), kAttachments[a], targets[a], 0);
}

void RsmTargets::attachLayer(int layer) {
    const GLuint targets[] = {position_.id(), normal_.id(), flux_.id(), depth_.id()};
    for (int a = 0; a < 4; ++a)
        glNamedFramebufferTextureLayer(fbo_.id(), kAttachments[a], targets[a], 0, layer);
}

void RsmTargets::bindForDrawing() const {
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    glViewport(0, 0, size_, size_);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE); // a light sees single-sided walls from either side
    glDisable(GL_POLYGON_OFFSET_FILL);
}

void RsmTargets::clear() {
    const float zero[] = {0.0f, 0.0f, 0.0f, 0.0f};
    const float farDepth = 1.0f;
    for (GLint b = 0; b < 3; ++b)
        glClearNamedFramebufferfv(fbo_.id(), GL_COLOR, b, zero);
    glClearNamedFramebufferfv(fbo_.id(), GL_DEPTH, 0, &farDepth);
}

std::vector<DebugImage> RsmTargets::debugImages(const std::string& prefix, int count) const {
    std::vector<DebugImage> images;
    const std::size_t row = std::size_t(size_) * 4;
    const std::pair<const char*, GLuint> targets[] = {
        {"position", position_.id()}, {"normal", normal_.id()}, {"flux", flux_.id()}};
    for (int layer = 0; layer < std::min(count, layers_); ++layer)
        for (const auto& [what, texture] : targets) {
            DebugImage image{prefix + "-" + std::to_string(layer) + "-" + what, size_, size_, 4, {}};
            image.pixels.resize(row * std::size_t(size_));
            glGetTextureSubImage(texture, 0, 0, 0, layer, size_, size_, 1, GL_RGBA, GL_FLOAT,
                                 GLsizei(image.pixels.size() * sizeof(float)), image.pixels.data());
            flipRows(image.pixels, size_, size_, 4);
            images.push_back(std::move(image));
        }
    return images;
}

} // namespace lpv::renderer
