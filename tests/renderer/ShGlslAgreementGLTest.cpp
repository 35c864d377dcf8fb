// shaders/sh.glsl against its C++ twin Sh.h, and shaders/sh3.glsl against
// ShBands.h (three bands, issue #47): the same functions on 1000 random
// inputs, evaluated by a compute shader (sh_test.comp, sh3_test.comp) and
// on the CPU.
#include "CaseKernel.h"
#include "GlFixture.h"

#include "lpv/renderer/GlHandle.h"
#include "lpv/renderer/ShaderLibrary.h"
#include "lpv/renderer/lpv/Sh.h"
#include "lpv/renderer/lpv/ShBands.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <random>
#include <vector>

using namespace lpv::renderer;

class ShGlslAgreement : public GlTest {};

TEST_F(ShGlslAgreement, EveryFunctionMatchesShH) {
    constexpr GLuint kCases = 1000;
    std::mt19937 rng(2010);
    std::normal_distribution<float> gauss;
    std::uniform_real_distribution<float> flux(0.0f, 4.0f), coefficient(-2.0f, 2.0f);
    std::vector<glm::vec4> inputs;
    for (GLuint i = 0; i < kCases; ++i) {
        const glm::vec3 w = glm::normalize(glm::vec3(gauss(rng), gauss(rng), gauss(rng)));
        inputs.emplace_back(w, flux(rng));
        inputs.emplace_back(coefficient(rng), coefficient(rng), coefficient(rng), coefficient(rng));
    }

    auto program = buildEmbeddedProgram({"sh_test.comp"});
    ASSERT_TRUE(program.has_value()) << program.error().describe();
    const std::vector<glm::vec4> gpu = runCaseKernel(program->id(), inputs, kCases, 4);

    const char* names[] = {"basis", "cosineLobe", "vplIntensity", "evaluate", "irradiance"};
    float worst[5] = {};
    for (GLuint i = 0; i < kCases; ++i) {
        const glm::vec3 w(inputs[2 * i]);
        const float phi = inputs[2 * i].w;
        const glm::vec4 f = inputs[2 * i + 1];
        const glm::vec4 cpu[3] = {sh::basis(w), sh::cosineLobe(w), sh::vplIntensity(w, phi)};
        for (int k = 0; k < 3; ++k)
            for (int c = 0; c < 4; ++c)
                worst[k] = std::max(worst[k], std::abs(gpu[4 * i + GLuint(k)][c] - cpu[k][c]));
        worst[3] = std::max(worst[3], std::abs(gpu[4 * i + 3].x - sh::evaluate(f, w)));
        worst[4] = std::max(worst[4], std::abs(gpu[4 * i + 3].y - sh::irradiance(f, w)));
    }
    for (int k = 0; k < 5; ++k) {
        char text[32];
        std::snprintf(text, sizeof text, "%.3g", double(worst[k]));
        RecordProperty(std::string("max_abs_difference.") + names[k], text);
        std::cout << "[measured] sh.glsl vs Sh.h " << names[k] << " max abs difference = " << text << "\n";
        EXPECT_LT(worst[k], 1e-5f) << names[k];
    }
}

TEST_F(ShGlslAgreement, ThreeBandsEveryFunctionMatchesShBands) {
    constexpr GLuint kCases = 1000;
    std::mt19937 rng(47);
    std::normal_distribution<float> gauss;
    std::uniform_real_distribution<float> flux(0.0f, 4.0f), coefficient(-2.0f, 2.0f);
    std::vector<glm::vec4> inputs;
    std::vector<sh::Coeffs<3>> functions;
    for (GLuint i = 0; i < kCases; ++i) {
        const glm::vec3 w = glm::normalize(glm::vec3(gauss(rng), gauss(rng), gauss(rng)));
        sh::Coeffs<3> f;
        for (float& c : f.c)
            c = coefficient(rng);
        functions.push_back(f);
        inputs.emplace_back(w, flux(rng));
        inputs.emplace_back(f[0], f[1], f[2], f[3]);
        inputs.emplace_back(f[4], f[5], f[6], f[7]);
        inputs.emplace_back(f[8], 0.0f, 0.0f, 0.0f);
    }
    auto program = buildEmbeddedProgram({"sh3_test.comp"});
    ASSERT_TRUE(program.has_value()) << program.error().describe();
    const std::vector<glm::vec4> gpu = runCaseKernel(program->id(), inputs, kCases, 9);

    auto coefficientOf = [&](GLuint at, int k) {
        return k < 4 ? gpu[at][k] : k < 8 ? gpu[at + 1][k - 4] : gpu[at + 2].x;
    };
    const char* names[] = {"basis", "cosineLobe", "vplIntensity", "evaluate", "irradiance"};
    float worst[5] = {};
    for (GLuint i = 0; i < kCases; ++i) {
        const glm::vec3 w(inputs[4 * i]);
        const float phi = inputs[4 * i].w;
        const sh::Coeffs<3> cpu[3] = {sh::basisOf<3>(w), sh::cosineLobeOf<3>(w), sh::vplIntensityOf<3>(w, phi)};
        for (int k = 0; k < 3; ++k)
            for (int c = 0; c < 9; ++c)
                worst[k] = std::max(worst[k], std::abs(coefficientOf(9 * i + 3 * GLuint(k), c) - cpu[k][c]));
        worst[3] = std::max(worst[3], std::abs(gpu[9 * i + 2].y - sh::evaluateAt<3>(functions[i], w)));
        worst[4] = std::max(worst[4], std::abs(gpu[9 * i + 2].z - sh::irradianceOf<3>(functions[i], w)));
    }
    for (int k = 0; k < 5; ++k) {
        std::cout << "[measured] sh3.glsl vs ShBands.h " << names[k] << " max abs difference = " << worst[k] << "\n";
        EXPECT_LT(worst[k], 1e-5f) << names[k];
    }
}
