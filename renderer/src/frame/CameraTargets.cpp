// The camera's targets, which the passes share (the depth pre-pass,
// shading, sun rays, tonemapping: passes/direct/), kept across frames so the
// next frame's geometry volume reads this one's G-buffer.
#include "frame/ForwardRendererImpl.h"

#include <string>

namespace lpv::renderer {

using scene::ErrorCode;
using scene::makeError;

namespace {

graph::ResourceDesc target2D(GLenum format, int w, int h) {
    return {graph::ResourceKind::Texture2D, format, w, h};
}

} // namespace

scene::Expected<void> ForwardRenderer::Impl::checkSize(int w, int h) const {
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    if (w <= 0 || h <= 0 || w > maxSize || h > maxSize)
        return makeError(ErrorCode::OutOfRange, "render", "size",
                         std::to_string(w) + "x" + std::to_string(h) + " is outside 1.." + std::to_string(maxSize) +
                             " (GL_MAX_TEXTURE_SIZE)");
    return {};
}

void ForwardRenderer::Impl::declareCameraTargets(const FrameContext& frame) {
    const int w = frame.width, h = frame.height;
    if (w != width || h != height)
        gBufferValid = false; // the new targets hold nothing yet
    width = w;
    height = h;
    // Last frame's G-buffer, as the geometry volume reads it: named by the camera and scene it shows.
    const std::uint64_t gBufferVersion =
        gBufferValid ? graph::ContentHash().add(previousCamera.inverseViewProj).add(gBufferSceneGeneration).value() : 0;
    using graph::Lifetime;
    graph.createResource(resources::CameraHdr, target2D(GL_RGBA16F, w, h), Lifetime::History);
    graph.createResource(resources::CameraNormal, target2D(GL_RGBA16F, w, h), Lifetime::History, gBufferVersion);
    graph.createResource(resources::CameraAlbedo, target2D(GL_RGBA8, w, h), Lifetime::History);
    graph.createResource(resources::CameraDepth, target2D(GL_DEPTH_COMPONENT32F, w, h), Lifetime::History, gBufferVersion);
    graph.createResource(resources::Display, target2D(GL_RGBA8, w, h), Lifetime::History);
}

} // namespace lpv::renderer
