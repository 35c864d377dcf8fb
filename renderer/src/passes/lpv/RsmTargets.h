#pragma once
// The texture arrays a reflective shadow map is drawn into, one layer per
// tile (the sun's cascades, RsmPass) or per face (the local lights' spots
// and cube faces, LocalRsmPass): world position (RGBA32F), normal
// (RGBA16F), flux (RGBA32F) and depth, with the framebuffer that draws
// them (colour attachments 0-2 in that order).
#include "lpv/renderer/ForwardRenderer.h"
#include "lpv/renderer/GlHandle.h"

#include <cstddef>
#include <string>
#include <vector>

namespace lpv::renderer {

class RsmTargets {
  public:
    // position, normal, flux, depth
    static constexpr std::size_t kBytesPerTexel = 16 + 8 + 16 + 4;

    int size() const { return size_; }
    int layers() const { return layers_; }
    bool holds(int size, int layers) const { return size == size_ && layers == layers_; }
    std::size_t bytes() const {
        return std::size_t(size_) * std::size_t(size_) * std::size_t(layers_) * kBytesPerTexel;
    }
    GLuint position() const { return position_.id(); }
    GLuint normal() const { return normal_.id(); }
    GLuint flux() const { return flux_.id(); }
    GLuint depth() const { return depth_.id(); }
    GLuint framebuffer() const { return fbo_.id(); }

    // Makes the arrays and the framebuffer, nothing attached. False when the
    // GPU ran out of memory: then nothing is held (an earlier GL_OUT_OF_MEMORY
    // is drained first, so it is not blamed on these).
    bool allocate(int size, int layers);
    void release();
    // All layers attached (a layered framebuffer: gl_Layer picks the tile), or one.
    void attachAllLayers();
    void attachLayer(int layer);
    // Binds the framebuffer for drawing at its size: depth test (less, written),
    // no blending, no culling (a light sees single-sided walls from either
    // side), no polygon offset.
    void bindForDrawing() const;
    // The attached layer(s) to zero and the depth to far.
    void clear();
    // Each layer's position, normal and flux as `prefix`-LAYER-WHAT images,
    // rows top to bottom (layers 0 .. count-1).
    std::vector<DebugImage> debugImages(const std::string& prefix, int count) const;

  private:
    int size_ = 0, layers_ = 0;
    Texture position_, normal_, flux_, depth_;
    Framebuffer fbo_;
};

} // namespace lpv::renderer
