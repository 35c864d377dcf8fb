// The slice viewer against known light (issue #9): one VPL of known flux in
// an empty volume, one propagation step of an isotropic point, the read-back
// that only happens on request, and the RSM flux view of the Cornell box.
#include "FrontSun.h"
#include "LpvPassFixture.h"

#include "passes/lpv/LpvPass.h"
#include "lpv/renderer/ForwardRenderer.h"
#include "lpv/renderer/GpuTimer.h"
#include "lpv/renderer/lpv/LpvReference.h"
#include "lpv/renderer/viz/LpvViews.h"
#include "lpv/renderer/viz/TileImages.h"
#include "lpv/scene/CornellBox.h"

#include <cmath>

using namespace lpv::renderer;
namespace ref = lpv::renderer::lpvref;

namespace {

constexpr int kGrid = 8;

class LpvVisualizerGLTest : public LpvPassGLTest {
  protected:
    // One cascade of 8^3 unit cells at the origin, no injection offset, compute gather.
    void run(const std::vector<Texel>& texels, int steps, std::optional<LpvCaptureRequest> capture) {
        FakeRsm rsm(4, {texels});
        LpvSettings settings;
        settings.gridSize = kGrid;
        settings.propagationSteps = steps;
        settings.injectionOffset = 0.0f;
        settings.occlusion = false;
        settings.gvFromCamera = false;
        pass_->setCapture(capture);
        runPass(settings, rsmInputOf(rsm, {LpvCascade{glm::vec3(0.0f), 1.0f, kGrid}}, {0.01f}));
    }

};

viz::LpvViewSpec zSlice(viz::LpvSource source, int z, viz::Channel channel) {
    viz::LpvViewSpec spec;
    spec.source = source;
    spec.slice.axis = viz::Axis::Z;
    spec.slice.index = z;
    spec.slice.channel = channel;
    return spec;
}

// The largest value of a field and where it is.
struct Peak {
    int u = -1, v = -1;
    float value = 0.0f;
};
Peak peakOf(const viz::SliceField& f) {
    Peak p;
    for (int v = 0; v < f.height; ++v)
        for (int u = 0; u < f.width; ++u)
            if (f.at(u, v) > p.value)
                p = {u, v, f.at(u, v)};
    return p;
}

} // namespace

// One VPL of flux (2, 1, 0.5) W facing +y in cell (3, 4, 2): band 0 of the
// injected volume is flux / pi * 0.886227 in that cell and zero elsewhere,
// and the picture's brightest pixel lies in that cell.
TEST_F(LpvVisualizerGLTest, SingleVplPeaksInItsCellWithItsFlux) {
    const glm::vec3 flux(2.0f, 1.0f, 0.5f);
    run({{glm::vec3(3.5f, 4.5f, 2.5f), glm::vec3(0, 1, 0), flux}}, 2, LpvCaptureRequest{0, 0});
    const auto& snapshot = pass_->snapshot();
    ASSERT_TRUE(snapshot.has_value());
    EXPECT_EQ(snapshot->step, 0);
    EXPECT_EQ(snapshot->propagationSteps, 2);

    for (int c = 0; c < 3; ++c) {
        const auto field = viz::lpvViewField(*snapshot, zSlice(viz::LpvSource::Injected, 2, viz::Channel(c)));
        ASSERT_TRUE(field.has_value()) << field.error().describe();
        const Peak peak = peakOf(*field);
        EXPECT_EQ(peak.u, 3);
        EXPECT_EQ(peak.v, 4);
        const float expected = flux[c] / sh::kPi * sh::kCos0;
        EXPECT_NEAR(peak.value, expected, 1e-5f * expected);
        float elsewhere = 0.0f;
        for (int v = 0; v < kGrid; ++v)
            for (int u = 0; u < kGrid; ++u)
                if (u != 3 || v != 4)
                    elsewhere = std::max(elsewhere, std::abs(field->at(u, v)));
        EXPECT_EQ(elsewhere, 0.0f);
    }
    // The neighbouring slice is empty.
    const auto next =
        viz::lpvViewField(*snapshot, zSlice(viz::LpvSource::Injected, 3, viz::Channel::Luminance));
    ASSERT_TRUE(next.has_value());
    EXPECT_EQ(peakOf(*next).u, -1);

    // Coefficient Y1-1 of a lobe facing +y: -1.023327 * flux / pi.
    auto spec = zSlice(viz::LpvSource::Injected, 2, viz::Channel::Red);
    spec.slice.quantity = viz::Quantity::Coefficient;
    spec.slice.coefficient = 1;
    const auto coefficient = viz::lpvViewField(*snapshot, spec);
    ASSERT_TRUE(coefficient.has_value());
    EXPECT_NEAR(coefficient->at(3, 4), -sh::kCos1 * flux.r / sh::kPi, 1e-5f);

    // The image: 8 pixels per cell, v up, so cell (3, 4) is pixels x 24..31, y 24..31 from the top.
    spec = zSlice(viz::LpvSource::Injected, 2, viz::Channel::Luminance);
    spec.colour.pixelsPerCell = 8;
    const auto image = viz::renderLpvView(*snapshot, spec);
    ASSERT_TRUE(image.has_value());
    int brightest = -1, bx = 0, by = 0;
    for (int y = 0; y < kGrid * 8; ++y)
        for (int x = 0; x < kGrid * 8; ++x) {
            const std::uint8_t* p =
                &image->pixels[(std::size_t(y) * std::size_t(image->width) + std::size_t(x)) * 4];
            if (p[0] + p[1] + p[2] > brightest) {
                brightest = p[0] + p[1] + p[2];
                bx = x;
                by = y;
            }
        }
    EXPECT_EQ(bx / 8, 3);
    EXPECT_EQ(by / 8, kGrid - 1 - 4);
    EXPECT_GT(image->height, kGrid * 8) << "the legend strip sits under the slice";
}

// One step after an isotropic point: its 6 axis neighbours hold the same
// light (the CPU reference's value), the point's own cell and the diagonal
// cells none; the accumulator holds both steps.
TEST_F(LpvVisualizerGLTest, OneStepLightsTheSixNeighbours) {
    std::vector<Texel> point;
    for (const glm::vec3 n : {glm::vec3(1, 0, 0), glm::vec3(-1, 0, 0), glm::vec3(0, 1, 0),
                              glm::vec3(0, -1, 0), glm::vec3(0, 0, 1), glm::vec3(0, 0, -1)})
        point.push_back({glm::vec3(4.5f), n, glm::vec3(3.0f)});
    run(point, 3, LpvCaptureRequest{0, 1});
    const auto& snapshot = pass_->snapshot();
    ASSERT_TRUE(snapshot.has_value());
    EXPECT_EQ(snapshot->step, 1);

    std::vector<ref::Vpl> vpls;
    for (const Texel& t : point)
        vpls.push_back({t.position, t.normal, t.flux});
    const ref::ShGrid v0 = ref::injectVpls({glm::vec3(0.0f), 1.0f, kGrid}, vpls, 0.0f);
    const ref::ShGrid v1 = ref::propagateStep(v0, nullptr);
    const float neighbour = v1.at(0, 5, 4, 4).x;
    ASSERT_GT(neighbour, 0.0f);

    const auto mid = viz::lpvViewField(*snapshot, zSlice(viz::LpvSource::Step, 4, viz::Channel::Red));
    const auto below = viz::lpvViewField(*snapshot, zSlice(viz::LpvSource::Step, 3, viz::Channel::Red));
    const auto above = viz::lpvViewField(*snapshot, zSlice(viz::LpvSource::Step, 5, viz::Channel::Red));
    ASSERT_TRUE(mid && below && above);
    for (const float v :
         {mid->at(5, 4), mid->at(3, 4), mid->at(4, 5), mid->at(4, 3), below->at(4, 4), above->at(4, 4)})
        EXPECT_NEAR(v, neighbour, 1e-4f * neighbour);
    EXPECT_NEAR(mid->at(4, 4), 0.0f, 1e-6f) << "V_1 holds no light in the source cell";
    EXPECT_NEAR(mid->at(5, 5), 0.0f, 1e-6f) << "diagonal cells are two steps away";
    EXPECT_NEAR(below->at(5, 4), 0.0f, 1e-6f);

    const auto accumulated =
        viz::lpvViewField(*snapshot, zSlice(viz::LpvSource::Accumulated, 4, viz::Channel::Red));
    ASSERT_TRUE(accumulated.has_value());
    EXPECT_NEAR(accumulated->at(4, 4), v0.at(0, 4, 4, 4).x, 1e-4f * v0.at(0, 4, 4, 4).x);
    EXPECT_NEAR(accumulated->at(5, 4), neighbour, 1e-4f * neighbour);
}

// Reading back costs a GPU stall, so without a request nothing is read; a
// cascade out of range gives no snapshot; a step past the last is the last.
TEST_F(LpvVisualizerGLTest, ReadsBackOnlyOnRequest) {
    const std::vector<Texel> vpl{{glm::vec3(2.5f), glm::vec3(0, 0, 1), glm::vec3(1.0f)}};
    run(vpl, 2, std::nullopt);
    EXPECT_FALSE(pass_->snapshot().has_value());
    run(vpl, 2, LpvCaptureRequest{1, 0});
    EXPECT_FALSE(pass_->snapshot().has_value());
    run(vpl, 2, LpvCaptureRequest{0, 99});
    ASSERT_TRUE(pass_->snapshot().has_value());
    EXPECT_EQ(pass_->snapshot()->step, 2);
    EXPECT_TRUE(pass_->snapshot()->geometry.empty()) << "occlusion is off: no geometry volume to show";
    pass_->setCapture(std::nullopt);
    EXPECT_FALSE(pass_->snapshot().has_value()) << "closing the view frees the copy";
}

// The RSM flux view of the Cornell box under a sun shining in through the
// open front: the texels of the red wall (normal -x) show red.
TEST_F(GlTest, CornellRsmFluxViewShowsTheRedWallRed) {
    lpv::scene::Project project = lpv::scene::makeCornellBoxProject();
    lpv::scene::Scene& s = project.scene;
    s.lights.push_back(lpv::test::cornellFrontSun());
    ASSERT_TRUE(project.parameters.set("rsm.tileSize", 64).has_value());
    auto renderer = ForwardRenderer::create();
    ASSERT_TRUE(renderer.has_value()) << renderer.error().describe();
    renderer->setScene(s);
    ASSERT_TRUE(renderer->render(s, project.parameters, s.cameras.front(), 32, 32).has_value());
    const auto all = renderer->debugImages("rsm");
    ASSERT_FALSE(all.empty());

    int redWall = 0, red = 0;
    for (int k = 0; k < project.parameters.getInt("rsm.cascades"); ++k) {
        const auto tiles = viz::imagesNamed(all, "rsm-" + std::to_string(k) + "-");
        ASSERT_EQ(tiles.size(), 3u);
        const DebugImage& position = tiles[0];
        const DebugImage& normal = tiles[1];
        const lpv::scene::Image8 flux = viz::debugImageView(tiles[2]);
        for (std::size_t i = 0; i < std::size_t(normal.width * normal.height); ++i) {
            // The red wall: x = 5.528..5.56 m, facing -x (the tall block has faces turned that way too).
            if (normal.pixels[i * 4 + 3] == 0.0f || normal.pixels[i * 4] > -0.9f ||
                position.pixels[i * 4] < 5.45f)
                continue;
            ++redWall;
            const std::uint8_t* p = &flux.pixels[i * 4];
            if (p[0] > 3 * std::max(p[1], p[2]) && p[0] > 20)
                ++red;
        }
    }
    ASSERT_GT(redWall, 20) << "the sun must reach the red wall through the open front";
    EXPECT_EQ(red, redWall);
}

// The shadow-map visualizer's tint: surfaces take their sun cascade's colour
// (the nearest ones cascade 0, red), and switching it off restores the frame.
TEST_F(GlTest, ShadowCascadeTintColoursSurfacesByCascade) {
    lpv::scene::Project project = lpv::scene::makeCornellBoxProject();
    lpv::scene::Scene& s = project.scene;
    s.lights.push_back(lpv::test::cornellFrontSun());
    ASSERT_TRUE(project.parameters.set("lpv.intensity", 0.0).has_value());
    ASSERT_TRUE(project.parameters.set("shadow.mapSize", 256).has_value());
    // A camera inside the box near the floor, looking at the back wall: the floor under it is in cascade 0.
    lpv::scene::Camera camera = s.cameras.front();
    camera.position = {2.78f, 0.3f, 1.0f};
    camera.target = {2.78f, 0.0f, 1.6f};
    auto renderer = ForwardRenderer::create();
    ASSERT_TRUE(renderer.has_value()) << renderer.error().describe();
    renderer->setScene(s);
    ASSERT_TRUE(renderer->render(s, project.parameters, camera, 32, 32).has_value());
    const std::vector<float> plain = renderer->readHdr();
    renderer->setShadowCascadeTint(true);
    ASSERT_TRUE(renderer->render(s, project.parameters, camera, 32, 32).has_value());
    const std::vector<float> tinted = renderer->readHdr();
    renderer->setShadowCascadeTint(false);
    ASSERT_TRUE(renderer->render(s, project.parameters, camera, 32, 32).has_value());
    EXPECT_EQ(renderer->readHdr(), plain);
    ASSERT_EQ(plain.size(), tinted.size());
    auto countReddish = [](const std::vector<float>& hdr, int& lit) {
        int reddish = 0;
        lit = 0;
        for (std::size_t i = 0; i < hdr.size(); i += 4) {
            if (hdr[i] + hdr[i + 1] + hdr[i + 2] <= 0.0f)
                continue;
            ++lit;
            reddish += hdr[i] > 1.5f * hdr[i + 1] && hdr[i] > 1.5f * hdr[i + 2];
        }
        return reddish;
    };
    int lit = 0;
    const int reddishPlain = countReddish(plain, lit);
    EXPECT_LT(reddishPlain, lit / 2) << "untinted, the white floor is not red";
    const int reddish = countReddish(tinted, lit);
    ASSERT_GT(lit, 100);
    EXPECT_GT(reddish, lit / 2) << "the floor near the camera lies in cascade 0 (red)";
}
