#include "ShadowPass.h"

#include "lpv/renderer/ShaderLibrary.h"

#include <glm/gtc/type_ptr.hpp>

#include <string>

namespace lpv::renderer {

using scene::ErrorCode;
using scene::makeError;

scene::Expected<ShadowPass> ShadowPass::create() {
    auto program = buildEmbeddedProgram({"shadow.vert", "shadow.frag"});
    if (!program)
        return std::unexpected(program.error());
    ShadowPass pass;
    pass.depthProgram_ = std::move(*program);
    return pass;
}

scene::Expected<void> ShadowPass::ensureMap(int size) {
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    if (size > maxSize)
        return makeError(ErrorCode::OutOfRange, "render", "parameters.shadow.mapSize",
                         std::to_string(size) + " exceeds this GPU's GL_MAX_TEXTURE_SIZE " + std::to_string(maxSize));
    if (size == size_)
        return {};
    size_ = size;
    map_ = createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(map_.id(), 1, GL_DEPTH_COMPONENT32F, size, size);
    glTextureParameteri(map_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(map_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(map_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(map_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTextureParameteri(map_.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTextureParameteri(map_.id(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    fbo_ = createFramebuffer();
    glNamedFramebufferTexture(fbo_.id(), GL_DEPTH_ATTACHMENT, map_.id(), 0);
    glNamedFramebufferDrawBuffer(fbo_.id(), GL_NONE);
    if (glGetError() == GL_OUT_OF_MEMORY)
        return makeError(ErrorCode::OutOfRange, "render", "shadow map", "the GPU ran out of memory allocating it");
    return {};
}

scene::Expected<void> ShadowPass::render(const FrameContext& frame, const SceneGpu& geometry,
                                         const MaterialGpu& materials) {
    lightIndex_ = findShadowLight(frame.scene);
    if (lightIndex_ < 0)
        return {};
    if (auto ok = ensureMap(frame.params.getInt("shadow.mapSize")); !ok)
        return ok;
    view_ = makeShadowView(frame.scene.lights[std::size_t(lightIndex_)], frame.scene.worldBounds(), size_);
    frame.timer.begin("shadowMap");
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    glViewport(0, 0, size_, size_);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE); // one-sided walls (the Cornell box) must still cast shadows
    glClear(GL_DEPTH_BUFFER_BIT);
    // Slope-scaled depth bias: receivers nearly parallel to the light's rays
    // (the Cornell walls under a ceiling light) otherwise show acne stripes.
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(2.0f, 2.0f);
    const GLuint p = depthProgram_.id();
    glUseProgram(p);
    glProgramUniformMatrix4fv(p, glGetUniformLocation(p, "uLightViewProj"), 1, GL_FALSE,
                              glm::value_ptr(view_.viewProj));
    const auto items = buildDrawList(geometry.draws(), view_.viewProj, glm::vec3(0.0f));
    geometry.draw(p, items, [&](std::uint32_t m) { materials.bind(p, m, MaterialBindMode::Coverage); });
    glDisable(GL_POLYGON_OFFSET_FILL);
    frame.timer.end("shadowMap");
    return {};
}

int ShadowPass::bindForShading(GLuint program, const FrameContext& frame, int firstUnit) const {
    auto loc = [&](const char* name) { return glGetUniformLocation(program, name); };
    glProgramUniform1i(program, loc("uShadowLight"), lightIndex_);
    glProgramUniformMatrix4fv(program, loc("uShadowViewProj"), 1, GL_FALSE, glm::value_ptr(view_.viewProj));
    glProgramUniform1f(program, loc("uShadowTexel"), view_.texelWorld);
    glProgramUniform1i(program, loc("uShadowPerspective"), view_.perspective ? 1 : 0);
    glProgramUniform1f(program, loc("uShadowBias"), frame.params.getFloat("shadow.bias"));
    glProgramUniform1f(program, loc("uShadowSoftness"), frame.params.getFloat("shadow.softness"));
    glProgramUniform1i(program, loc("uShadowMap"), firstUnit);
    glBindTextureUnit(GLuint(firstUnit), map_.id());
    return firstUnit + 1;
}

std::vector<DebugImage> ShadowPass::debugImages() const {
    if (lightIndex_ < 0 || size_ == 0)
        return {};
    DebugImage image{"shadow-map", size_, size_, 1, {}};
    image.pixels.resize(std::size_t(size_) * std::size_t(size_));
    glGetTextureImage(map_.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, GLsizei(image.pixels.size() * sizeof(float)),
                      image.pixels.data());
    return {image};
}

} // namespace lpv::renderer
