// The camera's depth pre-pass (output.depthPrepass, issue #25): shading then
// lights each visible pixel once, and the image stays the one-pass image.
#include "GlFixture.h"

#include "lpv/renderer/ForwardRenderer.h"
#include "lpv/scene/CornellBox.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace lpv;

namespace {

class DepthPrepassGLTest : public GlTest {};

std::vector<float> renderCornell(bool prepass, renderer::PassStatus* prepassStatus) {
    scene::Project project = scene::makeCornellBoxProject();
    EXPECT_TRUE(project.parameters.set("output.depthPrepass", prepass).has_value());
    auto r = renderer::ForwardRenderer::create();
    EXPECT_TRUE(r.has_value()) << r.error().describe();
    if (!r)
        return {};
    r->setScene(project.scene);
    for (int i = 0; i < 2; ++i) {
        auto ok = r->render(project.scene, project.parameters, project.scene.cameras.front(), 160, 120);
        EXPECT_TRUE(ok.has_value()) << ok.error().describe();
    }
    const auto* report = r->graphReport().find("depthPrepass");
    *prepassStatus = report ? report->status : renderer::PassStatus::Culled;
    return r->readHdr();
}

TEST_F(DepthPrepassGLTest, TheImageIsTheOnePassImage) {
    renderer::PassStatus with = renderer::PassStatus::Culled, without = renderer::PassStatus::Ran;
    const std::vector<float> a = renderCornell(true, &with);
    const std::vector<float> b = renderCornell(false, &without);
    EXPECT_EQ(with, renderer::PassStatus::Ran);
    EXPECT_EQ(without, renderer::PassStatus::Culled);
    ASSERT_EQ(a.size(), b.size());
    ASSERT_FALSE(a.empty());
    double worst = 0.0, peak = 0.0;
    std::size_t differing = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const double d = std::abs(double(a[i]) - double(b[i]));
        worst = std::max(worst, d);
        peak = std::max(peak, double(std::abs(b[i])));
        differing += d > 1e-4 * std::max(1.0, double(std::abs(b[i]))) ? 1 : 0;
    }
    EXPECT_GT(peak, 0.0) << "a black image";
    EXPECT_EQ(differing, 0u) << "largest difference " << worst << " of a peak " << peak;
}

} // namespace
