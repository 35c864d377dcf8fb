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

// Two frames of `project` from its first camera at 160x120; the second's HDR
// image, and the depth pre-pass's status in it when `prepassStatus` is given.
std::vector<float> renderTwice(const scene::Project& project, renderer::PassStatus* prepassStatus = nullptr) {
    auto r = renderer::ForwardRenderer::create();
    EXPECT_TRUE(r.has_value()) << r.error().describe();
    if (!r)
        return {};
    r->setScene(project.scene);
    for (int i = 0; i < 2; ++i) {
        auto ok = r->render(project.scene, project.parameters, project.scene.cameras.front(), 160, 120);
        EXPECT_TRUE(ok.has_value()) << ok.error().describe();
    }
    if (prepassStatus) {
        const auto* report = r->graphReport().find("depthPrepass");
        *prepassStatus = report ? report->status : renderer::PassStatus::Culled;
    }
    return r->readHdr();
}

std::vector<float> renderCornell(bool prepass, renderer::PassStatus* prepassStatus) {
    scene::Project project = scene::makeCornellBoxProject();
    EXPECT_TRUE(project.parameters.set("output.depthPrepass", prepass).has_value());
    return renderTwice(project, prepassStatus);
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

namespace {

// The Cornell box lit by a spot light instead of its area lamp; with
// `zeroAreaLight` an area light of intensity 0 is added, which selects the
// forward shader's area-light variant and must light nothing.
std::vector<float> renderSpotCornell(bool zeroAreaLight) {
    scene::Project project = scene::makeCornellBoxProject();
    scene::Light area;
    for (scene::Light& l : project.scene.lights)
        if (l.type == scene::LightType::Area) {
            area = l;
            l.type = scene::LightType::Spot;
            l.direction = glm::vec3(0.0f, -1.0f, 0.0f);
            l.outerConeAngle = 1.2f;
            l.innerConeAngle = 0.9f;
            l.intensity = 40.0f;
        }
    // Direct light only: the variants differ in direct shading, and a second
    // local light, even a dark one, changes how the LPV's local VPLs are laid out.
    EXPECT_TRUE(project.parameters.setFromText("gi.method", "off").has_value());
    if (zeroAreaLight) {
        area.intensity = 0.0f;
        area.name = "dark area light";
        project.scene.lights.push_back(area);
    }
    return renderTwice(project);
}

} // namespace

// forward.frag is built with and without its area-light code (issue #25: on
// llvmpipe the code alone made shading 1.5x slower where no area light
// shines); the two variants shade every other light alike.
TEST_F(DepthPrepassGLTest, TheShaderWithoutAreaLightsShadesOtherLightsAlike) {
    const std::vector<float> without = renderSpotCornell(false);
    const std::vector<float> with = renderSpotCornell(true);
    ASSERT_EQ(without.size(), with.size());
    ASSERT_FALSE(without.empty());
    double peak = 0.0, worst = 0.0;
    for (std::size_t i = 0; i < with.size(); ++i) {
        peak = std::max(peak, double(std::abs(without[i])));
        worst = std::max(worst, double(std::abs(without[i] - with[i])));
    }
    EXPECT_GT(peak, 0.0) << "a black image";
    EXPECT_LE(worst, 1e-5 * peak) << "largest difference " << worst << " of a peak " << peak;
}
