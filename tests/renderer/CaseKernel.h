#pragma once
// Runs a test compute kernel over a list of cases, the form the GLSL
// agreement tests share (sh_test.comp, sh3_test.comp, lpv_glossy_test.comp,
// lpv_lookup_test.comp): the inputs at SSBO binding 0, the outputs at
// binding 1, `caseCount` the number of cases, 64 invocations a group.
// Each output starts as -1234, so one the kernel did not write shows.
#include "lpv/renderer/GlHandle.h"

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include <cstddef>
#include <vector>

namespace lpv::renderer {

// `outputsPerCase` vec4s for each of `cases`; the program's other uniforms
// and textures are set by the caller.
inline std::vector<glm::vec4> runCaseKernel(GLuint program, const std::vector<glm::vec4>& inputs, GLuint cases,
                                            std::size_t outputsPerCase) {
    Buffer in = createBuffer(), out = createBuffer();
    glNamedBufferStorage(in.id(), GLsizeiptr(inputs.size() * sizeof(glm::vec4)), inputs.data(), 0);
    std::vector<glm::vec4> result(outputsPerCase * cases, glm::vec4(-1234.0f));
    glNamedBufferStorage(out.id(), GLsizeiptr(result.size() * sizeof(glm::vec4)), result.data(), 0);
    glUseProgram(program);
    glUniform1ui(glGetUniformLocation(program, "caseCount"), cases);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, in.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, out.id());
    glDispatchCompute((cases + 63) / 64, 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glGetNamedBufferSubData(out.id(), 0, GLsizeiptr(result.size() * sizeof(glm::vec4)), result.data());
    glUseProgram(0);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    return result;
}

} // namespace lpv::renderer
