// lpv.shBands (issue #47) through the renderer: three bands have only their
// CPU twin so far (LpvBands.h), so every propagation variant refuses a frame
// with lpv.shBands = 3 with an error that names the parameter and the variant,
// and renders again at 2.
#include "GlFixture.h"

#include "lpv/renderer/ForwardRenderer.h"
#include "lpv/scene/CornellBox.h"

using namespace lpv;

TEST_F(GlTest, EveryLpvVariantRefusesThreeShBandsNamingItself) {
    scene::Project project = scene::makeCornellBoxProject();
    auto r = renderer::ForwardRenderer::create();
    ASSERT_TRUE(r.has_value());
    r->setScene(project.scene);
    const scene::Camera& camera = project.scene.cameras.front();
    for (const char* variant : {"computeGather", "computeScatter", "rasterGather", "rasterScatter"}) {
        SCOPED_TRACE(variant);
        scene::ParameterSet params = project.parameters;
        ASSERT_TRUE(params.setFromText("lpv.variant", variant, "test").has_value());
        ASSERT_TRUE(params.setFromText("lpv.shBands", "3", "test").has_value());
        auto refused = r->render(project.scene, params, camera, 64, 64);
        ASSERT_FALSE(refused.has_value());
        const std::string message = refused.error().describe();
        EXPECT_NE(message.find("lpv.shBands"), std::string::npos) << message;
        EXPECT_NE(message.find(std::string("the ") + variant + " LPV runs two bands only"), std::string::npos)
            << message;
        ASSERT_TRUE(params.setFromText("lpv.shBands", "2", "test").has_value());
        auto ok = r->render(project.scene, params, camera, 64, 64);
        EXPECT_TRUE(ok.has_value()) << (ok ? "" : ok.error().describe());
    }
}
