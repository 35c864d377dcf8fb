// The three-band gather step on the GPU (shaders/lpv_transfer3.glsl, run by
// lpv_gather3_test.comp over volumes in buffers) against its CPU twin
// lpvref::bands::propagateStep<3> (issue #47): two VPLs and a wall of surfels
// in a 10^3 grid, with the geometry volume's occlusion and without.
#include "GlFixture.h"

#include "lpv/renderer/GlHandle.h"
#include "lpv/renderer/ShaderLibrary.h"
#include "lpv/renderer/lpv/LpvBands.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <random>
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

namespace {

// Runs one gather step of `program` over the buffers; its time in ms.
double timedDispatch(GLuint program, int n, GLuint in, GLuint gv, GLuint out, bool occlusion) {
    glUseProgram(program);
    glUniform1i(glGetUniformLocation(program, "uGridSize3"), n);
    glUniform1f(glGetUniformLocation(program, "uStrength3"), 1.333f);
    glUniform1i(glGetUniformLocation(program, "uOcclusion"), occlusion ? 1 : 0);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, in);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, gv);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, out);
    // Wall time between glFinish calls: llvmpipe's GL_TIME_ELAPSED does not
    // cover a compute dispatch (it read 1 ns), and it runs on these CPUs.
    glFinish();
    const auto start = std::chrono::steady_clock::now();
    glDispatchCompute(GLuint((n * n * n + 63) / 64), 1, 1);
    glFinish();
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    glUseProgram(0);
    return ms;
}

} // namespace

// The two-band twin of the test kernel (lpv_gather2_test.comp) matches
// propagateStep<2>, and one step of each over 32^3 cells with occlusion is
// timed, alternated: the cost of the three bands' face transfer on kernels
// that differ only in the band count (not the renderer's texture pass).
TEST_F(LpvGather3, TheTwoBandTwinMatchesAndTheStepsCostIsMeasured) {
    auto two = buildEmbeddedProgram({"lpv_gather2_test.comp"});
    auto three = buildEmbeddedProgram({"lpv_gather3_test.comp"});
    ASSERT_TRUE(two.has_value()) << two.error().describe();
    ASSERT_TRUE(three.has_value()) << three.error().describe();
    {
        const GridFrame frame{glm::vec3(0.0f), 0.5f, 10};
        const Vpl vpl{glm::vec3(1.2f, 1.6f, 2.1f), glm::normalize(glm::vec3(1, 0.3f, 0.1f)), glm::vec3(1, 2, 3)};
        std::vector<Surfel> wall;
        for (int y = 0; y <= 20; ++y)
            for (int z = 0; z <= 20; ++z)
                wall.push_back({glm::vec3(2.5f, 0.25f * float(y), 0.25f * float(z)), glm::vec3(-1, 0, 0), 0.06f});
        auto gvCpu = bands::injectSurfels<2>(frame, wall);
        gvCpu.strength = 1.333f;
        const auto source = bands::propagateStep<2>(bands::injectVpls<2>(frame, std::span(&vpl, 1), 0.875f), &gvCpu);
        const auto cpu = bands::propagateStep<2>(source, &gvCpu);
        std::vector<glm::vec4> sourceData, gvData;
        for (int z = 0; z < frame.n; ++z)
            for (int y = 0; y < frame.n; ++y)
                for (int x = 0; x < frame.n; ++x)
                    for (int c = 0; c < 3; ++c)
                        sourceData.push_back(sh::toVec4(source.at(c, x, y, z)));
        for (const auto& b : gvCpu.potential)
            gvData.push_back(sh::toVec4(b));
        Buffer in = createBuffer(), gv = createBuffer(), out = createBuffer();
        glNamedBufferStorage(in.id(), GLsizeiptr(sourceData.size() * sizeof(glm::vec4)), sourceData.data(), 0);
        glNamedBufferStorage(gv.id(), GLsizeiptr(gvData.size() * sizeof(glm::vec4)), gvData.data(), 0);
        std::vector<glm::vec4> gpu(sourceData.size(), glm::vec4(-1234.0f));
        glNamedBufferStorage(out.id(), GLsizeiptr(gpu.size() * sizeof(glm::vec4)), gpu.data(), 0);
        (void)timedDispatch(two->id(), frame.n, in.id(), gv.id(), out.id(), true);
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        glGetNamedBufferSubData(out.id(), 0, GLsizeiptr(gpu.size() * sizeof(glm::vec4)), gpu.data());
        double largest = 0.0, worst = 0.0;
        std::size_t i = 0;
        for (int z = 0; z < frame.n; ++z)
            for (int y = 0; y < frame.n; ++y)
                for (int x = 0; x < frame.n; ++x)
                    for (int c = 0; c < 3; ++c, ++i)
                        for (int k = 0; k < 4; ++k) {
                            largest = std::max(largest, double(std::abs(cpu.at(c, x, y, z)[k])));
                            worst = std::max(worst, double(std::abs(gpu[i][k] - cpu.at(c, x, y, z)[k])));
                        }
        EXPECT_GT(largest, 1e-3);
        EXPECT_LT(worst, 1e-5 * largest);
    }
    // Timing: 32^3 cells (one cascade of the default grid), arbitrary positive light.
    const int n = 32;
    std::mt19937 rng(47);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const std::size_t cells = std::size_t(n) * std::size_t(n) * std::size_t(n), gvCells = std::size_t(n + 1) * (n + 1) * (n + 1);
    std::vector<glm::vec4> src2(cells * 3), gv2(gvCells), src3(cells * 9), gv3(gvCells * 3);
    for (auto* v : {&src2, &gv2, &src3, &gv3})
        for (glm::vec4& x : *v)
            x = glm::vec4(u(rng), u(rng) - 0.5f, u(rng) - 0.5f, u(rng) - 0.5f) * 0.1f;
    auto buffer = [](const std::vector<glm::vec4>& data) {
        Buffer b = createBuffer();
        glNamedBufferStorage(b.id(), GLsizeiptr(data.size() * sizeof(glm::vec4)), data.data(), 0);
        return b;
    };
    Buffer in2 = buffer(src2), g2 = buffer(gv2), out2 = buffer(src2), in3 = buffer(src3), g3 = buffer(gv3),
           out3 = buffer(src3);
    std::vector<double> t2, t3;
    for (int round = 0; round < 7; ++round) {
        const bool twoFirst = round % 2 == 0;
        for (int k = 0; k < 2; ++k) {
            if ((k == 0) == twoFirst)
                t2.push_back(timedDispatch(two->id(), n, in2.id(), g2.id(), out2.id(), true));
            else
                t3.push_back(timedDispatch(three->id(), n, in3.id(), g3.id(), out3.id(), true));
        }
    }
    ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    std::ranges::sort(t2);
    std::ranges::sort(t3);
    std::cout << "[measured] one gather step, 32^3 cells, occlusion, 7 alternated rounds: two bands " << t2.front()
              << " / " << t2[3] << " / " << t2.back() << " ms, three bands " << t3.front() << " / " << t3[3] << " / "
              << t3.back() << " ms (min / median / max); ratio of medians " << t3[3] / t2[3] << "\n";
    EXPECT_GT(t2[3], 0.0);
    EXPECT_GT(t3[3], 0.0);
}
