// The three-band gather step on the GPU (shaders/lpv_transfer3.glsl, run by
// lpv_gather3_test.comp over volumes in buffers) against its CPU twin
// lpvref::bands::propagateStep<3> (issue #47): two VPLs and a wall of surfels
// in a 10^3 grid, with the geometry volume's occlusion and without.
#include "GlFixture.h"

#include "lpv/renderer/GlHandle.h"
#include "lpv/renderer/ShaderLibrary.h"
#include "lpv/renderer/lpv/LpvBands.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <vector>

using namespace lpv::renderer;
using namespace lpv::renderer::lpvref;

namespace {

void append(std::vector<glm::vec4>& out, const sh::Coeffs<3>& f) {
    out.emplace_back(f[0], f[1], f[2], f[3]);
    out.emplace_back(f[4], f[5], f[6], f[7]);
    out.emplace_back(f[8], 0.0f, 0.0f, 0.0f);
}

} // namespace

class LpvGather3 : public GlTest {};

TEST_F(LpvGather3, OneStepMatchesTheCpuTwinWithAndWithoutOcclusion) {
    const GridFrame frame{glm::vec3(0.0f), 0.5f, 10};
    const Vpl vpls[] = {{glm::vec3(1.2f, 1.6f, 2.1f), glm::normalize(glm::vec3(1, 0.3f, 0.1f)), glm::vec3(1, 2, 3)},
                        {glm::vec3(3.7f, 4.1f, 1.3f), glm::vec3(0, -1, 0), glm::vec3(0.5f, 0.2f, 0.1f)}};
    std::vector<Surfel> wall;
    for (int y = 0; y <= 20; ++y)
        for (int z = 0; z <= 20; ++z)
            wall.push_back({glm::vec3(2.5f, 0.25f * float(y), 0.25f * float(z)), glm::vec3(-1, 0, 0), 0.06f});
    // Two steps on the CPU first, so the source has light in many cells and directions.
    auto gvCpu = bands::injectSurfels<3>(frame, wall);
    gvCpu.strength = 1.333f;
    const auto source =
        bands::propagateStep<3>(bands::propagateStep<3>(bands::injectVpls<3>(frame, vpls, 0.875f), &gvCpu), &gvCpu);
    std::vector<glm::vec4> sourceData, gvData;
    const int n = frame.n;
    for (int z = 0; z < n; ++z)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x)
                for (int c = 0; c < 3; ++c)
                    append(sourceData, source.at(c, x, y, z));
    for (const auto& b : gvCpu.potential)
        append(gvData, b);

    auto program = buildEmbeddedProgram({"lpv_gather3_test.comp"});
    ASSERT_TRUE(program.has_value()) << program.error().describe();
    for (const bool occlusion : {false, true}) {
        SCOPED_TRACE(occlusion);
        const auto cpu = bands::propagateStep<3>(source, occlusion ? &gvCpu : nullptr);
        Buffer in = createBuffer(), gv = createBuffer(), out = createBuffer();
        glNamedBufferStorage(in.id(), GLsizeiptr(sourceData.size() * sizeof(glm::vec4)), sourceData.data(), 0);
        glNamedBufferStorage(gv.id(), GLsizeiptr(gvData.size() * sizeof(glm::vec4)), gvData.data(), 0);
        std::vector<glm::vec4> gpu(sourceData.size(), glm::vec4(-1234.0f));
        glNamedBufferStorage(out.id(), GLsizeiptr(gpu.size() * sizeof(glm::vec4)), gpu.data(), 0);
        glUseProgram(program->id());
        glUniform1i(glGetUniformLocation(program->id(), "uGridSize3"), n);
        glUniform1f(glGetUniformLocation(program->id(), "uStrength3"), gvCpu.strength);
        glUniform1i(glGetUniformLocation(program->id(), "uOcclusion"), occlusion ? 1 : 0);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, in.id());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, gv.id());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, out.id());
        glDispatchCompute(GLuint((n * n * n + 63) / 64), 1, 1);
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        glGetNamedBufferSubData(out.id(), 0, GLsizeiptr(gpu.size() * sizeof(glm::vec4)), gpu.data());
        glUseProgram(0);
        ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
        double largest = 0.0, worst = 0.0;
        std::size_t i = 0;
        for (int z = 0; z < n; ++z)
            for (int y = 0; y < n; ++y)
                for (int x = 0; x < n; ++x)
                    for (int c = 0; c < 3; ++c, i += 3) {
                        const sh::Coeffs<3>& f = cpu.at(c, x, y, z);
                        for (int k = 0; k < 9; ++k) {
                            const float g = k < 4 ? gpu[i][k] : k < 8 ? gpu[i + 1][k - 4] : gpu[i + 2].x;
                            largest = std::max(largest, double(std::abs(f[k])));
                            worst = std::max(worst, double(std::abs(g - f[k])));
                        }
                    }
        std::cout << "[measured] three-band gather, occlusion " << occlusion << ": largest coefficient " << largest
                  << ", max abs GPU - CPU " << worst << "\n";
        EXPECT_GT(largest, 1e-3);
        EXPECT_LT(worst, 1e-5 * largest);
    }
}
