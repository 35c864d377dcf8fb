#include "passes/direct/AutoExposurePass.h"

#include "frame/FrameResources.h"
#include "gl/GpuMemoryLedger.h"
#include "lpv/renderer/ShaderLibrary.h"

#include <array>

namespace lpv::renderer {
namespace {
constexpr int kTilePixels = 64; // exposure_reduce.comp: 16x16 invocations of 4x4 pixels
}

scene::Expected<AutoExposurePass> AutoExposurePass::create() {
    AutoExposurePass p;
    auto reduce = buildEmbeddedProgram({"exposure_reduce.comp"});
    if (!reduce)
        return std::unexpected(reduce.error());
    auto adapt = buildEmbeddedProgram({"exposure_adapt.comp"});
    if (!adapt)
        return std::unexpected(adapt.error());
    p.reduce_ = std::move(*reduce);
    p.adapt_ = std::move(*adapt);
    p.exposure_ = createBuffer();
    glNamedBufferStorage(p.exposure_.id(), 4 * sizeof(float), nullptr, GL_DYNAMIC_STORAGE_BIT);
    p.histogram_ = createBuffer();
    glNamedBufferStorage(p.histogram_.id(), kMeterBins * sizeof(GLuint), nullptr, 0);
    p.reset();
    return p;
}

void AutoExposurePass::reset() {
    const std::array<float, 4> initial{0.0f, 1.0f, 0.0f, 0.0f};
    glNamedBufferSubData(exposure_.id(), 0, sizeof(initial), initial.data());
}

void AutoExposurePass::meter(GLuint hdr, int width, int height, const MeterTarget& target, float blend) {
    const int tilesX = (width + kTilePixels - 1) / kTilePixels;
    const int tilesY = (height + kTilePixels - 1) / kTilePixels;
    const int tiles = tilesX * tilesY;
    if (tiles > tileCapacity_) {
        tiles_ = createBuffer();
        glNamedBufferStorage(tiles_.id(), GLsizeiptr(tiles) * 2 * GLsizeiptr(sizeof(float)), nullptr, 0);
        tileCapacity_ = tiles;
    }
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, tiles_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, exposure_.id());
    const GLuint zero = 0;
    glClearNamedBufferData(histogram_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, histogram_.id());
    glUseProgram(reduce_.id());
    glBindTextureUnit(0, hdr);
    glProgramUniform1i(reduce_.id(), glGetUniformLocation(reduce_.id(), "uHdr"), 0);
    glDispatchCompute(GLuint(tilesX), GLuint(tilesY), 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    const GLuint a = adapt_.id();
    glUseProgram(a);
    glProgramUniform1i(a, glGetUniformLocation(a, "uTileCount"), tiles);
    glProgramUniform1f(a, glGetUniformLocation(a, "uKey"), float(target.key));
    glProgramUniform1f(a, glGetUniformLocation(a, "uHighlightPercent"), float(target.highlightPercent));
    glProgramUniform1f(a, glGetUniformLocation(a, "uHighlightInput"), float(target.highlightInput));
    glProgramUniform1f(a, glGetUniformLocation(a, "uBlend"), blend);
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

double AutoExposurePass::readExposure() const {
    std::array<float, 4> values{};
    glGetNamedBufferSubData(exposure_.id(), 0, sizeof(values), values.data());
    return double(values[1]);
}

void AutoExposurePass::addGpuMemory(GpuMemoryLedger& ledger) const {
    ledger.addBuffer(resources::Exposure.name(), exposure_.id());
    ledger.addBuffer("exposure.tiles", tiles_.id());
    ledger.addBuffer("exposure.histogram", histogram_.id());
}

} // namespace lpv::renderer
