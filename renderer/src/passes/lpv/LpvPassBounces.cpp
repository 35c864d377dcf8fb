// LpvPass's multi-bounce (docs/lpv.md, "Local lights, emissive surfaces and
// bounces"), kept apart from the single-bounce pass it extends. The CPU twin
// is lpvref::propagateWithBounces (LpvBounce.h).
#include "passes/lpv/LpvPass.h"

namespace lpv::renderer {

namespace {

GLuint groups(int count, int size) {
    return GLuint((count + size - 1) / size);
}
constexpr GLbitfield kComputeResults =
    GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT;
constexpr GLuint kScalesBinding = 1; // lpv_common.glsl's LpvScales

} // namespace

void LpvPass::addBounceTotal(bool final) {
    const GLuint p = kernel(LpvKernel::BounceAdd);
    glUseProgram(p);
    setCascadeUniforms(p);
    glProgramUniform1i(p, loc(p, "uFinal"), final ? 1 : 0);
    for (int c = 0; c < 3; ++c) {
        glBindImageTexture(GLuint(c), volumes_.bounceTotal.channel[std::size_t(c)].id(), 0, GL_TRUE, 0,
                           GL_READ_WRITE, GL_RGBA32F);
        glBindImageTexture(GLuint(3 + c), volumes_.accumulator.channel[std::size_t(c)].id(), 0, GL_TRUE, 0,
                           GL_READ_WRITE, GL_RGBA32F);
    }
    const int n = volumes_.gridSize();
    glDispatchCompute(groups(n, 4), groups(n, 4), groups(n * volumes_.cascades(), 4));
    glMemoryBarrier(kComputeResults);
}

void LpvPass::propagateBounces(const LpvSettings& settings) {
    const int n = volumes_.gridSize(), k = volumes_.cascades();
    bouncing_ = true;
    for (int bounce = 2; bounce <= settings.bounces; ++bounce) {
        // The accumulator holds the bounce just propagated: keep it in the total before it is replaced.
        if (bounce == 2) {
            glMemoryBarrier(GL_ALL_BARRIER_BITS);
            for (std::size_t c = 0; c < 3; ++c)
                glCopyImageSubData(volumes_.accumulator.channel[c].id(), GL_TEXTURE_3D, 0, 0, 0, 0,
                                   volumes_.bounceTotal.channel[c].id(), GL_TEXTURE_3D, 0, 0, 0, 0, n, n,
                                   n * k);
        } else {
            addBounceTotal(false);
        }
        // The compute scatter scales the next step by the largest coefficient recorded in its slot.
        const GLuint zero = 0;
        glClearNamedBufferSubData(volumes_.scales.id(), GL_R32UI, GLintptr(k * (1 + scaleSlot_)) * 4,
                                  GLsizeiptr(k) * 4, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
        const GLuint p = kernel(LpvKernel::BounceInject);
        glUseProgram(p);
        setCascadeUniforms(p);
        glProgramUniform1f(p, loc(p, "uAlbedo"), settings.bounceAlbedo);
        glProgramUniform1i(p, loc(p, "uRecordSlot"), scaleSlot_);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kScalesBinding, volumes_.scales.id());
        glBindTextureUnit(3, volumes_.geometry.id());
        for (int c = 0; c < 3; ++c) {
            glBindImageTexture(GLuint(c),
                               volumes_.volume[std::size_t(readIndex_)].channel[std::size_t(c)].id(), 0,
                               GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
            glBindImageTexture(GLuint(3 + c), volumes_.accumulator.channel[std::size_t(c)].id(), 0, GL_TRUE,
                               0, GL_READ_WRITE, GL_RGBA32F);
        }
        glDispatchCompute(groups(n, 4), groups(n, 4), groups(n * k, 4));
        glMemoryBarrier(kComputeResults);
        propagate(settings);
    }
    addBounceTotal(true);
    bouncing_ = false;
}

} // namespace lpv::renderer
