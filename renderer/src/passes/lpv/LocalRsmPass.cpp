#include "passes/lpv/LocalRsmPass.h"

#include "frame/FrameResources.h"
#include "gl/GpuMemoryLedger.h"
#include "lpv/scene/AreaLight.h"

#include "passes/direct/ShadowLights.h"
#include "lpv/renderer/DrawList.h"
#include "lpv/renderer/ShaderLibrary.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace lpv::renderer {

using scene::ErrorCode;
using scene::makeError;

namespace {

// The axis of each face of a point light's cube, in pointShadowView's order; a spot's is its direction.
constexpr glm::vec3 kCubeAxes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};

} // namespace

std::vector<int> selectInjectedLocalLights(const scene::Scene& scene) {
    std::vector<int> out;
    for (int i = 0; i < int(scene.lights.size()) && i < kMaxShadedLights; ++i) {
        const scene::Light& l = scene.lights[std::size_t(i)];
        if (l.type == scene::LightType::Directional || l.intensity <= 0.0f)
            continue;
        if (int(out.size()) < kMaxInjectedLocalLights)
            out.push_back(i);
    }
    return out;
}

scene::Expected<LocalRsmPass> LocalRsmPass::create() {
    LocalRsmPass pass;
    // One face per draw (a single layer attached), so rsm.geom runs one invocation.
    auto program = buildEmbeddedProgram({"rsm.vert", "rsm.geom", "rsm_local.frag"}, {"RSM_TILES 1"});
    if (!program)
        return std::unexpected(program.error());
    pass.program_ = std::move(*program);
    return pass;
}

void LocalRsmPass::release() {
    targets_.release();
    lights_ = 0;
}

scene::Expected<void> LocalRsmPass::ensureTargets(int size, int layers) {
    if (targets_.holds(size, layers))
        return {};
    release();
    GLint maxLayers = 0, maxSize = 0;
    glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &maxLayers);
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    if (size > maxSize || layers > maxLayers)
        return makeError(ErrorCode::OutOfRange, "render", "parameters.lpv.localRsmSize",
                         std::to_string(layers) + " local RSM faces of " + std::to_string(size) +
                             "^2 exceed GL_MAX_TEXTURE_SIZE " + std::to_string(maxSize) +
                             " or GL_MAX_ARRAY_TEXTURE_LAYERS " + std::to_string(maxLayers));
    if (!targets_.allocate(size, layers))
        return makeError(ErrorCode::OutOfRange, "render", "parameters.lpv.localRsmSize",
                         "the GPU ran out of memory allocating " + std::to_string(layers) +
                             " local RSM faces of " + std::to_string(size) + "^2");
    return {};
}

scene::Expected<void> LocalRsmPass::render(const FrameContext& frame, const SceneGpu& geometry,
                                           const MaterialGpu& materials, int size) {
    const std::vector<int> lights = selectInjectedLocalLights(frame.scene);
    int layers = 0;
    for (int i : lights)
        layers += frame.scene.lights[std::size_t(i)].type == scene::LightType::Spot ? 1 : 6;
    if (layers == 0) {
        release();
        return {};
    }
    if (auto ok = ensureTargets(size, layers); !ok)
        return ok;
    lights_ = int(lights.size());

    const GLuint p = program_.id();
    auto loc = [&](const char* name) { return glGetUniformLocation(p, name); };
    const scene::Bounds bounds = frame.sceneBounds;
    targets_.bindForDrawing();
    glUseProgram(p);
    int layer = 0;
    for (int index : lights) {
        const scene::Light& light = frame.scene.lights[std::size_t(index)];
        const bool spot = light.type == scene::LightType::Spot;
        const LocalShadowView view = spot ? spotShadowView(light, bounds) : pointShadowView(light, bounds);
        // The texel's area on the image plane at distance 1 (rsm_local.frag's derivation).
        const float texel = 2.0f * view.tanHalfFov / float(size);
        const float texelArea = texel * texel;
        const glm::vec3 spotDirection = glm::normalize(light.direction);
        // An area light is seen from its centre as a point of intensity L A cos(theta) (rsm_local.frag).
        const bool area = light.type == scene::LightType::Area;
        const glm::vec3 radiant =
            area ? scene::areaLightRadiance(light) * scene::areaLightArea(light) : light.color * light.intensity;
        glProgramUniform1i(p, loc("uArea"), area ? 1 : 0);
        glProgramUniform1i(p, loc("uTwoSided"), light.twoSided ? 1 : 0);
        glProgramUniform1fv(p, loc("uTexelArea"), 1, &texelArea);
        glProgramUniform3fv(p, loc("uLightPosition"), 1, glm::value_ptr(light.position));
        glProgramUniform3fv(p, loc("uSpotDirection"), 1, glm::value_ptr(spotDirection));
        glProgramUniform1i(p, loc("uSpot"), spot ? 1 : 0);
        glProgramUniform2f(p, loc("uCosCone"), std::cos(light.outerConeAngle),
                           std::cos(std::min(light.innerConeAngle, light.outerConeAngle - 1e-3f)));
        glProgramUniform1f(p, loc("uRange"), light.range);
        glProgramUniform3fv(p, loc("uRadiantIntensity"), 1, glm::value_ptr(radiant));
        for (int face = 0; face < view.faces; ++face, ++layer) {
            targets_.attachLayer(layer);
            targets_.clear();
            const glm::mat4& viewProj = view.viewProj[std::size_t(face)];
            const glm::vec3 axis = spot ? spotDirection : kCubeAxes[face];
            glProgramUniformMatrix4fv(p, loc("uTileViewProj"), 1, GL_FALSE, glm::value_ptr(viewProj));
            glProgramUniform3fv(p, loc("uFaceAxis"), 1, glm::value_ptr(axis));
            const auto items = buildDrawList(geometry.draws(), viewProj, light.position);
            geometry.draw(p, items,
                          [&](std::uint32_t m) { materials.bind(p, m, MaterialBindMode::Reflectance); });
        }
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return {};
}

std::vector<DebugImage> LocalRsmPass::debugImages() const {
    return targets_.debugImages("localrsm", targets_.layers());
}

void LocalRsmPass::addGpuMemory(GpuMemoryLedger& ledger) const {
    ledger.addTexture(resources::LocalRsmPosition.name(), targets_.position());
    ledger.addTexture(resources::LocalRsmNormal.name(), targets_.normal());
    ledger.addTexture(resources::LocalRsmFlux.name(), targets_.flux());
    ledger.addTexture("localRsm.depth", targets_.depth());
}

} // namespace lpv::renderer
