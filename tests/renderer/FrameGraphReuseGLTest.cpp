// Reuse of unchanged outputs through the whole renderer (issue #23): for
// each pass, a parameter that does not invalidate it keeps its output (no
// timer row this frame), one that does recomputes it, and either way the
// image equals a frame rendered without reuse. The scene is the Cornell box
// with its ceiling open and a sun shining in, so every LPV pass runs.
#include "GlFixture.h"
#include "GraphReportQueries.h"
#include "OpenCornellBox.h"

#include "lpv/renderer/ForwardRenderer.h"
#include "lpv/scene/CornellBox.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace lpv;
using renderer::PassStatus;
using scene::Pass;

namespace {

constexpr int kWidth = 96, kHeight = 72;

scene::Project openCornellBoxWithSun() {
    scene::Project project = test::openCornellBox(glm::vec3(0.55f, -1.0f, 0.25f));
    project.scene.sky.intensity = 0.5f; // the open ceiling lets sky light in
    return project;
}

struct ReuseCase {
    Pass pass;
    const char* keepKey; // does not invalidate the pass
    scene::ParameterValue keepValue;
    const char* changeKey; // invalidates it
    scene::ParameterValue changeValue;
};

void PrintTo(const ReuseCase& c, std::ostream* os) { *os << scene::passName(c.pass); }

class FrameGraphReuseGLTest : public GlTest,
                              public ::testing::WithParamInterface<ReuseCase>,
                              protected test::GraphReportQueries {
  protected:
    scene::Project project = openCornellBoxWithSun();
    scene::ParameterSet params = project.parameters;

    void render(renderer::ForwardRenderer& r) {
        auto ok = r.render(project.scene, params, project.scene.cameras.front(), kWidth, kHeight);
        ASSERT_TRUE(ok.has_value()) << ok.error().describe();
    }
    // Whether this frame's timer has a sample of the pass.
    static bool timed(renderer::ForwardRenderer& r, Pass p) {
        r.timer().resolveAll();
        const auto table = r.timer().table();
        return std::any_of(table.begin(), table.end(),
                           [&](const auto& row) { return row.pass == scene::passName(p) && row.samples > 0; });
    }
    // The image of the last frame against the same frame rendered again with reuse off.
    void expectSameAsWithoutReuse(renderer::ForwardRenderer& r) {
        const std::vector<float> reused = r.readHdr();
        scene::ParameterSet fresh = params;
        ASSERT_TRUE(fresh.set("lpv.reuse", false).has_value());
        auto ok = r.render(project.scene, fresh, project.scene.cameras.front(), kWidth, kHeight);
        ASSERT_TRUE(ok.has_value()) << ok.error().describe();
        const std::vector<float> computed = r.readHdr();
        ASSERT_EQ(reused.size(), computed.size());
        double worst = 0.0, total = 0.0;
        for (std::size_t i = 0; i < reused.size(); ++i) {
            worst = std::max(worst, double(std::abs(reused[i] - computed[i])));
            total += std::abs(computed[i]);
        }
        EXPECT_GT(total, 0.0) << "a black image";
        EXPECT_LE(worst, 1e-4) << "the reused frame differs from one computed from scratch";
    }
};

TEST_P(FrameGraphReuseGLTest, UnchangedInputsKeepTheOutputAndChangedOnesRecomputeIt) {
    const ReuseCase c = GetParam();
    ASSERT_TRUE(params.set("effects.skyInjection", std::string("on")).has_value());
    auto r = renderer::ForwardRenderer::create();
    ASSERT_TRUE(r.has_value()) << r.error().describe();
    r->setScene(project.scene);
    // Three frames: the second reads the first's G-buffer, the third finds nothing changed.
    for (int i = 0; i < 3; ++i)
        render(*r);
    EXPECT_EQ(status(*r, c.pass), PassStatus::Reused) << reason(*r, c.pass);

    // A parameter the pass does not depend on: its output is kept, it is not timed.
    ASSERT_TRUE(params.set(c.keepKey, c.keepValue).has_value());
    r->timer().resolveAll();
    r->timer().clearHistory();
    render(*r);
    EXPECT_EQ(status(*r, c.pass), PassStatus::Reused) << c.keepKey << ": " << reason(*r, c.pass);
    EXPECT_FALSE(timed(*r, c.pass)) << c.keepKey << " should not rerun " << scene::passName(c.pass);
    expectSameAsWithoutReuse(*r);

    // A parameter it depends on: recomputed, and timed.
    render(*r); // back to a frame with reuse on after the comparison frame
    ASSERT_TRUE(params.set(c.changeKey, c.changeValue).has_value());
    r->timer().resolveAll();
    r->timer().clearHistory();
    render(*r);
    EXPECT_EQ(status(*r, c.pass), PassStatus::Ran) << c.changeKey;
    EXPECT_TRUE(timed(*r, c.pass)) << c.changeKey << " should rerun " << scene::passName(c.pass);
    expectSameAsWithoutReuse(*r);
}

INSTANTIATE_TEST_SUITE_P(
    EveryReusablePass, FrameGraphReuseGLTest,
    ::testing::Values(ReuseCase{Pass::ShadowMaps, "lpv.propagationSteps", 4, "shadow.mapSize", 512},
                      ReuseCase{Pass::Rsm, "lpv.propagationSteps", 4, "rsm.tileSize", 128},
                      ReuseCase{Pass::SkyHeight, "lpv.propagationSteps", 4, "lpv.cellSize", 0.3},
                      ReuseCase{Pass::GeometryVolume, "lpv.propagationSteps", 4, "lpv.gvFromCamera", false},
                      ReuseCase{Pass::LpvInjection, "lpv.intensity", 2.0, "lpv.injectionOffset", 0.5},
                      ReuseCase{Pass::LpvPropagation, "lpv.bleedingDamping", 0.5, "lpv.propagationSteps", 4}),
    [](const auto& testInfo) { return scene::passName(testInfo.param.pass); });

// The camera turns without moving: the sun's shadow cascades fit the view
// and rerun; the RSM tiles and the LPV cascades sit around the camera's
// position and are kept. The image still equals one without reuse.
TEST_F(FrameGraphReuseGLTest, RotatingTheCameraKeepsTheRsmButNotTheShadowMaps) {
    ASSERT_TRUE(params.set("lpv.gvFromCamera", false).has_value());
    auto r = renderer::ForwardRenderer::create();
    ASSERT_TRUE(r.has_value()) << r.error().describe();
    r->setScene(project.scene);
    render(*r);
    render(*r);
    scene::Camera& camera = project.scene.cameras.front();
    camera.target += glm::vec3(0.3f, 0.0f, 0.0f); // turn, do not move
    render(*r);
    EXPECT_EQ(status(*r, Pass::ShadowMaps), PassStatus::Ran) << "the sun's cascades fit the view";
    EXPECT_EQ(status(*r, Pass::Rsm), PassStatus::Reused) << "RSM tiles follow the camera's position only";
    EXPECT_EQ(status(*r, Pass::LpvPropagation), PassStatus::Reused) << reason(*r, Pass::LpvPropagation);
    expectSameAsWithoutReuse(*r);
}

// With lpv.viewShift the cascades sit ahead of the camera, so turning moves
// them: the RSM tiles must follow them (their key is the cascades, not the
// camera's position), or the LPV would inject tiles of the old view.
TEST_F(FrameGraphReuseGLTest, RotatingTheCameraWithTheCascadesShiftedRedrawsTheRsm) {
    ASSERT_TRUE(params.set("lpv.gvFromCamera", false).has_value());
    ASSERT_TRUE(params.set("lpv.viewShift", 1.0).has_value());
    auto r = renderer::ForwardRenderer::create();
    ASSERT_TRUE(r.has_value()) << r.error().describe();
    r->setScene(project.scene);
    render(*r);
    render(*r);
    const auto before = r->lpvCascadeFrames();
    scene::Camera& camera = project.scene.cameras.front();
    camera.target += glm::vec3(3.0f, 0.0f, 0.0f); // turn about 20 degrees, do not move
    render(*r);
    ASSERT_NE(r->lpvCascadeFrames().front().origin, before.front().origin) << "the turn must move the cascades";
    EXPECT_EQ(status(*r, Pass::Rsm), PassStatus::Ran) << reason(*r, Pass::Rsm);
    EXPECT_EQ(status(*r, Pass::LpvPropagation), PassStatus::Ran) << reason(*r, Pass::LpvPropagation);
    expectSameAsWithoutReuse(*r);
}

// `lpv render --dump` checks names against frameGraphNames() before any frame
// exists: every name a frame declares (outputs and passes) must be in it.
TEST_F(FrameGraphReuseGLTest, EveryDeclaredNameIsKnownToDump) {
    ASSERT_TRUE(params.set("effects.skyInjection", std::string("on")).has_value());
    ASSERT_TRUE(params.set("lpv.directedPropagation", std::string("on")).has_value());
    ASSERT_TRUE(params.set("lpv.bounces", 2).has_value());
    auto r = renderer::ForwardRenderer::create();
    ASSERT_TRUE(r.has_value()) << r.error().describe();
    r->setScene(project.scene);
    render(*r);
    const std::vector<std::string> declared = r->dumpNames();
    const std::vector<std::string>& known = renderer::frameGraphNames();
    EXPECT_GE(declared.size(), 30u) << "outputs and passes of a frame with sky, directed propagation and bounces";
    for (const std::string& name : declared)
        EXPECT_NE(std::find(known.begin(), known.end(), name), known.end())
            << name << " is declared by the frame but `--dump` would reject it";
    // And what it names can be dumped: the sky's height map is an image.
    EXPECT_FALSE(r->debugImages("skyHeight").empty());
    EXPECT_FALSE(r->debugImages("lpv.normals").empty());
}

} // namespace
