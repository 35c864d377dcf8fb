// shadow.cascadeDraws (issue #25): the sun's cascades drawn one by one, each
// culled with its own volume, give the same shadow maps as the geometry
// shader that broadcasts every triangle to all cascades.
#include "GlFixture.h"

#include "lpv/renderer/ForwardRenderer.h"
#include "lpv/scene/CornellBox.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace lpv;

namespace {

class ShadowCascadeDrawsGLTest : public GlTest {};

struct Maps {
    std::vector<renderer::DebugImage> shadow;
    std::vector<float> hdr;
};

Maps render(const std::string& mode) {
    scene::Project project = scene::makeCornellBoxProject();
    scene::Light sun;
    sun.name = "sun";
    sun.type = scene::LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(0.4f, -1.0f, -0.3f));
    sun.intensity = 2.0f;
    project.scene.lights.push_back(sun);
    EXPECT_TRUE(project.parameters.setFromText("shadow.cascadeDraws", mode).has_value());
    EXPECT_TRUE(project.parameters.set("shadow.mapSize", 256).has_value());
    auto r = renderer::ForwardRenderer::create();
    EXPECT_TRUE(r.has_value()) << r.error().describe();
    if (!r)
        return {};
    r->setScene(project.scene);
    auto ok = r->render(project.scene, project.parameters, project.scene.cameras.front(), 128, 96);
    EXPECT_TRUE(ok.has_value()) << ok.error().describe();
    return {r->debugImages("shadowMaps"), r->readHdr()};
}

TEST_F(ShadowCascadeDrawsGLTest, OneDrawPerCascadeGivesTheGeometryShadersMaps) {
    const Maps broadcast = render("geometryShader");
    const Maps perCascade = render("perCascade");
    ASSERT_EQ(broadcast.shadow.size(), perCascade.shadow.size());
    ASSERT_GE(broadcast.shadow.size(), 4u) << "the sun's cascades (and the lamp's cube)";
    std::size_t castersInCascades = 0;
    for (std::size_t i = 0; i < broadcast.shadow.size(); ++i) {
        const auto& a = broadcast.shadow[i].pixels;
        const auto& b = perCascade.shadow[i].pixels;
        ASSERT_EQ(a.size(), b.size()) << broadcast.shadow[i].name;
        std::size_t differing = 0, covered = 0;
        for (std::size_t p = 0; p < a.size(); ++p) {
            differing += std::abs(a[p] - b[p]) > 1e-6f ? 1 : 0;
            covered += a[p] < 1.0f ? 1 : 0;
        }
        EXPECT_EQ(differing, 0u) << broadcast.shadow[i].name;
        if (broadcast.shadow[i].name.starts_with("shadow-cascade"))
            castersInCascades += covered;
    }
    // The near cascades lie in front of the box (the camera stands outside it); the far ones hold it.
    EXPECT_GT(castersInCascades, 1000u) << "the sun's cascades hold no caster: the comparison proves nothing";
    ASSERT_EQ(broadcast.hdr.size(), perCascade.hdr.size());
    float worst = 0.0f;
    for (std::size_t i = 0; i < broadcast.hdr.size(); ++i)
        worst = std::max(worst, std::abs(broadcast.hdr[i] - perCascade.hdr[i]));
    EXPECT_LE(worst, 1e-5f);
}

} // namespace
