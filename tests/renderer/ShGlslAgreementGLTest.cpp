// shaders/sh.glsl against its C++ twin Sh.h: the same functions on 1000 random
// inputs, evaluated by a compute shader (shaders/sh_test.comp) and on the CPU.
#include "CaseKernel.h"
#include "GlFixture.h"

#include "lpv/renderer/GlHandle.h"
#include "lpv/renderer/ShaderLibrary.h"
#include "lpv/renderer/lpv/Sh.h"

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
