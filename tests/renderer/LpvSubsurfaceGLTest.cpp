// Subsurface-scattering LPV (issue #6, item 3; docs/lpv.md, "Subsurface LPV")
// on llvmpipe: the GPU injection and attenuated propagation against the CPU
// reference; a thin translucent slab lit from behind is brighter on its unlit
// side with the extension on while opaque surfaces do not change; and without
// a translucent material the pass neither runs nor holds memory.
#include "GlFixture.h"
#include "LpvPassFixture.h"

#include "passes/lpv/LpvPass.h"
#include "passes/lpv/LpvSubsurfacePass.h"
#include "lpv/renderer/ForwardRenderer.h"
#include "lpv/renderer/GpuTimer.h"
#include "lpv/renderer/ShaderLibrary.h"
#include "lpv/renderer/lpv/LpvSubsurfaceReference.h"
#include "lpv/scene/Primitives.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>

using namespace lpv;
using namespace lpv::renderer;
namespace ref = lpv::renderer::lpvref;

namespace {

// One RSM tile (RGBA32F 2D array of one layer, as exact as the CPU's numbers)
// whose flux alpha is 1 + each texel's translucency, as rsm.frag writes it.
struct TranslucentRsm {
    Texture position, normal, flux;
    int tileSize = 0;

    TranslucentRsm(int size, const std::vector<ref::TranslucentVpl>& texels) : tileSize(size) {
        const std::size_t count = std::size_t(size) * std::size_t(size);
        std::vector<glm::vec4> p(count, glm::vec4(0.0f)), n(count, glm::vec4(0.0f)),
            f(count, glm::vec4(0.0f));
        EXPECT_LE(texels.size(), count);
        for (std::size_t i = 0; i < texels.size() && i < count; ++i) {
            p[i] = glm::vec4(texels[i].vpl.position, 1.0f);
            n[i] = glm::vec4(texels[i].vpl.normal, 1.0f);
            f[i] = glm::vec4(texels[i].vpl.flux, 1.0f + texels[i].translucency);
        }
        auto make = [&](Texture& t, const std::vector<glm::vec4>& data) {
            t = createTexture(GL_TEXTURE_2D_ARRAY);
            glTextureStorage3D(t.id(), 1, GL_RGBA32F, size, size, 1);
            glTextureSubImage3D(t.id(), 0, 0, 0, 0, size, size, 1, GL_RGBA, GL_FLOAT, data.data());
        };
        make(position, p);
        make(normal, n);
        make(flux, f);
    }
};

float maxAbs(const std::array<std::vector<glm::vec4>, 3>& a) {
    float m = 0.0f;
    for (const auto& channel : a)
        for (const glm::vec4& v : channel)
            for (int j = 0; j < 4; ++j)
                m = std::max(m, std::abs(v[j]));
    return m;
}

class LpvSubsurfaceGLTest : public GlTest {};

TEST_F(LpvSubsurfaceGLTest, InjectionAndAttenuatedPropagationMatchReference) {
    auto lpvPass = LpvPass::create();
    ASSERT_TRUE(lpvPass.has_value()) << lpvPass.error().describe();
    auto sss = LpvSubsurfacePass::create();
    ASSERT_TRUE(sss.has_value()) << sss.error().describe();

    // 300 VPLs in a 12^3 cascade: a third opaque (translucency 0), the rest
    // translucent by a random amount.
    const ref::GridFrame grid{glm::vec3(-1.0f, 0.5f, 2.0f), 0.25f, 12};
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<ref::TranslucentVpl> texels;
    for (int i = 0; i < 300; ++i) {
        const glm::vec3 p = grid.origin + glm::vec3(u(rng), u(rng), u(rng)) * (grid.cellSize * float(grid.n));
        const float translucency = i % 3 == 0 ? 0.0f : u(rng);
        texels.push_back({{p, randomUnit(rng), 2.0f * glm::vec3(u(rng), u(rng), u(rng))}, translucency});
    }
    const TranslucentRsm rsm(18, texels);
    const LpvRsmInput input = rsmInputOf(rsm, {LpvCascade{grid.origin, grid.cellSize, grid.n}}, {0.01f});

    LpvSettings settings;
    settings.gridSize = grid.n;
    settings.propagationSteps = 2;
    settings.occlusion = false;
    settings.gvFromCamera = false;
    const ref::ShGrid injected = ref::injectSubsurface(grid, texels);
    std::array<std::vector<glm::vec4>, 3> lpvFirst;
    for (int steps : {0, 1, 4}) {
        const LpvSubsurfaceSettings sssSettings{steps, 0.3f};
        GpuTimer timer;
        timer.beginFrame();
        ASSERT_TRUE(lpvPass->run(settings, input, nullptr, timer).has_value());
        const auto lpvBefore = lpvPass->readAccumulator(0);
        sss->run(sssSettings, *lpvPass, input);
        // The LPV itself is untouched, and the shared fixed-point sums are left
        // cleared: the next frame's LPV (the next iteration here) is the same.
        EXPECT_EQ(lpvPass->readAccumulator(0), lpvBefore);
        if (lpvFirst[0].empty())
            lpvFirst = lpvBefore;
        EXPECT_EQ(lpvBefore, lpvFirst) << "the LPV of a later frame changed";

        const auto gpu = sss->readAccumulator(0);
        const ref::ShGrid expected = ref::propagateSubsurface(injected, steps, sssSettings.attenuation);
        float diff = 0.0f, peak = 0.0f;
        for (int c = 0; c < 3; ++c)
            for (std::size_t i = 0; i < expected.channel[c].size(); ++i)
                for (int j = 0; j < 4; ++j) {
                    diff = std::max(diff, std::abs(gpu[std::size_t(c)][i][j] - expected.channel[c][i][j]));
                    peak = std::max(peak, std::abs(expected.channel[c][i][j]));
                }
        std::cout << "[ figures ] subsurface, " << steps
                  << " steps, attenuation 0.3: max |GPU - CPU| = " << diff << " of max " << peak
                  << " (relative " << diff / peak << ")\n";
        ASSERT_GT(peak, 0.0f);
        EXPECT_LT(diff / peak, 2e-5f);
    }
    EXPECT_GT(sss->allocatedBytes(), 0u);
    EXPECT_GT(maxAbs(lpvFirst), 0.0f);
}

// --- Through the whole renderer ---

constexpr int kW = 160, kH = 120;
const glm::vec3 kSlabAlbedo(0.9f, 0.5f, 0.3f);

// Open ground, a thin upright slab (2 x 2 x 0.06 m) between the camera and a
// low sun: the sun lights the slab's far face, the camera sees its near one.
scene::Scene slabLitFromBehind(float translucency) {
    scene::Scene s;
    s.meshes.push_back(scene::makePlane(8));
    s.meshes.push_back(scene::makeBox());
    for (scene::Submesh& sub : s.meshes[1].submeshes)
        sub.materialIndex = 1;
    s.materials.emplace_back(); // ground: opaque grey
    scene::Material slab;
    slab.name = "slab";
    slab.diffuseColor = kSlabAlbedo;
    slab.translucency = translucency;
    s.materials.push_back(slab);
    scene::Object ground;
    ground.mesh = 0;
    ground.transform.scale = glm::vec3(12.0f);
    s.objects.push_back(ground);
    scene::Object wall;
    wall.mesh = 1;
    wall.transform.translation = {0.0f, 1.1f, 0.0f};
    wall.transform.scale = {2.0f, 2.0f, 0.06f};
    s.objects.push_back(wall);
    scene::Light sun;
    sun.direction = glm::normalize(glm::vec3(0.15f, -0.5f, 1.0f)); // from behind the slab toward the camera
    sun.intensity = 3.0f;
    s.lights.push_back(sun);
    scene::Camera camera;
    camera.position = {0.0f, 1.4f, 3.5f};
    camera.target = {0.0f, 1.0f, 0.0f};
    camera.fovY = glm::radians(55.0f);
    s.cameras.push_back(camera);
    return s;
}

scene::ParameterSet smallLpv(const char* subsurface) {
    scene::ParameterSet p;
    for (auto [key, value] : {std::pair{"lpv.gridSize", "16"},
                              {"lpv.cascades", "2"},
                              {"rsm.cascades", "2"},
                              {"rsm.tileSize", "128"},
                              {"lpv.cellSize", "0.25"},
                              {"effects.sunRays", "off"},
                              {"effects.skyInjection", "off"},
                              {"shadow.mapSize", "512"},
                              {"shadow.cascades", "2"},
                              {"lpv.reuse", "false"},
                              {"effects.subsurface", subsurface}})
        EXPECT_TRUE(p.setFromText(key, value, "test").has_value()) << key;
    return p;
}

struct SlabFrame {
    std::vector<float> hdr, albedo, normal;
    EffectDecision decision;
    std::size_t bytes = 0;
    bool timed = false;
};

SlabFrame renderSlab(ForwardRenderer& r, const scene::Scene& s, const char* subsurface) {
    const scene::ParameterSet params = smallLpv(subsurface);
    r.setScene(s);
    r.timer().resolveAll(); // nothing of the last render lands in this one's table
    r.timer().clearHistory();
    // Two frames: the geometry volume also takes the previous frame's G-buffer.
    for (int i = 0; i < 2; ++i) {
        auto ok = r.render(s, params, s.cameras.front(), kW, kH);
        EXPECT_TRUE(ok.has_value()) << (ok ? "" : ok.error().describe());
    }
    SlabFrame f{r.readHdr(), r.readGBufferAlbedo(),        r.readGBufferNormal(),
                {},          r.subsurfaceAllocatedBytes(), false};
    for (const EffectDecision& d : r.frameEffects())
        if (d.parameter == "effects.subsurface")
            f.decision = d;
    r.timer().resolveAll();
    for (const auto& row : r.timer().table())
        f.timed |= row.samples > 0 && row.pass == "subsurface";
    return f;
}

bool isSlab(const SlabFrame& f, std::size_t i) {
    return std::abs(f.albedo[4 * i] - kSlabAlbedo.r) < 0.02f &&
           std::abs(f.albedo[4 * i + 1] - kSlabAlbedo.g) < 0.02f &&
           std::abs(f.albedo[4 * i + 2] - kSlabAlbedo.b) < 0.02f;
}

TEST_F(LpvSubsurfaceGLTest, SlabLitFromBehindIsBrighterOnItsUnlitSideOpaqueGroundUnchanged) {
    auto r = ForwardRenderer::create();
    ASSERT_TRUE(r.has_value()) << r.error().describe();
    const scene::Scene s = slabLitFromBehind(0.8f);
    const SlabFrame off = renderSlab(*r, s, "off");
    EXPECT_FALSE(off.decision.runs());
    EXPECT_EQ(off.bytes, 0u);
    EXPECT_FALSE(off.timed);
    const SlabFrame on = renderSlab(*r, s, "auto");
    EXPECT_TRUE(on.decision.runs()) << on.decision.reason;
    EXPECT_NE(on.decision.reason.find("translucent"), std::string::npos) << on.decision.reason;
    EXPECT_GT(on.bytes, 0u);
    EXPECT_TRUE(on.timed);

    // The slab's near face (normal toward the camera, +z) is in its own shadow.
    double slabOff = 0.0, slabOn = 0.0, groundDiff = 0.0;
    int slabPixels = 0, groundPixels = 0;
    for (std::size_t i = 0; i < std::size_t(kW) * kH; ++i) {
        if (isSlab(on, i) && on.normal[4 * i + 2] > 0.9f) {
            ++slabPixels;
            for (int c = 0; c < 3; ++c) {
                slabOff += off.hdr[4 * i + std::size_t(c)];
                slabOn += on.hdr[4 * i + std::size_t(c)];
            }
        } else if (on.albedo[4 * i + 3] > 0.0f && !isSlab(on, i)) {
            ++groundPixels;
            for (int c = 0; c < 3; ++c)
                groundDiff = std::max(groundDiff, double(std::abs(on.hdr[4 * i + std::size_t(c)] -
                                                                  off.hdr[4 * i + std::size_t(c)])));
        }
    }
    const double ratio = slabOn / slabOff;
    std::cout << "[ figures ] unlit face of the slab (" << slabPixels << " px): mean HDR off "
              << slabOff / (3.0 * slabPixels) << ", on " << slabOn / (3.0 * slabPixels) << ", on / off "
              << ratio << "; opaque ground (" << groundPixels << " px): max |on - off| " << groundDiff
              << "; subsurface volumes " << double(on.bytes) / (1024.0 * 1024.0) << " MiB\n";
    ASSERT_GT(slabPixels, 500);
    ASSERT_GT(groundPixels, 2000);
    EXPECT_GT(slabOff, 0.0);
    EXPECT_GT(ratio, 2.0) << "light crossing the slab brightens its unlit face";
    EXPECT_LT(groundDiff, 1e-6) << "opaque surfaces do not read the subsurface LPV";
}

TEST_F(LpvSubsurfaceGLTest, WithoutTranslucentMaterialThePassDoesNotRunAndHoldsNothing) {
    auto r = ForwardRenderer::create();
    ASSERT_TRUE(r.has_value()) << r.error().describe();
    const SlabFrame translucent = renderSlab(*r, slabLitFromBehind(0.8f), "auto");
    ASSERT_TRUE(translucent.decision.runs());
    ASSERT_GT(translucent.bytes, 0u);
    // Same renderer, same scene with an opaque slab: the volumes go away.
    const SlabFrame opaque = renderSlab(*r, slabLitFromBehind(0.0f), "auto");
    EXPECT_FALSE(opaque.decision.wanted);
    EXPECT_NE(opaque.decision.reason.find("no visible material is translucent"), std::string::npos)
        << opaque.decision.reason;
    EXPECT_EQ(opaque.bytes, 0u);
    EXPECT_FALSE(opaque.timed);
    // Forced on, it runs even then (for comparisons) and adds nothing to an opaque scene.
    const SlabFrame forced = renderSlab(*r, slabLitFromBehind(0.0f), "on");
    EXPECT_TRUE(forced.decision.runs());
    EXPECT_TRUE(forced.timed);
    EXPECT_EQ(forced.hdr, opaque.hdr);
}

// The forward shader's two builds: with the subsurface sampler (17 in the
// fragment stage, where GL_MAX_TEXTURE_IMAGE_UNITS allows) and without it
// (GL's minimum of 16), which ForwardRenderer picks on such a driver.
TEST_F(LpvSubsurfaceGLTest, ForwardShaderBuildsWithAndWithoutTheSubsurfaceSampler) {
    auto countSamplers = [](GLuint program) {
        GLint uniforms = 0, samplers = 0;
        glGetProgramiv(program, GL_ACTIVE_UNIFORMS, &uniforms);
        for (GLint i = 0; i < uniforms; ++i) {
            GLint size = 0;
            GLenum type = 0;
            char name[128];
            glGetActiveUniform(program, GLuint(i), sizeof(name), nullptr, &size, &type, name);
            samplers += type == GL_SAMPLER_2D || type == GL_SAMPLER_3D || type == GL_SAMPLER_2D_ARRAY ||
                                type == GL_SAMPLER_2D_ARRAY_SHADOW || type == GL_SAMPLER_CUBE_MAP_ARRAY ||
                                type == GL_SAMPLER_CUBE_MAP_ARRAY_SHADOW || type == GL_SAMPLER_2D_SHADOW
                            ? size
                            : 0;
        }
        return samplers;
    };
    GLint units = 0;
    glGetIntegerv(GL_MAX_TEXTURE_IMAGE_UNITS, &units);
    auto without = buildEmbeddedProgram({"forward.vert", "forward.frag"}, {"LPV_NO_SUBSURFACE_SAMPLER 1"});
    ASSERT_TRUE(without.has_value()) << without.error().describe();
    EXPECT_EQ(glGetUniformLocation(without->id(), "uLpvSubsurfaceVolume"), -1);
    const int minimum = countSamplers(without->id());
    std::cout << "[ figures ] GL_MAX_TEXTURE_IMAGE_UNITS " << units
              << "; forward.frag samplers without the subsurface "
              << "volume " << minimum << "\n";
    EXPECT_LE(minimum, 16) << "the build for GL's minimum must fit it";
    if (units < 17)
        GTEST_SKIP() << "this GL cannot build the 17-sampler variant";
    auto with = buildEmbeddedProgram({"forward.vert", "forward.frag"});
    ASSERT_TRUE(with.has_value()) << with.error().describe();
    EXPECT_NE(glGetUniformLocation(with->id(), "uLpvSubsurfaceVolume"), -1);
    EXPECT_EQ(countSamplers(with->id()), minimum + 1);
}

} // namespace
