#include "passes/lpv/LpvSubsurfacePass.h"

#include "frame/FrameResources.h"
#include "gl/GpuMemoryLedger.h"
#include "lpv/renderer/ShaderLibrary.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>

namespace lpv::renderer {

namespace {

GLuint groups(int count, int size) {
    return GLuint((count + size - 1) / size);
}
GLint loc(GLuint program, const char* name) {
    return glGetUniformLocation(program, name);
}

// The SSBO bindings of lpv_common.glsl's fixed point (as LpvPass binds them).
constexpr GLuint kSumsBinding = 0, kScalesBinding = 1;
constexpr GLbitfield kComputeResults =
    GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT;

} // namespace

LpvSubsurfaceSettings LpvSubsurfaceSettings::fromParameters(const scene::ParameterSet& params) {
    LpvSubsurfaceSettings s;
    s.steps = params.getInt("effects.subsurfaceSteps");
    s.attenuation = float(params.getFloat("effects.subsurfaceAttenuation"));
    return s;
}

scene::Expected<LpvSubsurfacePass> LpvSubsurfacePass::create() {
    LpvSubsurfacePass pass;
    struct Build {
        Program* target;
        const char* file;
    };
    for (const Build& b : {Build{&pass.inject_, "lpv_subsurface_inject.comp"},
                           Build{&pass.resolve_, "lpv_subsurface_resolve.comp"},
                           Build{&pass.gather_, "lpv_subsurface_gather.comp"}}) {
        auto program = buildEmbeddedProgram({b.file});
        if (!program)
            return std::unexpected(program.error());
        *b.target = std::move(*program);
    }
    return pass;
}

void LpvSubsurfacePass::ensureVolumes(int gridSize, int cascades) {
    if (gridSize == gridSize_ && cascades == cascades_)
        return;
    auto make = [&](Texture& t) {
        t = createTexture(GL_TEXTURE_3D);
        glTextureStorage3D(t.id(), 1, GL_RGBA32F, 3 * gridSize, gridSize, gridSize * cascades);
        // Linear for the shading lookup, which clamps inside each channel's block.
        glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
            glTextureParameteri(t.id(), wrap, GL_CLAMP_TO_EDGE);
    };
    make(volume_[0]);
    make(volume_[1]);
    make(accumulator_);
    gridSize_ = gridSize;
    cascades_ = cascades;
}

std::size_t LpvSubsurfacePass::allocatedBytes() const {
    const std::size_t texels =
        3 * std::size_t(gridSize_) * std::size_t(gridSize_) * std::size_t(gridSize_) * std::size_t(cascades_);
    return 3 * texels * 16; // two ping-pong volumes and the accumulator, RGBA32F
}

void LpvSubsurfacePass::setCascadeUniforms(GLuint program, const LpvPass& lpv) const {
    std::array<glm::vec3, 6> origin{};
    std::array<float, 6> cellSize{};
    const auto& cascades = lpv.cascades();
    for (std::size_t k = 0; k < cascades.size() && k < 6; ++k) {
        origin[k] = cascades[k].origin;
        cellSize[k] = cascades[k].cellSize;
    }
    glProgramUniform1i(program, loc(program, "uGridSize"), gridSize_);
    glProgramUniform1i(program, loc(program, "uCascades"), cascades_);
    glProgramUniform3fv(program, loc(program, "uOrigin"), 6, glm::value_ptr(origin[0]));
    glProgramUniform1fv(program, loc(program, "uCellSize"), 6, cellSize.data());
}

void LpvSubsurfacePass::run(const LpvSubsurfaceSettings& settings, const LpvPass& lpv, const LpvRsmInput& rsm) {
    const LpvVolumes& volumes = lpv.volumes();
    ensureVolumes(volumes.gridSize(), volumes.cascades());
    steps_ = settings.steps;
    const int n = gridSize_, k = cascades_;

    // The LPV's sums are all zero again after its resolves; its scale [k] is
    // this frame's brightest texel per tile, which bounds flux * translucency too.
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kSumsBinding, volumes.lpvSums.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kScalesBinding, volumes.scales.id());
    GLuint p = inject_.id();
    glUseProgram(p);
    setCascadeUniforms(p, lpv);
    glBindTextureUnit(0, rsm.position);
    glBindTextureUnit(1, rsm.flux);
    glBindTextureUnit(2, rsm.normal);
    glProgramUniform1i(p, loc(p, "uRsmPosition"), 0);
    glProgramUniform1i(p, loc(p, "uRsmFlux"), 1);
    glProgramUniform1i(p, loc(p, "uRsmNormal"), 2);
    glProgramUniform1i(p, loc(p, "uTexelsPerTile"), rsm.tileSize * rsm.tileSize);
    glProgramUniform1i(p, loc(p, "uScaleSlot"), -1);
    glDispatchCompute(groups(rsm.tileSize, 8), groups(rsm.tileSize, 8), GLuint(k));
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

    p = resolve_.id();
    glUseProgram(p);
    setCascadeUniforms(p, lpv);
    glProgramUniform1i(p, loc(p, "uTexelsPerTile"), rsm.tileSize * rsm.tileSize);
    glProgramUniform1i(p, loc(p, "uScaleSlot"), -1);
    glBindImageTexture(0, volume_[0].id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glBindImageTexture(1, accumulator_.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glDispatchCompute(groups(n, 4), groups(n, 4), groups(n * k, 4));
    glMemoryBarrier(kComputeResults);

    p = gather_.id();
    glUseProgram(p);
    setCascadeUniforms(p, lpv);
    glProgramUniform1f(p, loc(p, "uKeep"), 1.0f - settings.attenuation);
    int read = 0;
    for (int step = 0; step < settings.steps; ++step) {
        const int write = 1 - read;
        // Cleared so that the gather need not store the cells that receive nothing.
        glClearTexImage(volume_[std::size_t(write)].id(), 0, GL_RGBA, GL_FLOAT, nullptr);
        glBindTextureUnit(0, volume_[std::size_t(read)].id());
        glBindImageTexture(0, volume_[std::size_t(write)].id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
        glBindImageTexture(1, accumulator_.id(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_RGBA32F);
        glDispatchCompute(groups(n, 8), groups(n, 8), GLuint(n * k));
        glMemoryBarrier(kComputeResults);
        read = write;
    }
}

void LpvSubsurfacePass::bindForShading(const CachedProgram& program, GLuint unit) const {
    glProgramUniform1i(program.id(), program.uniform("uLpvSubsurface"), 1);
    glProgramUniform1i(program.id(), program.uniform("uLpvSubsurfaceVolume"), GLint(unit));
    glBindTextureUnit(unit, accumulator_.id());
}

void LpvSubsurfacePass::bindNone(const CachedProgram& program, GLuint unit) {
    glProgramUniform1i(program.id(), program.uniform("uLpvSubsurface"), 0);
    // The sampler must still name a 3D texture unit of its own; nothing reads it.
    glProgramUniform1i(program.id(), program.uniform("uLpvSubsurfaceVolume"), GLint(unit));
    glBindTextureUnit(unit, 0);
}

std::array<std::vector<glm::vec4>, 3> LpvSubsurfacePass::readAccumulator(int cascade) const {
    std::array<std::vector<glm::vec4>, 3> out;
    if (cascade < 0 || cascade >= cascades_)
        return out;
    const int n = gridSize_;
    const std::size_t cells = std::size_t(n) * std::size_t(n) * std::size_t(n);
    for (int c = 0; c < 3; ++c) {
        out[std::size_t(c)].resize(cells);
        glGetTextureSubImage(accumulator_.id(), 0, c * n, 0, cascade * n, n, n, n, GL_RGBA, GL_FLOAT,
                             GLsizei(cells * sizeof(glm::vec4)), out[std::size_t(c)].data());
    }
    return out;
}

void LpvSubsurfacePass::addGpuMemory(GpuMemoryLedger& ledger) const {
    for (const Texture& t : volume_)
        ledger.addTexture("subsurface.volumes", t.id());
    ledger.addTexture(resources::SubsurfaceAccumulator.name(), accumulator_.id());
}

} // namespace lpv::renderer
