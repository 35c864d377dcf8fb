// The injection of VPLs that are not tied to a cascade (lpv_inject_local.comp:
// emissive samples, spot and point lights' RSM faces) against the CPU
// reference: every VPL goes into every cascade that holds it, here with no
// sun at all, and together with a sun tile (one fixed-point scale for both).
#include "FakeRsm.h"
#include "GlFixture.h"
#include "ShGridCompare.h"

#include "passes/lpv/EmissiveVplBuffer.h"
#include "passes/lpv/LpvPass.h"
#include "lpv/renderer/GpuTimer.h"
#include "lpv/renderer/lpv/LpvReference.h"

#include <cmath>
#include <iostream>
#include <random>

using namespace lpv::renderer;
namespace ref = lpv::renderer::lpvref;

namespace {

// Two nested cascades of 8^3 (0.5 m and 1 m cells) around the origin.
const std::vector<LpvCascade> kCascades = {LpvCascade{glm::vec3(-2.0f), 0.5f, 8},
                                           LpvCascade{glm::vec3(-4.0f), 1.0f, 8}};

std::vector<ref::Vpl> randomVpls(int count, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-4.5f, 4.5f), f(0.0f, 2.0f);
    std::normal_distribution<float> g;
    std::vector<ref::Vpl> vpls;
    for (int i = 0; i < count; ++i) {
        glm::vec3 n{g(rng), g(rng), g(rng)};
        vpls.push_back({{u(rng), u(rng), u(rng)}, glm::normalize(n), {f(rng), f(rng), f(rng)}});
    }
    return vpls;
}

// Relative to the CPU's largest coefficient, which must not be zero.
double relative(const ref::ShGrid& expected, const std::array<std::vector<glm::vec4>, 3>& gpu) {
    float largest = 0.0f;
    const double d = relativeDifference(expected, gpu, &largest);
    EXPECT_GT(largest, 0.0f);
    return d;
}

class LpvLocalInjectionGLTest : public GlTest {};

} // namespace

TEST_F(LpvLocalInjectionGLTest, EveryCascadeThatHoldsAVplGetsItAsTheReferenceSays) {
    auto pass = LpvPass::create();
    ASSERT_TRUE(pass.has_value()) << pass.error().describe();
    const std::vector<ref::Vpl> vpls = randomVpls(300, 7);
    EmissiveVplBuffer buffer;
    buffer.upload(vpls);
    const FakeRsm sunTile(8, {{Texel{{0.3f, -1.2f, 0.7f}, {0, 1, 0}, {5.0f, 4.0f, 3.0f}},
                               Texel{{-1.1f, 0.4f, 0.2f}, {1, 0, 0}, {2.0f, 1.0f, 0.5f}}},
                              {Texel{{2.6f, 1.5f, -3.1f}, {0, 0, 1}, {1.0f, 1.0f, 1.0f}}}});
    GpuTimer timer;
    // Directed: the local VPLs' normals join the sun's in the normals volume (issue #24).
    for (bool directed : {false, true})
    for (bool withSun : {false, true})
        for (int steps : {0, 4}) {
            if (directed && steps == 0)
                continue; // the normals only weight propagation
            LpvSettings settings;
            settings.gridSize = 8;
            settings.propagationSteps = steps;
            settings.directed = directed;
            settings.directedDilation = 1;
            settings.occlusion = false;
            settings.gvFromCamera = false;
            LpvRsmInput rsm;
            rsm.cascades = kCascades;
            rsm.texelArea = {0.01f, 0.01f};
            if (withSun) {
                rsm.tileSize = sunTile.tileSize;
                rsm.position = sunTile.position.id();
                rsm.normal = sunTile.normal.id();
                rsm.flux = sunTile.flux.id();
            }
            timer.beginFrame();
            ASSERT_TRUE(pass->run(settings, rsm, nullptr, timer, nullptr, {buffer.input()}).has_value());
            EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
            EXPECT_NE(pass->note().find("300 emissive VPLs injected"), std::string::npos) << pass->note();
            for (int k = 0; k < 2; ++k) {
                const ref::GridFrame frame{kCascades[std::size_t(k)].origin,
                                           kCascades[std::size_t(k)].cellSize, 8};
                std::vector<ref::Vpl> all = vpls;
                if (withSun) // tile k feeds cascade k only
                    for (int i = 0; i < (k == 0 ? 2 : 1); ++i) {
                        const int tile = k;
                        const glm::vec3 p =
                            tile == 0 ? (i == 0 ? glm::vec3(0.3f, -1.2f, 0.7f) : glm::vec3(-1.1f, 0.4f, 0.2f))
                                      : glm::vec3(2.6f, 1.5f, -3.1f);
                        const glm::vec3 n = tile == 0 ? (i == 0 ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0))
                                                      : glm::vec3(0, 0, 1);
                        const glm::vec3 f =
                            tile == 0 ? (i == 0 ? glm::vec3(5, 4, 3) : glm::vec3(2, 1, 0.5f)) : glm::vec3(1);
                        all.push_back({p, n, f});
                    }
                const ref::NormalGrid normals = ref::dilateNormals(ref::injectNormals(frame, all, 1.0f));
                const ref::ShGrid expected = ref::propagateAndAccumulate(ref::injectVpls(frame, all, 1.0f), nullptr,
                                                                         steps, directed ? &normals : nullptr);
                const double d = relative(expected, pass->readAccumulator(k));
                if (directed) { // the normals must change the result, or this tests nothing
                    const ref::ShGrid undirected =
                        ref::propagateAndAccumulate(ref::injectVpls(frame, all, 1.0f), nullptr, steps);
                    std::array<std::vector<glm::vec4>, 3> plain;
                    for (int c = 0; c < 3; ++c)
                        plain[std::size_t(c)] = undirected.channel[c];
                    EXPECT_GT(relative(expected, plain), 1e-3);
                }
                std::cout << "[ figures ] local VPLs" << (withSun ? " + sun tile" : "") << (directed ? ", directed" : "")
                          << ", cascade " << k
                          << ", " << steps << " steps: relative |GPU - CPU| " << d << "\n";
                EXPECT_LT(d, 2e-5);
            }
        }
}
