#include "lpv/renderer/RadiosityView.h"
#include "gl/ImageRows.h"

#include "passes/radiosity/PatchVertices.h"
#include "lpv/radiosity/VertexRadiosity.h"
#include "lpv/renderer/ShaderLibrary.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>

namespace lpv::renderer {

scene::Expected<RadiosityView> RadiosityView::create() {
    auto program = buildEmbeddedProgram({"radiosity_view.vert", "radiosity_view.frag"});
    if (!program)
        return std::unexpected(program.error());
    RadiosityView view;
    view.program_ = std::move(*program);
    return view;
}

void RadiosityView::setPatches(const radiosity::PatchMesh& mesh, std::span<const glm::vec3> perPatch,
                               bool smooth) {
    const std::vector<glm::vec3> corners = radiosity::cornerValues(mesh, perPatch, smooth);
    PatchDraw tris = uploadPatchVertices(patchTriangles(mesh, corners));
    PatchDraw lines = uploadPatchVertices(patchOutlines(mesh, corners));
    triangles_ = std::move(tris.buffer);
    triangleVao_ = std::move(tris.vao);
    triangleVertices_ = tris.vertices;
    lines_ = std::move(lines.buffer);
    lineVao_ = std::move(lines.vao);
    lineVertices_ = lines.vertices;
}

void RadiosityView::render(const scene::Camera& camera, int width, int height, float exposureEv,
                           bool wireframe) {
    if (width != width_ || height != height_ || !fbo_) {
        width_ = width;
        height_ = height;
        color_ = createTexture(GL_TEXTURE_2D);
        glTextureStorage2D(color_.id(), 1, GL_RGBA8, width, height);
        radiance_ = createTexture(GL_TEXTURE_2D);
        glTextureStorage2D(radiance_.id(), 1, GL_RGBA32F, width, height);
        depth_ = createTexture(GL_TEXTURE_2D);
        glTextureStorage2D(depth_.id(), 1, GL_DEPTH_COMPONENT32F, width, height);
        fbo_ = createFramebuffer();
        glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, color_.id(), 0);
        glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT1, radiance_.id(), 0);
        glNamedFramebufferTexture(fbo_.id(), GL_DEPTH_ATTACHMENT, depth_.id(), 0);
        const GLenum targets[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
        glNamedFramebufferDrawBuffers(fbo_.id(), 2, targets);
    }
    const float background[4] = {0.0f, 0.0f, 0.0f, 1.0f};
    const float farDepth = 1.0f;
    glClearNamedFramebufferfv(fbo_.id(), GL_COLOR, 0, background);
    glClearNamedFramebufferfv(fbo_.id(), GL_COLOR, 1, background);
    glClearNamedFramebufferfv(fbo_.id(), GL_DEPTH, 0, &farDepth);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    glViewport(0, 0, width, height);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    const glm::mat4 viewProj = camera.projection(float(width) / float(std::max(height, 1))) * camera.view();
    const GLuint prog = program_.id();
    glUseProgram(prog);
    glProgramUniformMatrix4fv(prog, glGetUniformLocation(prog, "uViewProj"), 1, GL_FALSE,
                              glm::value_ptr(viewProj));
    glProgramUniform1f(prog, glGetUniformLocation(prog, "uExposureScale"), std::exp2(exposureEv));
    glProgramUniform1i(prog, glGetUniformLocation(prog, "uFlat"), 0);
    if (triangleVertices_ > 0) {
        glBindVertexArray(triangleVao_.id());
        // Pushed back a little so the wireframe drawn on top wins the depth test.
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(1.0f, 1.0f);
        glDrawArrays(GL_TRIANGLES, 0, triangleVertices_);
        glDisable(GL_POLYGON_OFFSET_FILL);
    }
    if (wireframe && lineVertices_ > 0) {
        glProgramUniform1i(prog, glGetUniformLocation(prog, "uFlat"), 1);
        glProgramUniform3f(prog, glGetUniformLocation(prog, "uFlatColor"), 0.1f, 0.9f, 0.9f);
        glBindVertexArray(lineVao_.id());
        glDrawArrays(GL_LINES, 0, lineVertices_);
    }
    glBindVertexArray(0);
    glUseProgram(0);
    glDepthFunc(GL_LESS);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

std::vector<std::uint8_t> RadiosityView::readDisplay() const {
    std::vector<std::uint8_t> pixels(std::size_t(width_) * std::size_t(height_) * 4);
    if (!color_)
        return pixels;
    glGetTextureImage(color_.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(pixels.size()), pixels.data());
    flipRows(pixels, width_, height_, 4);
    return pixels;
}

std::vector<float> RadiosityView::readRadiance() const {
    std::vector<float> pixels(std::size_t(width_) * std::size_t(height_) * 4);
    if (!radiance_)
        return pixels;
    glGetTextureImage(radiance_.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(pixels.size() * sizeof(float)),
                      pixels.data());
    flipRows(pixels, width_, height_, 4);
    return pixels;
}

void RadiosityView::blitTo(GLuint framebuffer, int width, int height) const {
    if (!fbo_)
        return;
    glNamedFramebufferReadBuffer(fbo_.id(), GL_COLOR_ATTACHMENT0);
    glBlitNamedFramebuffer(fbo_.id(), framebuffer, 0, 0, width_, height_, 0, 0, width, height,
                           GL_COLOR_BUFFER_BIT, GL_LINEAR);
}

} // namespace lpv::renderer
