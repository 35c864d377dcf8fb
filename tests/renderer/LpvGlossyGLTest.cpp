// shaders/lpv_glossy.glsl against its C++ twin LpvGlossy.cpp: the same ray
// march over the same two-cascade volume (stacked along z as LpvVolumes holds
// it, sampled by the GL's trilinear filter), on random rays.
#include "CaseKernel.h"
#include "GlFixture.h"

#include "lpv/renderer/GlHandle.h"
#include "lpv/renderer/ShaderLibrary.h"
#include "lpv/renderer/lpv/LpvGlossy.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <random>
#include <vector>

using namespace lpv::renderer;
using namespace lpv::renderer::lpvref;

namespace {

constexpr int kCells = 8;
constexpr int kCascades = 2;

// Per colour channel one RGBA32F texture of N x N x N K, cascade k at z = k N ...
std::vector<Texture> uploadStacked(const std::vector<ShGrid>& grids) {
    std::vector<Texture> out;
    for (int c = 0; c < 3; ++c) {
        std::vector<glm::vec4> texels;
        for (const ShGrid& g : grids)
            texels.insert(texels.end(), g.channel[c].begin(), g.channel[c].end());
        Texture t = createTexture(GL_TEXTURE_3D);
        glTextureStorage3D(t.id(), 1, GL_RGBA32F, kCells, kCells, kCells * kCascades);
        glTextureSubImage3D(t.id(), 0, 0, 0, 0, kCells, kCells, kCells * kCascades, GL_RGBA, GL_FLOAT,
                            texels.data());
        glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
            glTextureParameteri(t.id(), wrap, GL_CLAMP_TO_EDGE);
        out.push_back(std::move(t));
    }
    return out;
}

} // namespace

class LpvGlossyGLTest : public GlTest {};

TEST_F(LpvGlossyGLTest, MarchMatchesTheCpuTwin) {
    constexpr GLuint kCases = 1000;
    std::mt19937 rng(2010);
    std::uniform_real_distribution<float> dc(0.0f, 2.0f), band1(-1.0f, 1.0f), unit(0.0f, 1.0f);
    std::normal_distribution<float> gauss;

    // Cascade 1 has cells twice as wide and is centred on cascade 0.
    const std::vector<GridFrame> frames{{glm::vec3(0.0f), 0.25f, kCells}, {glm::vec3(-1.0f), 0.5f, kCells}};
    std::vector<ShGrid> grids(kCascades, ShGrid(kCells));
    for (ShGrid& g : grids)
        for (auto& channel : g.channel)
            for (glm::vec4& v : channel)
                v = {dc(rng), band1(rng), band1(rng), band1(rng)};
    GlossyMarch march;
    march.steps = 8;
    march.maxDistanceCells = 12.0f;
    const float lpvIntensity = 1.5f, glossyIntensity = 0.8f;
    march.intensity = lpvIntensity * glossyIntensity;

    std::vector<glm::vec4> inputs;
    for (GLuint i = 0; i < kCases; ++i) {
        const glm::vec3 x = glm::vec3(0.25f) + 1.5f * glm::vec3(unit(rng), unit(rng), unit(rng));
        const glm::vec3 r = glm::normalize(glm::vec3(gauss(rng), gauss(rng), gauss(rng)));
        inputs.emplace_back(x, unit(rng));
        inputs.emplace_back(r, unit(rng));
        inputs.emplace_back(unit(rng), unit(rng), unit(rng), 0.0f);
    }

    auto program = buildEmbeddedProgram({"lpv_glossy_test.comp"});
    ASSERT_TRUE(program.has_value()) << program.error().describe();
    const GLuint p = program->id();
    auto at = [&](const std::string& name) { return glGetUniformLocation(p, name.c_str()); };
    std::vector<Texture> volumes = uploadStacked(grids);
    glProgramUniform1i(p, at("uLpvCascadeCount"), kCascades);
    glProgramUniform1i(p, at("uLpvGridSize"), kCells);
    for (int k = 0; k < kCascades; ++k) {
        const std::string idx = "[" + std::to_string(k) + "]";
        glProgramUniform3fv(p, at("uLpvOrigin" + idx), 1, glm::value_ptr(frames[std::size_t(k)].origin));
        glProgramUniform1f(p, at("uLpvCellSize" + idx), frames[std::size_t(k)].cellSize);
    }
    glProgramUniform1f(p, at("uLpvIntensity"), lpvIntensity);
    glProgramUniform1i(p, at("uGlossySteps"), march.steps);
    glProgramUniform1f(p, at("uGlossyMaxDistance"), march.maxDistanceCells);
    glProgramUniform1f(p, at("uGlossyIntensity"), glossyIntensity);
    const char* samplers[] = {"uLpvAccumR", "uLpvAccumG", "uLpvAccumB"};
    for (int c = 0; c < 3; ++c) {
        glProgramUniform1i(p, at(samplers[c]), c);
        glBindTextureUnit(GLuint(c), volumes[std::size_t(c)].id());
    }

    const std::vector<glm::vec4> gpu = runCaseKernel(p, inputs, kCases, 2);

    float peak = 0.0f, worst = 0.0f, worstReflectance = 0.0f;
    int sameCascade = 0, coarseFirst = 0;
    for (GLuint i = 0; i < kCases; ++i) {
        const glm::vec3 x(inputs[3 * i]), r(inputs[3 * i + 1]), f0(inputs[3 * i + 2]);
        const float glossiness = inputs[3 * i].w, nDotV = inputs[3 * i + 1].w;
        const glm::vec3 cpu = glossyIncoming(grids, frames, x, r, glossiness, march);
        const float t0 = frames[0].cellSize;
        const int first = glossyCascade(frames, x + r * t0, 2.0f * t0 * (1.0f - glossiness));
        sameCascade += int(gpu[2 * i].w) == first;
        coarseFirst += first == 1;
        for (int c = 0; c < 3; ++c) {
            peak = std::max(peak, std::abs(cpu[c]));
            worst = std::max(worst, std::abs(gpu[2 * i][c] - cpu[c]));
            worstReflectance = std::max(
                worstReflectance, std::abs(gpu[2 * i + 1][c] - glossyReflectance(f0, glossiness, nDotV)[c]));
        }
    }
    const float relative = worst / std::max(peak, 1e-20f);
    char text[160];
    std::snprintf(text, sizeof text, "incoming: max |GPU - CPU| / peak = %.3g (peak %.3g); reflectance %.3g",
                  double(relative), double(peak), double(worstReflectance));
    std::cout << "[ figures ] lpv_glossy.glsl vs LpvGlossy.cpp, " << kCases << " rays: " << text
              << "; first sample "
              << "in the same cascade " << sameCascade << ", of which the coarse one " << coarseFirst << "\n";
    RecordProperty("relative_difference", text);
    EXPECT_GT(peak, 0.0f);
    EXPECT_EQ(sameCascade, int(kCases));
    EXPECT_GT(coarseFirst, 50) << "rough rays must start in the coarser cascade";
    EXPECT_LT(relative, 1e-4f);
    EXPECT_LT(worstReflectance, 1e-5f);
}

// The march reuses the diffuse lookup's accumulator samplers: the forward
// program's fragment stage must stay within the 16 units GL 4.5 guarantees.
TEST_F(LpvGlossyGLTest, ForwardPassAddsNoSampler) {
    // Built as for a GL with OpenGL's minimum of 16 units: without the
    // subsurface LPV's sampler (LpvSubsurfaceGLTest counts that one).
    auto program = buildEmbeddedProgram({"forward.vert", "forward.frag"}, {"LPV_NO_SUBSURFACE_SAMPLER 1"});
    ASSERT_TRUE(program.has_value()) << program.error().describe();
    const GLuint p = program->id();
    GLint count = 0;
    glGetProgramInterfaceiv(p, GL_UNIFORM, GL_ACTIVE_RESOURCES, &count);
    int samplers = 0;
    bool glossyActive = false;
    for (GLint i = 0; i < count; ++i) {
        const GLenum props[] = {GL_TYPE, GL_ARRAY_SIZE, GL_REFERENCED_BY_FRAGMENT_SHADER};
        GLint values[3] = {};
        glGetProgramResourceiv(p, GL_UNIFORM, GLuint(i), 3, props, 3, nullptr, values);
        char name[128] = {};
        glGetProgramResourceName(p, GL_UNIFORM, GLuint(i), sizeof name, nullptr, name);
        glossyActive |= std::string(name) == "uGlossySteps";
        const GLenum type = GLenum(values[0]);
        const bool sampler = type == GL_SAMPLER_2D || type == GL_SAMPLER_3D || type == GL_SAMPLER_2D_ARRAY ||
                             type == GL_SAMPLER_2D_ARRAY_SHADOW || type == GL_SAMPLER_2D_SHADOW ||
                             type == GL_SAMPLER_CUBE || type == GL_SAMPLER_CUBE_SHADOW ||
                             type == GL_SAMPLER_CUBE_MAP_ARRAY || type == GL_SAMPLER_CUBE_MAP_ARRAY_SHADOW;
        if (sampler && values[2] != 0)
            samplers += values[1];
    }
    std::cout << "[ figures ] forward.frag: " << samplers << " samplers\n";
    EXPECT_TRUE(glossyActive) << "the march is compiled into the forward pass";
    EXPECT_LE(samplers, 16);
    EXPECT_GT(samplers, 0);
}
