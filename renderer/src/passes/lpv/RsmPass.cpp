#include "passes/lpv/RsmPass.h"

#include "lpv/renderer/ShaderLibrary.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <array>
#include <cstdio>
#include <string>

namespace lpv::renderer {

using scene::ErrorCode;
using scene::makeError;

namespace {

std::string hex(GLenum value) {
    char text[16];
    std::snprintf(text, sizeof text, "0x%04X", unsigned(value));
    return text;
}

GLint getInt(GLenum name) {
    GLint v = 0;
    glGetIntegerv(name, &v);
    return v;
}

} // namespace

RsmTargetLimits RsmTargetLimits::query() {
    return {getInt(GL_MAX_TEXTURE_SIZE), getInt(GL_MAX_ARRAY_TEXTURE_LAYERS),
            getInt(GL_MAX_FRAMEBUFFER_LAYERS),
            std::min(getInt(GL_MAX_FRAMEBUFFER_WIDTH), getInt(GL_MAX_FRAMEBUFFER_HEIGHT))};
}

scene::Expected<void> checkRsmTargets(int tileSize, int tiles, const RsmTargetLimits& limits) {
    const int maxSize = std::min(limits.maxTextureSize, limits.maxFramebufferSize);
    if (tileSize < 1 || tileSize > maxSize)
        return makeError(ErrorCode::OutOfRange, "render", "parameters.rsm.tileSize",
                         std::to_string(tileSize) + " exceeds this GPU's largest render target " +
                             std::to_string(maxSize) +
                             " (GL_MAX_TEXTURE_SIZE, GL_MAX_FRAMEBUFFER_WIDTH/HEIGHT)");
    const int maxLayers = std::min({limits.maxArrayLayers, limits.maxFramebufferLayers, kMaxRsmCascades});
    if (tiles < 1 || tiles > maxLayers)
        return makeError(
            ErrorCode::OutOfRange, "render", "parameters.rsm.cascades",
            std::to_string(tiles) + " tiles; this GPU renders 1.." + std::to_string(maxLayers) +
                " in one layered pass (GL_MAX_ARRAY_TEXTURE_LAYERS, GL_MAX_FRAMEBUFFER_LAYERS, " +
                std::to_string(kMaxRsmCascades) + " geometry-shader invocations)");
    return {};
}

scene::Expected<GLuint> RsmPass::perTileProgram() {
    if (!perTileProgram_) {
        auto built = buildEmbeddedProgram({"rsm.vert", "rsm.frag"}, {"RSM_NO_GEOMETRY_SHADER 1"});
        if (!built)
            return std::unexpected(built.error());
        perTileProgram_ = std::move(*built);
    }
    return perTileProgram_.id();
}

scene::Expected<GLuint> RsmPass::programFor(int tiles) {
    if (tiles < 1 || tiles > kMaxRsmCascades)
        return makeError(ErrorCode::OutOfRange, "render", "parameters.rsm.cascades",
                         std::to_string(tiles) + " is outside 1.." + std::to_string(kMaxRsmCascades));
    Program& program = programs_[std::size_t(tiles - 1)];
    if (program)
        return program.id();
    auto built = buildEmbeddedProgram({"rsm.vert", "rsm.geom", "rsm.frag"}, {"RSM_TILES " + std::to_string(tiles)});
    if (!built)
        return std::unexpected(built.error());
    program = std::move(*built);
    return program.id();
}

scene::Expected<RsmPass> RsmPass::create() {
    // Build the default count now, so that a shader error shows when the renderer is made.
    RsmPass pass;
    if (auto program = pass.programFor(4); !program)
        return std::unexpected(program.error());
    return pass;
}

void RsmPass::releaseTargets() { targets_.release(); }

scene::Expected<void> RsmPass::ensureTargets(int tileSize, int layers) {
    if (auto ok = checkRsmTargets(tileSize, layers, RsmTargetLimits::query()); !ok)
        return ok;
    if (targets_.holds(tileSize, layers))
        return {};
    const std::string what = std::to_string(layers) + " RSM tiles of " + std::to_string(tileSize) + "^2 (" +
                             std::to_string(std::size_t(tileSize) * std::size_t(tileSize) * std::size_t(layers) *
                                            RsmTargets::kBytesPerTexel / (1024 * 1024)) +
                             " MiB)";
    if (!targets_.allocate(tileSize, layers))
        return makeError(ErrorCode::OutOfRange, "render", "parameters.rsm.tileSize",
                         "the GPU ran out of memory allocating " + what);
    // Whole arrays attached: a layered framebuffer, gl_Layer picks the tile.
    targets_.attachAllLayers();
    if (const GLenum status = glCheckNamedFramebufferStatus(targets_.framebuffer(), GL_FRAMEBUFFER);
        status != GL_FRAMEBUFFER_COMPLETE) {
        releaseTargets();
        return makeError(ErrorCode::OutOfRange, "render", "parameters.rsm.tileSize",
                         "the framebuffer of " + what + " is incomplete (status " + hex(status) + ")");
    }
    return {};
}

scene::Expected<void> RsmPass::render(const FrameContext& frame, const SceneGpu& geometry,
                                      const MaterialGpu& materials) {
    const int count = frame.params.getInt("rsm.cascades");
    return render(frame, geometry, materials,
                  lpvCascades(frame.camera.position, frame.camera.target - frame.camera.position,
                              lpvCascadeSettings(frame.params, count, frame.sceneBounds)));
}

scene::Expected<void> RsmPass::render(const FrameContext& frame, const SceneGpu& geometry,
                                      const MaterialGpu& materials, const std::vector<LpvCascade>& cascades) {
    sunIndex_ = findSun(frame.scene);
    tiles_.clear();
    if (sunIndex_ < 0) {
        releaseTargets();
        return {};
    }
    const int count = int(cascades.size());
    const int size = frame.params.getInt("rsm.tileSize");
    if (auto ok = ensureTargets(size, count); !ok) {
        sunIndex_ = -1;
        return ok;
    }
    const bool perTile = frame.params.getEnum("rsm.tileDraws") == "perTile";
    const auto program = perTile ? perTileProgram() : programFor(count);
    if (!program) {
        sunIndex_ = -1;
        return std::unexpected(program.error());
    }

    const scene::Light& sun = frame.scene.lights[std::size_t(sunIndex_)];
    const scene::Bounds sceneBounds = frame.sceneBounds;
    std::array<glm::mat4, kMaxRsmCascades> viewProj{};
    std::array<float, kMaxRsmCascades> texelArea{};
    for (const LpvCascade& cascade : cascades) {
        tiles_.push_back(makeRsmTile(cascade, sun.direction, sceneBounds, size));
        viewProj[tiles_.size() - 1] = tiles_.back().viewProj;
        texelArea[tiles_.size() - 1] = tiles_.back().texelArea;
    }

    targets_.bindForDrawing();
    const glm::vec3 irradiance = sun.color * sun.intensity;
    const GLuint p = *program;
    auto loc = [&](const char* name) { return glGetUniformLocation(p, name); };
    glUseProgram(p);
    glProgramUniform3fv(p, loc("uSunIrradiance"), 1, glm::value_ptr(irradiance));
    if (perTile) {
        // Each tile attaches its layer of the four arrays, culls with its own
        // box and draws only what it holds: no geometry-shader broadcast.
        for (std::size_t k = 0; k < tiles_.size(); ++k) {
            targets_.attachLayer(int(k));
            targets_.clear();
            glProgramUniformMatrix4fv(p, loc("uViewProj"), 1, GL_FALSE, glm::value_ptr(tiles_[k].viewProj));
            glProgramUniform1f(p, loc("uTileTexelArea"), tiles_[k].texelArea);
            const auto items = buildDrawList(geometry.draws(), tiles_[k].viewProj, frame.camera.position);
            geometry.draw(p, items, [&](std::uint32_t m) { materials.bind(p, m, MaterialBindMode::Reflectance); });
        }
        targets_.attachAllLayers(); // layered again
    } else {
        targets_.clear();
        glProgramUniformMatrix4fv(p, loc("uTileViewProj"), count, GL_FALSE, glm::value_ptr(viewProj[0]));
        glProgramUniform1fv(p, loc("uTexelArea"), count, texelArea.data());
        // Culled once against the box that holds every tile; rsm.geom drops a
        // triangle from the tiles it misses.
        const auto items = buildDrawList(geometry.draws(), rsmUnionViewProj(tiles_), frame.camera.position);
        geometry.draw(p, items, [&](std::uint32_t m) { materials.bind(p, m, MaterialBindMode::Reflectance); });
    }
    return {};
}

std::vector<DebugImage> RsmPass::debugImages() const {
    if (!active())
        return {};
    return targets_.debugImages("rsm", int(tiles_.size()));
}

} // namespace lpv::renderer
