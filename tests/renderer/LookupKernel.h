#pragma once
// Runs shaders/lpv_lookup_test.comp: lpv_lookup.glsl's lookup of one cascade
// of an LpvPass's accumulator (and its visibility moments) at a list of
// points, for comparison with lpvref::irradianceAt / irradianceVisibleAt.
#include "passes/lpv/LpvPass.h"
#include "lpv/renderer/GlHandle.h"
#include "lpv/renderer/ShaderLibrary.h"

#include <glm/gtc/type_ptr.hpp>
#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace lpv::renderer {

struct LookupPoint {
    glm::vec3 position, normal;
};

// Irradiance (rgb, times s^-2: lpvIrradianceRaw) at each point from cascade
// `cascade`; `visibility` selects the visibility-aware path (its moments must
// have been built by the pass), `bias` its normal bias in cells.
// `lookupOffset`: lpv.lookupOffset in cells. A pass of three SH bands
// (lpv.shBands = 3) is read with lpv_lookup.glsl's three-band lookup.
inline std::vector<glm::vec3> runLookup(const LpvPass& pass, int cascade, bool visibility, float bias,
                                        const std::vector<LookupPoint>& points, float lookupOffset = 0.0f) {
    const bool three = pass.volumes().bands() == 3;
    auto program = buildEmbeddedProgram({"lpv_lookup_test.comp"},
                                        three ? std::vector<std::string>{"LPV_SH_BANDS 3"} : std::vector<std::string>{});
    EXPECT_TRUE(program.has_value()) << (program ? "" : program.error().describe());
    if (!program)
        return {};
    const GLuint p = program->id();
    auto at = [&](const std::string& name) { return glGetUniformLocation(p, name.c_str()); };
    const LpvVolumes& volumes = pass.volumes();
    glProgramUniform1i(p, at("uLpvCascadeCount"), volumes.cascades());
    glProgramUniform1i(p, at("uLpvGridSize"), volumes.gridSize());
    for (std::size_t k = 0; k < pass.cascades().size(); ++k) {
        const std::string idx = "[" + std::to_string(k) + "]";
        glProgramUniform3fv(p, at("uLpvOrigin" + idx), 1, glm::value_ptr(pass.cascades()[k].origin));
        glProgramUniform1f(p, at("uLpvCellSize" + idx), pass.cascades()[k].cellSize);
    }
    glProgramUniform1i(p, at("uLpvVisibility"), visibility ? 1 : 0);
    glProgramUniform1f(p, at("uLpvVisibilityBias"), bias);
    glProgramUniform1f(p, at("uLpvLookupOffset"), lookupOffset);
    glProgramUniform1i(p, at("uCascade"), cascade);
    const char* samplers[] = {"uLpvAccumR", "uLpvAccumG", "uLpvAccumB"};
    for (int c = 0; c < 3; ++c) {
        glProgramUniform1i(p, at(samplers[c]), c);
        glBindTextureUnit(GLuint(c), volumes.accumulator.channel[std::size_t(c)].id());
    }
    if (three) {
        glProgramUniform1i(p, at("uLpvAccumHigh"), 3);
        glBindTextureUnit(3, volumes.accumulatorHigh.id());
    }
    if (visibility)
        glBindImageTexture(7, volumes.visibility.id(), 0, GL_TRUE, 0, GL_READ_ONLY, GL_RGBA32F);
    std::vector<glm::vec4> inputs;
    for (const LookupPoint& point : points) {
        inputs.emplace_back(point.position, 0.0f);
        inputs.emplace_back(point.normal, 0.0f);
    }
    Buffer in = createBuffer(), out = createBuffer();
    glNamedBufferStorage(in.id(), GLsizeiptr(inputs.size() * sizeof(glm::vec4)), inputs.data(), 0);
    std::vector<glm::vec4> result(points.size(), glm::vec4(-1234.0f));
    glNamedBufferStorage(out.id(), GLsizeiptr(result.size() * sizeof(glm::vec4)), result.data(), 0);
    glUseProgram(p);
    glUniform1ui(at("caseCount"), GLuint(points.size()));
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, in.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, out.id());
    glDispatchCompute(GLuint((points.size() + 63) / 64), 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glGetNamedBufferSubData(out.id(), 0, GLsizeiptr(result.size() * sizeof(glm::vec4)), result.data());
    glUseProgram(0);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    std::vector<glm::vec3> e;
    for (const glm::vec4& r : result)
        e.emplace_back(r);
    return e;
}

} // namespace lpv::renderer
