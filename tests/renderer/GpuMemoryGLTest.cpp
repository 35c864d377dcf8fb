// ForwardRenderer::gpuMemory() on the built-in Cornell box (issue #43 item 3):
// the LPV's bytes are what its formats and sizes give, counted here from the
// layout docs/lpv.md describes rather than from the renderer's own formulas;
// the RSM's grow with the square of its tile; every allocation is named,
// sized and counted once.
#include "GlFixture.h"

#include "gl/GpuMemoryLedger.h"
#include "lpv/renderer/ForwardRenderer.h"
#include "lpv/renderer/GpuMemory.h"
#include "lpv/scene/CornellBox.h"

#include <algorithm>
#include <cstdint>
#include <string>

using namespace lpv;

namespace {

constexpr int kSize = 64;

class GpuMemoryGLTest : public GlTest {
  protected:
    void SetUp() override {
        GlTest::SetUp();
        params = project.parameters;
        // The LPV's optional volumes fixed, so the expected layout is known:
        // the compute gather (with its interleaved ping-pong), one bounce,
        // undirected, no visibility moments, no subsurface LPV.
        for (auto [key, value] : {std::pair{"lpv.variant", "computeGather"},
                                  {"lpv.directedPropagation", "off"},
                                  {"lpv.bounces", "1"},
                                  {"lpv.visibilityLookup", "false"},
                                  {"effects.subsurface", "off"}})
            EXPECT_TRUE(params.setFromText(key, value).has_value()) << key;
    }

    renderer::GpuMemory render(const scene::Scene& scene) {
        auto r = renderer::ForwardRenderer::create();
        EXPECT_TRUE(r.has_value()) << (r ? "" : r.error().describe());
        if (!r)
            return {};
        r->setScene(scene);
        auto ok = r->render(scene, params, scene.cameras.front(), kSize, kSize);
        EXPECT_TRUE(ok.has_value()) << (ok ? "" : ok.error().describe());
        EXPECT_NE(r->lpvNote().find("LPV: " + std::to_string(cascades()) + " cascades"), std::string::npos)
            << r->lpvNote();
        renderer::GpuMemory memory = r->gpuMemory();
        checkConsistent(memory);
        return memory;
    }
    renderer::GpuMemory renderGrid(int gridSize) {
        EXPECT_TRUE(params.set("lpv.gridSize", gridSize).has_value());
        return render(project.scene);
    }
    int cascades() const { return std::min(params.getInt("lpv.cascades"), params.getInt("rsm.cascades")); }

    // What every report must satisfy, whatever the settings.
    static void checkConsistent(const renderer::GpuMemory& memory) {
        ASSERT_FALSE(memory.allocations.empty());
        std::uint64_t sum = 0;
        for (std::size_t i = 0; i < memory.allocations.size(); ++i) {
            const renderer::GpuAllocation& a = memory.allocations[i];
            sum += a.bytes;
            EXPECT_GT(a.bytes, 0u) << a.name << ": " << a.what;
            EXPECT_EQ(a.what.find("unknown"), std::string::npos) << a.name << ": " << a.what;
            EXPECT_FALSE(a.name.empty());
            if (i > 0) {
                EXPECT_GE(memory.allocations[i - 1].bytes, a.bytes) << "largest first: " << a.name;
            }
            for (std::size_t j = 0; j < i; ++j)
                EXPECT_NE(memory.allocations[j].name, a.name) << "one line per name";
        }
        EXPECT_EQ(memory.totalBytes, sum);
    }

    std::uint64_t bytesOf(const renderer::GpuMemory& memory, const std::string& name) {
        const renderer::GpuAllocation* a = memory.find(name);
        EXPECT_NE(a, nullptr) << name;
        return a ? a->bytes : 0;
    }

    scene::Project project = scene::makeCornellBoxProject();
    scene::ParameterSet params;
};

// Every LPV volume is RGBA32F (16 bytes a texel), the K cascades stacked along
// z; the sums are 32-bit integers.
TEST_F(GpuMemoryGLTest, LpvVolumesAreExactlyTheirFormatsAndSizes) {
    for (int n : {16, 32}) {
        SCOPED_TRACE("lpv.gridSize " + std::to_string(n));
        const renderer::GpuMemory memory = renderGrid(n);
        const std::uint64_t N = std::uint64_t(n), K = std::uint64_t(cascades()), M = N + 1;
        const std::uint64_t cells = N * N * N * K, gvCells = M * M * M * K, texel = 16, word = 4;
        EXPECT_EQ(bytesOf(memory, "lpv.volumes"), 2 * 3 * cells * texel); // ping-pong x R, G, B
        EXPECT_EQ(bytesOf(memory, "lpv.accumulator"), 3 * cells * texel);
        EXPECT_EQ(bytesOf(memory, "lpv.geometry"), gvCells * texel);
        EXPECT_EQ(bytesOf(memory, "lpv.faceBlocking"), 3 * cells * texel);
        EXPECT_EQ(bytesOf(memory, "lpv.interleaved"), 2 * 3 * cells * texel);
        EXPECT_EQ(bytesOf(memory, "lpv.lpvSums"), 12 * cells * word);
        EXPECT_EQ(bytesOf(memory, "lpv.gvSums"), 2 * 4 * gvCells * word);
        EXPECT_EQ(bytesOf(memory, "lpv.scales"), 3 * K * word);
        const std::uint64_t lpv = (6 + 3 + 3 + 6) * cells * texel + gvCells * texel + 12 * cells * word +
                                  8 * gvCells * word + 3 * K * word;
        EXPECT_EQ(memory.bytesOf("lpv."), lpv);
        const std::string stacked =
            std::to_string(n) + "x" + std::to_string(n) + "x" + std::to_string(n * cascades());
        EXPECT_EQ(memory.find("lpv.volumes")->what, "6 x 3D RGBA32F " + stacked);
        // The camera's graph-owned targets at 64 x 64.
        EXPECT_EQ(bytesOf(memory, "camera.hdr"), std::uint64_t(kSize * kSize * 8));
        EXPECT_EQ(bytesOf(memory, "camera.depth"), std::uint64_t(kSize * kSize * 4));
    }
}

// The volumes of the LPV's options count while they run: directed
// propagation's normals (ping-pong RGBA32F) and their integer sums, the
// bounces' running total (R, G, B), the visibility moments (3N wide).
TEST_F(GpuMemoryGLTest, OptionalLpvVolumesCountWhileTheyRun) {
    const std::uint64_t base = renderGrid(16).bytesOf("lpv.");
    for (auto [key, value] :
         {std::pair{"lpv.directedPropagation", "on"}, {"lpv.bounces", "2"}, {"lpv.visibilityLookup", "true"}})
        ASSERT_TRUE(params.setFromText(key, value).has_value()) << key;
    const renderer::GpuMemory memory = renderGrid(16);
    const std::uint64_t cells = 16u * 16u * 16u * std::uint64_t(cascades());
    EXPECT_EQ(bytesOf(memory, "lpv.normals"), 2 * cells * 16);
    EXPECT_EQ(bytesOf(memory, "lpv.normalSums"), 4 * cells * 4);
    EXPECT_EQ(bytesOf(memory, "lpv.bounceTotal"), 3 * cells * 16);
    EXPECT_EQ(bytesOf(memory, "lpv.visibility"), 3 * cells * 16);
    EXPECT_EQ(memory.bytesOf("lpv."), base + (2 + 3 + 3) * cells * 16 + 4 * cells * 4);
}

TEST_F(GpuMemoryGLTest, DoublingTheGridGivesEightTimesTheLpvChannels) {
    const renderer::GpuMemory coarse = renderGrid(16), fine = renderGrid(32);
    auto channels = [&](const renderer::GpuMemory& m) {
        return bytesOf(m, "lpv.volumes") + bytesOf(m, "lpv.accumulator");
    };
    ASSERT_GT(channels(coarse), 0u);
    EXPECT_EQ(channels(fine), 8 * channels(coarse));
    // The frame graph's camera targets do not depend on the grid.
    EXPECT_EQ(bytesOf(fine, "camera.hdr"), bytesOf(coarse, "camera.hdr"));
    EXPECT_EQ(fine.totalBytes - fine.bytesOf("lpv."), coarse.totalBytes - coarse.bytesOf("lpv."));
}

// The sun's RSM: position and flux RGBA32F, normal RGBA16F, depth 32F per
// texel of rsm.cascades tiles. The Cornell box has only its area light, so the sun is added.
TEST_F(GpuMemoryGLTest, RsmTileSizeScalesTheRsmByItsSquare) {
    scene::Scene scene = project.scene;
    scene::Light sun;
    sun.name = "sun";
    sun.type = scene::LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
    sun.intensity = 1.0f;
    scene.lights.push_back(sun);
    std::uint64_t rsm[2] = {};
    for (int i = 0; i < 2; ++i) {
        const int tile = i == 0 ? 256 : 512;
        SCOPED_TRACE("rsm.tileSize " + std::to_string(tile));
        ASSERT_TRUE(params.set("rsm.tileSize", tile).has_value());
        const renderer::GpuMemory memory = render(scene);
        rsm[i] = memory.bytesOf("rsm.");
        const std::uint64_t texels =
            std::uint64_t(tile) * std::uint64_t(tile) * std::uint64_t(params.getInt("rsm.cascades"));
        EXPECT_EQ(rsm[i], texels * (16 + 8 + 16 + 4));
        EXPECT_EQ(bytesOf(memory, "rsm.flux"), texels * 16);
    }
    EXPECT_EQ(rsm[1], 4 * rsm[0]);
}

// The area light's local RSM follows lpv.localRsmSize the same way.
TEST_F(GpuMemoryGLTest, LocalRsmSizeScalesTheLocalRsmByItsSquare) {
    std::uint64_t bytes[2] = {};
    for (int i = 0; i < 2; ++i) {
        ASSERT_TRUE(params.set("lpv.localRsmSize", i == 0 ? 64 : 128).has_value());
        bytes[i] = render(project.scene).bytesOf("localRsm.");
    }
    ASSERT_GT(bytes[0], 0u);
    EXPECT_EQ(bytes[1], 4 * bytes[0]);
}

TEST_F(GpuMemoryGLTest, NothingBeforeTheFirstFrame) {
    auto r = renderer::ForwardRenderer::create();
    ASSERT_TRUE(r.has_value());
    const renderer::GpuMemory memory = r->gpuMemory();
    std::uint64_t sum = 0;
    for (const renderer::GpuAllocation& a : memory.allocations)
        sum += a.bytes;
    EXPECT_EQ(memory.totalBytes, sum);
    EXPECT_EQ(memory.bytesOf("lpv."), 0u);
    EXPECT_EQ(memory.find("camera.hdr"), nullptr);
}

// The ledger itself: mip levels asked of GL, an object met twice counted
// once under its first name, a texture and a buffer of the same GL name both counted.
TEST_F(GpuMemoryGLTest, LedgerCountsMipLevelsAndEachObjectOnce) {
    renderer::Texture mipped = renderer::createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(mipped.id(), 3, GL_RGBA8, 8, 4); // 32 + 8 + 2 texels
    renderer::Texture volume = renderer::createTexture(GL_TEXTURE_3D);
    glTextureStorage3D(volume.id(), 1, GL_RGBA32F, 4, 4, 8);
    renderer::Buffer buffer = renderer::createBuffer();
    glNamedBufferStorage(buffer.id(), 100, nullptr, 0);
    ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));

    renderer::GpuMemoryLedger ledger;
    ledger.addTexture("a.mipped", mipped.id());
    ledger.addTexture("b.volume", volume.id());
    ledger.addTexture("b.volume.again", volume.id()); // the same object: nothing more
    ledger.addResource("graph.view", volume.id(), renderer::graph::queryTexture(volume.id()));
    ledger.addBuffer("c.buffer", buffer.id());
    ledger.addTexture("empty", 0);
    const renderer::GpuMemory memory = ledger.finish();
    checkConsistent(memory);
    ASSERT_EQ(memory.allocations.size(), 3u);
    EXPECT_EQ(memory.allocations[0].name, "b.volume");
    EXPECT_EQ(memory.allocations[0].bytes, 4u * 4u * 8u * 16u);
    EXPECT_EQ(bytesOf(memory, "a.mipped"), (32u + 8u + 2u) * 4u);
    EXPECT_EQ(memory.find("a.mipped")->what, "2D RGBA8 8x4, 3 levels");
    EXPECT_EQ(bytesOf(memory, "c.buffer"), 100u);
    EXPECT_EQ(memory.totalBytes, 4u * 4u * 8u * 16u + 42u * 4u + 100u);
}

} // namespace
