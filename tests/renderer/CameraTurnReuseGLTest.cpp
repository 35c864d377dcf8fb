// A camera that only turns reuses the LPV (issue #48 item 2): on Sibenik as
// `lpv import` makes it, with the registry's defaults, the cascades keep
// their snapped placement (they follow the camera's position, not its view:
// lpv.viewShift is 0), so the frame graph's report says the RSM, the
// geometry volume, injection and propagation were reused, while the shadow
// maps (fitted to the view) and shading reran. The turned frame equals a
// fresh renderer's frame from the same view.
#include "GlFixture.h"
#include "GraphReportQueries.h"
#include "OpeningViews.h"

#include "lpv/renderer/ForwardRenderer.h"
#include "lpv/scene/CameraTurn.h"


#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace lpv;
using renderer::PassStatus;
using scene::Pass;

namespace {

constexpr int kWidth = 96, kHeight = 56;

class CameraTurnReuseGLTest : public GlTest, protected test::GraphReportQueries {};

TEST_F(CameraTurnReuseGLTest, TurningOnSibenikKeepsTheCascadesAndReusesTheLpv) {
    const test::OpeningView view = test::importedScene("4ds/sibenik.4ds");
    ASSERT_FALSE(view.project.scene.meshes.empty());
    const scene::Scene& scene = view.project.scene;
    const scene::ParameterSet& params = view.project.parameters;
    auto r = renderer::ForwardRenderer::create();
    ASSERT_TRUE(r.has_value()) << r.error().describe();
    r->setScene(scene);
    auto render = [&](renderer::ForwardRenderer& renderer, const scene::Camera& camera) {
        auto ok = renderer.render(scene, params, camera, kWidth, kHeight);
        ASSERT_TRUE(ok.has_value()) << ok.error().describe();
    };
    render(*r, view.camera);
    ASSERT_EQ(status(*r, Pass::LpvPropagation), PassStatus::Ran) << "the LPV must run on Sibenik: "
                                                                  << reason(*r, Pass::LpvPropagation);
    const std::vector<renderer::LpvGridFrame> placed = r->lpvCascadeFrames();
    ASSERT_FALSE(placed.empty());

    scene::Camera turned = view.camera;
    for (const float degrees : {5.0f, -5.0f, 30.0f, 90.0f, -150.0f}) {
        SCOPED_TRACE(testing::Message() << "yawed " << degrees << " degrees");
        turned = scene::yawedAboutUp(view.camera, degrees);
        render(*r, turned);
        const std::vector<renderer::LpvGridFrame> now = r->lpvCascadeFrames();
        ASSERT_EQ(now.size(), placed.size());
        for (std::size_t k = 0; k < now.size(); ++k) {
            EXPECT_EQ(now[k].origin, placed[k].origin) << "cascade " << k << " moved";
            EXPECT_EQ(now[k].cellSize, placed[k].cellSize) << "cascade " << k;
        }
        for (const Pass p : {Pass::Rsm, Pass::GeometryVolume, Pass::LpvInjection, Pass::LpvPropagation})
            EXPECT_EQ(status(*r, p), PassStatus::Reused) << scene::passName(p) << ": " << reason(*r, p);
        EXPECT_EQ(status(*r, Pass::ShadowMaps), PassStatus::Ran) << "the sun's cascades fit the view";
        EXPECT_EQ(status(*r, Pass::Shading), PassStatus::Ran);
    }

    // The last turned frame against a renderer that never saw another view.
    // Only the shadow maps' far cascades may differ: while the camera moves
    // they are redrawn every shadow.farCascadeInterval frames and shade from
    // the layer they were drawn with (docs/renderer.md, "Amortised far
    // cascades"); everything the LPV gives is the same.
    const std::vector<float> reused = r->readHdr();
    auto fresh = renderer::ForwardRenderer::create();
    ASSERT_TRUE(fresh.has_value()) << fresh.error().describe();
    fresh->setScene(scene);
    render(*fresh, turned);
    const std::vector<float> computed = fresh->readHdr();
    ASSERT_EQ(reused.size(), computed.size());
    double worst = 0.0, difference = 0.0, total = 0.0;
    for (std::size_t i = 0; i < reused.size(); ++i) {
        const double d = std::abs(double(reused[i]) - double(computed[i]));
        worst = std::max(worst, d);
        difference += d;
        total += std::abs(double(computed[i]));
    }
    ASSERT_GT(total, 0.0) << "a black image";
    std::printf("turned frame against a fresh renderer: largest difference %.3g, summed %.3g of the image's %.3g\n",
                worst, difference, total);
    EXPECT_LE(difference, 1e-6 * total) << "the reused frame differs from a fresh render of the same view";
}

// The counter-case (docs/lpv.md, Grids): with lpv.viewShift = 1 the cascades
// sit ahead of the camera, so a 5 degree turn moves the finest one (by about
// 1.2 of its cells) and the LPV reruns.
TEST_F(CameraTurnReuseGLTest, WithTheCascadesShiftedAlongTheViewATurnMovesThemAndRerunsTheLpv) {
    test::OpeningView view = test::importedScene("4ds/sibenik.4ds");
    ASSERT_FALSE(view.project.scene.meshes.empty());
    ASSERT_TRUE(view.project.parameters.set("lpv.viewShift", 1.0).has_value());
    auto r = renderer::ForwardRenderer::create();
    ASSERT_TRUE(r.has_value()) << r.error().describe();
    r->setScene(view.project.scene);
    auto render = [&](const scene::Camera& camera) {
        auto ok = r->render(view.project.scene, view.project.parameters, camera, kWidth, kHeight);
        ASSERT_TRUE(ok.has_value()) << ok.error().describe();
    };
    render(view.camera);
    const std::vector<renderer::LpvGridFrame> placed = r->lpvCascadeFrames();
    ASSERT_FALSE(placed.empty());
    render(scene::yawedAboutUp(view.camera, 5.0f));
    EXPECT_NE(r->lpvCascadeFrames().front().origin, placed.front().origin) << "the finest cascade should move";
    for (const Pass p : {Pass::Rsm, Pass::LpvInjection, Pass::LpvPropagation})
        EXPECT_EQ(status(*r, p), PassStatus::Ran) << scene::passName(p) << ": " << reason(*r, p);
}

} // namespace
