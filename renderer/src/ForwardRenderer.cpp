#include "lpv/renderer/ForwardRenderer.h"

#include "lpv/renderer/ShaderLibrary.h"
#include "ShadowView.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace lpv::renderer {

using scene::ErrorCode;
using scene::makeError;

namespace {

constexpr int kMaxLights = 8;

GLint loc(GLuint program, const std::string& name) { return glGetUniformLocation(program, name.c_str()); }

int tonemapperIndex(const std::string& name) {
    if (name == "aces") return 0;
    if (name == "reinhard") return 1;
    if (name == "uncharted2") return 2;
    return 3;
}

} // namespace

struct ForwardRenderer::Impl {
    Program shadowProgram, forwardProgram, tonemapProgram;
    std::unique_ptr<SceneGpu> sceneGpu;
    GpuTimer timer;
    VertexArray emptyVao;

    int width = 0, height = 0;
    Texture hdrColor, depth, display;
    Framebuffer hdrFbo, displayFbo;

    int shadowSize = 0;
    Texture shadowMap;
    Framebuffer shadowFbo;

    Expected<void> ensureTargets(int w, int h) {
        GLint maxSize = 0;
        glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
        if (w <= 0 || h <= 0 || w > maxSize || h > maxSize)
            return makeError(ErrorCode::OutOfRange, "render", "size",
                             std::to_string(w) + "x" + std::to_string(h) + " is outside 1.." + std::to_string(maxSize) +
                                 " (GL_MAX_TEXTURE_SIZE)");
        if (w == width && h == height)
            return {};
        width = w;
        height = h;
        hdrColor = createTexture(GL_TEXTURE_2D);
        glTextureStorage2D(hdrColor.id(), 1, GL_RGBA16F, w, h);
        depth = createTexture(GL_TEXTURE_2D);
        glTextureStorage2D(depth.id(), 1, GL_DEPTH_COMPONENT32F, w, h);
        display = createTexture(GL_TEXTURE_2D);
        glTextureStorage2D(display.id(), 1, GL_RGBA8, w, h);
        for (GLuint t : {hdrColor.id(), display.id()}) {
            glTextureParameteri(t, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
            glTextureParameteri(t, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        }
        hdrFbo = createFramebuffer();
        glNamedFramebufferTexture(hdrFbo.id(), GL_COLOR_ATTACHMENT0, hdrColor.id(), 0);
        glNamedFramebufferTexture(hdrFbo.id(), GL_DEPTH_ATTACHMENT, depth.id(), 0);
        displayFbo = createFramebuffer();
        glNamedFramebufferTexture(displayFbo.id(), GL_COLOR_ATTACHMENT0, display.id(), 0);
        return checkTargets("HDR/display targets");
    }

    Expected<void> ensureShadowMap(int size) {
        GLint maxSize = 0;
        glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
        if (size > maxSize)
            return makeError(ErrorCode::OutOfRange, "render", "parameters.shadow.mapSize",
                             std::to_string(size) + " exceeds this GPU's GL_MAX_TEXTURE_SIZE " + std::to_string(maxSize));
        if (size == shadowSize)
            return {};
        shadowSize = size;
        shadowMap = createTexture(GL_TEXTURE_2D);
        glTextureStorage2D(shadowMap.id(), 1, GL_DEPTH_COMPONENT32F, size, size);
        glTextureParameteri(shadowMap.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTextureParameteri(shadowMap.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTextureParameteri(shadowMap.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTextureParameteri(shadowMap.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        glTextureParameteri(shadowMap.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
        glTextureParameteri(shadowMap.id(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
        shadowFbo = createFramebuffer();
        glNamedFramebufferTexture(shadowFbo.id(), GL_DEPTH_ATTACHMENT, shadowMap.id(), 0);
        glNamedFramebufferDrawBuffer(shadowFbo.id(), GL_NONE);
        return checkTargets("shadow map");
    }

    static Expected<void> checkTargets(const char* what) {
        if (glGetError() == GL_OUT_OF_MEMORY)
            return makeError(ErrorCode::OutOfRange, "render", what, "the GPU ran out of memory allocating it");
        return {};
    }

    void drawScene(GLuint program, const scene::Scene& scene, bool withMaterials) {
        sceneGpu->bindGeometry();
        const GLint model = loc(program, "uModel");
        const GLint normalMatrix = loc(program, "uNormalMatrix");
        for (const DrawItem& d : sceneGpu->draws()) {
            glProgramUniformMatrix4fv(program, model, 1, GL_FALSE, glm::value_ptr(d.model));
            if (withMaterials) {
                glProgramUniformMatrix3fv(program, normalMatrix, 1, GL_FALSE, glm::value_ptr(d.normalMatrix));
                const scene::Material& m = d.material < scene.materials.size() ? scene.materials[d.material]
                                                                               : scene::Material{};
                glProgramUniform3fv(program, loc(program, "uDiffuse"), 1, glm::value_ptr(m.diffuseColor));
                glProgramUniform3fv(program, loc(program, "uSpecular"), 1, glm::value_ptr(m.specularColor));
                glProgramUniform1f(program, loc(program, "uShininess"), std::max(m.shininess, 1.0f));
                glProgramUniform3fv(program, loc(program, "uEmissive"), 1, glm::value_ptr(m.emissive));
                glProgramUniform1i(program, loc(program, "uTwoSided"), m.twoSided ? 1 : 0);
            }
            glDrawElementsBaseVertex(GL_TRIANGLES, d.indexCount, GL_UNSIGNED_INT,
                                     reinterpret_cast<const void*>(d.indexByteOffset), d.baseVertex);
        }
    }
};

ForwardRenderer::ForwardRenderer() : impl_(std::make_unique<Impl>()) {}
ForwardRenderer::ForwardRenderer(ForwardRenderer&&) noexcept = default;
ForwardRenderer& ForwardRenderer::operator=(ForwardRenderer&&) noexcept = default;
ForwardRenderer::~ForwardRenderer() = default;

Expected<ForwardRenderer> ForwardRenderer::create() {
    ForwardRenderer r;
    auto shadow = buildEmbeddedProgram({"shadow.vert", "shadow.frag"});
    if (!shadow) return std::unexpected(shadow.error());
    auto forward = buildEmbeddedProgram({"forward.vert", "forward.frag"});
    if (!forward) return std::unexpected(forward.error());
    auto tonemap = buildEmbeddedProgram({"fullscreen.vert", "tonemap.frag"});
    if (!tonemap) return std::unexpected(tonemap.error());
    r.impl_->shadowProgram = std::move(*shadow);
    r.impl_->forwardProgram = std::move(*forward);
    r.impl_->tonemapProgram = std::move(*tonemap);
    r.impl_->emptyVao = createVertexArray();
    return r;
}

void ForwardRenderer::setScene(const scene::Scene& scene) { impl_->sceneGpu = std::make_unique<SceneGpu>(scene); }

GpuTimer& ForwardRenderer::timer() { return impl_->timer; }
int ForwardRenderer::width() const { return impl_->width; }
int ForwardRenderer::height() const { return impl_->height; }

Expected<void> ForwardRenderer::render(const scene::Scene& scene, const scene::ParameterSet& params,
                                       const scene::Camera& camera, int width, int height) {
    Impl& d = *impl_;
    if (!d.sceneGpu)
        setScene(scene);
    if (auto ok = d.ensureTargets(width, height); !ok)
        return ok;
    d.timer.beginFrame();

    // --- Shadow map for the first shadow-casting directional or spot light ---
    const int shadowLight = findShadowLight(scene);
    ShadowView shadowView;
    if (shadowLight >= 0) {
        if (auto ok = d.ensureShadowMap(params.getInt("shadow.mapSize")); !ok)
            return ok;
        shadowView = makeShadowView(scene.lights[std::size_t(shadowLight)], scene.worldBounds(), d.shadowSize);
        d.timer.begin("shadowMap");
        glBindFramebuffer(GL_FRAMEBUFFER, d.shadowFbo.id());
        glViewport(0, 0, d.shadowSize, d.shadowSize);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glDisable(GL_CULL_FACE); // one-sided walls (the Cornell box) must still cast shadows
        glClear(GL_DEPTH_BUFFER_BIT);
        // Slope-scaled depth bias: receivers nearly parallel to the light's rays
        // (the Cornell walls under a ceiling light) otherwise show acne stripes.
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(2.0f, 2.0f);
        glUseProgram(d.shadowProgram.id());
        glProgramUniformMatrix4fv(d.shadowProgram.id(), loc(d.shadowProgram.id(), "uLightViewProj"), 1, GL_FALSE,
                                  glm::value_ptr(shadowView.viewProj));
        d.drawScene(d.shadowProgram.id(), scene, false);
        glDisable(GL_POLYGON_OFFSET_FILL);
        d.timer.end("shadowMap");
    }

    // --- Forward pass into HDR ---
    d.timer.begin("forward");
    const GLuint fp = d.forwardProgram.id();
    glBindFramebuffer(GL_FRAMEBUFFER, d.hdrFbo.id());
    glViewport(0, 0, width, height);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);
    const glm::vec3 sky = scene.sky.color * scene.sky.intensity;
    glClearColor(sky.r, sky.g, sky.b, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glUseProgram(fp);
    const glm::mat4 viewProj = camera.projection(float(width) / float(height)) * camera.view();
    glProgramUniformMatrix4fv(fp, loc(fp, "uViewProj"), 1, GL_FALSE, glm::value_ptr(viewProj));
    glProgramUniform3fv(fp, loc(fp, "uCameraPos"), 1, glm::value_ptr(camera.position));
    const int lightCount = std::min<int>(int(scene.lights.size()), kMaxLights);
    glProgramUniform1i(fp, loc(fp, "uLightCount"), lightCount);
    for (int i = 0; i < lightCount; ++i) {
        const scene::Light& l = scene.lights[std::size_t(i)];
        const std::string idx = "[" + std::to_string(i) + "]";
        glProgramUniform1i(fp, loc(fp, "uLightType" + idx), int(l.type));
        const glm::vec3 radiant = l.color * l.intensity;
        glProgramUniform3fv(fp, loc(fp, "uLightRadiantColor" + idx), 1, glm::value_ptr(radiant));
        glProgramUniform3fv(fp, loc(fp, "uLightPosition" + idx), 1, glm::value_ptr(l.position));
        glProgramUniform3fv(fp, loc(fp, "uLightDirection" + idx), 1, glm::value_ptr(l.direction));
        glProgramUniform1f(fp, loc(fp, "uLightRange" + idx), l.range);
        glProgramUniform2f(fp, loc(fp, "uLightCosCone" + idx), std::cos(l.outerConeAngle),
                           std::cos(std::min(l.innerConeAngle, l.outerConeAngle - 1e-3f)));
    }
    glProgramUniform1i(fp, loc(fp, "uShadowLight"), shadowLight);
    glProgramUniformMatrix4fv(fp, loc(fp, "uShadowViewProj"), 1, GL_FALSE, glm::value_ptr(shadowView.viewProj));
    glProgramUniform1f(fp, loc(fp, "uShadowTexel"), shadowView.texelWorld);
    glProgramUniform1i(fp, loc(fp, "uShadowPerspective"), shadowView.perspective ? 1 : 0);
    glProgramUniform1f(fp, loc(fp, "uShadowBias"), params.getFloat("shadow.bias"));
    glProgramUniform1f(fp, loc(fp, "uShadowSoftness"), params.getFloat("shadow.softness"));
    glProgramUniform1i(fp, loc(fp, "uShadowMap"), 0);
    glBindTextureUnit(0, d.shadowMap.id());
    d.drawScene(fp, scene, true);
    d.timer.end("forward");

    // --- Tonemap to the display target ---
    d.timer.begin("tonemap");
    const GLuint tp = d.tonemapProgram.id();
    glBindFramebuffer(GL_FRAMEBUFFER, d.displayFbo.id());
    glViewport(0, 0, width, height);
    glDisable(GL_DEPTH_TEST);
    glUseProgram(tp);
    glProgramUniform1f(tp, loc(tp, "uExposure"), std::exp2(params.getFloat("output.exposure")));
    glProgramUniform1i(tp, loc(tp, "uOperator"), tonemapperIndex(params.getEnum("output.tonemapper")));
    glProgramUniform1i(tp, loc(tp, "uHdr"), 0);
    glBindTextureUnit(0, d.hdrColor.id());
    glBindVertexArray(d.emptyVao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    d.timer.end("tonemap");

    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (GLenum err = glGetError(); err != GL_NO_ERROR)
        return makeError(ErrorCode::IoError, "render", "OpenGL", "GL error 0x" + std::to_string(err) + " during the frame");
    return {};
}

void ForwardRenderer::blitTo(GLuint framebuffer, int width, int height) const {
    glBlitNamedFramebuffer(impl_->displayFbo.id(), framebuffer, 0, 0, impl_->width, impl_->height, 0, 0, width, height,
                           GL_COLOR_BUFFER_BIT, GL_LINEAR);
}

namespace {

template <class T>
void flipRows(std::vector<T>& pixels, int width, int height, int channels) {
    const std::size_t row = std::size_t(width) * std::size_t(channels);
    for (int y = 0; y < height / 2; ++y)
        std::swap_ranges(pixels.begin() + std::ptrdiff_t(std::size_t(y) * row),
                         pixels.begin() + std::ptrdiff_t(std::size_t(y + 1) * row),
                         pixels.begin() + std::ptrdiff_t(std::size_t(height - 1 - y) * row));
}

} // namespace

std::vector<float> ForwardRenderer::readHdr() const {
    std::vector<float> px(std::size_t(impl_->width) * std::size_t(impl_->height) * 4);
    glGetTextureImage(impl_->hdrColor.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(px.size() * sizeof(float)), px.data());
    flipRows(px, impl_->width, impl_->height, 4);
    return px;
}

std::vector<std::uint8_t> ForwardRenderer::readDisplay() const {
    std::vector<std::uint8_t> px(std::size_t(impl_->width) * std::size_t(impl_->height) * 4);
    glGetTextureImage(impl_->display.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(px.size()), px.data());
    flipRows(px, impl_->width, impl_->height, 4);
    return px;
}

} // namespace lpv::renderer
