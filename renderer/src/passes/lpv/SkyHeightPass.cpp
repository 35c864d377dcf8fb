#include "passes/lpv/SkyHeightPass.h"

#include "lpv/renderer/DrawList.h"
#include "lpv/renderer/ShaderLibrary.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>

namespace lpv::renderer {

using scene::ErrorCode;
using scene::makeError;

float skyHeightMargin(const scene::Bounds& bounds) {
    if (bounds.empty())
        return 1.0f; // no scene to scale with; nothing is drawn either
    const glm::vec3 size = bounds.size();
    const float margin = 0.01f * std::max(size.y, 1e-3f * std::max(size.x, size.z));
    return margin > 0.0f && std::isfinite(margin) ? margin : 1.0f;
}

scene::Expected<SkyHeightPass> SkyHeightPass::create() {
    SkyHeightPass pass;
    // The shadow maps' programs: world-space vertices, one layer, alpha-masked cut-outs.
    auto program = buildEmbeddedProgram({"shadow.vert", "shadow.geom", "shadow.frag"}, {"SHADOW_LAYERS 1"});
    if (!program)
        return std::unexpected(program.error());
    pass.program_ = std::move(*program);
    return pass;
}

int SkyHeightPass::resolutionFor(int gridSize, int cascades) {
    const long long wanted = 2LL * gridSize * (1LL << std::clamp(cascades - 1, 0, 10));
    return int(std::clamp(wanted, 16LL, 2048LL));
}

scene::Expected<LpvSkyInput> SkyHeightPass::render(const FrameContext& frame, const SceneGpu& geometry,
                                                   const MaterialGpu& materials, const LpvCascade& coarsest,
                                                   int resolution) {
    if (resolution != size_) {
        GLint maxSize = 0;
        glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
        if (resolution > maxSize)
            return makeError(ErrorCode::OutOfRange, "render", "sky height map",
                             std::to_string(resolution) + " texels exceed GL_MAX_TEXTURE_SIZE " +
                                 std::to_string(maxSize));
        depth_ = createTexture(GL_TEXTURE_2D_ARRAY);
        glTextureStorage3D(depth_.id(), 1, GL_DEPTH_COMPONENT32F, resolution, resolution, 1);
        glTextureParameteri(depth_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTextureParameteri(depth_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glTextureParameteri(depth_.id(), GL_TEXTURE_COMPARE_MODE, GL_NONE);
        fbo_ = createFramebuffer();
        glNamedFramebufferTexture(fbo_.id(), GL_DEPTH_ATTACHMENT, depth_.id(), 0);
        glNamedFramebufferDrawBuffer(fbo_.id(), GL_NONE);
        glNamedFramebufferReadBuffer(fbo_.id(), GL_NONE);
        size_ = resolution;
    }
    const scene::Bounds bounds = frame.sceneBounds;
    const float margin = skyHeightMargin(bounds);
    LpvSkyInput out;
    out.depth = depth_.id();
    out.size = resolution;
    out.min = {coarsest.origin.x, coarsest.origin.z};
    out.texelSize = coarsest.extent() / float(resolution);
    out.top = std::max(bounds.max.y, coarsest.origin.y + coarsest.extent()) + margin;
    out.bottom = std::min(bounds.min.y, coarsest.origin.y) - margin;

    // Orthographic, straight down: world x -> NDC x, world z -> NDC y, and
    // depth (top - y) / (top - bottom), so depth 0 is the top and 1 the bottom.
    const float w = coarsest.extent(), h = out.top - out.bottom;
    glm::mat4 m(0.0f);
    m[0][0] = 2.0f / w;
    m[3][0] = -2.0f * out.min.x / w - 1.0f;
    m[2][1] = 2.0f / w;
    m[3][1] = -2.0f * out.min.y / w - 1.0f;
    m[1][2] = -2.0f / h;
    m[3][2] = 2.0f * out.top / h - 1.0f;
    m[3][3] = 1.0f;

    const GLuint p = program_.id();
    glUseProgram(p);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    glViewport(0, 0, resolution, resolution);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE); // the highest surface counts whichever way it faces
    glClearDepth(1.0);
    glClear(GL_DEPTH_BUFFER_BIT);
    glProgramUniform1i(p, glGetUniformLocation(p, "uLayerCount"), 1);
    glProgramUniform1i(p, glGetUniformLocation(p, "uFirstLayer"), 0);
    glProgramUniformMatrix4fv(p, glGetUniformLocation(p, "uLayerViewProj"), 1, GL_FALSE, glm::value_ptr(m));
    const auto items = buildDrawList(geometry.draws(), m, glm::vec3(0.0f));
    geometry.draw(p, items, [&](std::uint32_t material) { materials.bind(p, material, MaterialBindMode::Coverage); });
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return out;
}

} // namespace lpv::renderer
