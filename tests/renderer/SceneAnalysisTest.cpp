// The scene analysis that decides which effects run, on analytic scenes and
// on real ones (Cornell box closed, Sponza's courtyard open to the sky).
#include "TestPaths.h"

#include "lpv/importers/Importer.h"
#include "lpv/renderer/SceneAnalysis.h"
#include "lpv/scene/CornellBox.h"
#include "lpv/scene/Primitives.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace lpv;

namespace {

const renderer::EffectDecision& find(const std::vector<renderer::EffectDecision>& all, const std::string& key) {
    auto it = std::find_if(all.begin(), all.end(), [&](const auto& d) { return d.parameter == key; });
    EXPECT_NE(it, all.end()) << key;
    return *it;
}

scene::Scene groundWithSun() {
    scene::Scene s;
    s.meshes.push_back(scene::makePlane(2));
    s.materials.emplace_back();
    scene::Object ground;
    ground.mesh = 0;
    ground.transform.scale = glm::vec3(10.0f);
    s.objects.push_back(ground);
    scene::Object box = ground;
    s.meshes.push_back(scene::makeBox());
    box.mesh = 1;
    box.transform.scale = glm::vec3(1.0f);
    box.transform.translation = {0.0f, 0.5f, 0.0f};
    s.objects.push_back(box);
    scene::Light sun;
    sun.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
    s.lights.push_back(sun);
    return s;
}

} // namespace

TEST(SceneAnalysis, OpenGroundGetsSkyLightAClosedBoxDoesNot) {
    const scene::Scene open = groundWithSun();
    const auto openTraits = renderer::analyseSceneTraits(open);
    EXPECT_GT(openTraits.openSkyFraction, 0.5f);
    const auto openDecisions = renderer::decideEffects(open, openTraits, {}, nullptr);
    EXPECT_TRUE(find(openDecisions, "effects.skyInjection").wanted);
    EXPECT_NE(find(openDecisions, "effects.skyInjection").reason.find("open scene"), std::string::npos);

    scene::Project cornell = scene::makeCornellBoxProject();
    cornell.scene.sky.intensity = 1.0f; // so that the geometry decides
    const auto closedTraits = renderer::analyseSceneTraits(cornell.scene);
    EXPECT_LT(closedTraits.openSkyFraction, renderer::kOpenSkyThreshold);
    const auto closed = renderer::decideEffects(cornell.scene, closedTraits, {}, nullptr);
    EXPECT_FALSE(find(closed, "effects.skyInjection").wanted);
    EXPECT_NE(find(closed, "effects.skyInjection").reason.find("closed scene"), std::string::npos);
}

TEST(SceneAnalysis, SponzaCourtyardIsOpenToTheSky) {
    auto imported = importers::importScene(std::string(test::kSharedScenesDir) + "/sponza/sponza.obj");
    ASSERT_TRUE(imported) << imported.error().describe();
    const auto traits = renderer::analyseSceneTraits(imported->scene);
    EXPECT_GT(traits.openSkyFraction, renderer::kOpenSkyThreshold);
    EXPECT_LT(traits.openSkyFraction, 0.9f) << "the galleries' roofs cover part of the floor";
    std::printf("Sponza: %.0f%% of %d columns open to the sky\n", 100.0 * traits.openSkyFraction, traits.skyProbes);
}

TEST(SceneAnalysis, MaterialsDecideSubsurfaceAndGlossy) {
    scene::Scene s = groundWithSun();
    auto decisions = renderer::decideEffects(s, renderer::analyseSceneTraits(s), {}, nullptr);
    EXPECT_FALSE(find(decisions, "effects.subsurface").wanted);
    EXPECT_FALSE(find(decisions, "effects.glossyReflections").wanted);
    s.materials[0].translucency = 0.4f;
    s.materials[0].glossiness = 0.8f;
    decisions = renderer::decideEffects(s, renderer::analyseSceneTraits(s), {}, nullptr);
    EXPECT_TRUE(find(decisions, "effects.subsurface").wanted);
    EXPECT_TRUE(find(decisions, "effects.glossyReflections").wanted);
    // A material no visible object draws with does not count.
    s.objects[0].visible = false;
    s.objects[1].visible = false;
    EXPECT_FALSE(renderer::analyseSceneTraits(s).hasTranslucentMaterial);
}

TEST(SceneAnalysis, SettingsForceOnAndOffAndSayBy) {
    const scene::Scene s = groundWithSun();
    const auto traits = renderer::analyseSceneTraits(s);
    scene::ParameterSet params;
    ASSERT_TRUE(params.setFromText("effects.subsurface", "on"));
    ASSERT_TRUE(params.setFromText("effects.skyInjection", "off"));
    const auto d = renderer::decideEffects(s, traits, params, nullptr);
    EXPECT_TRUE(find(d, "effects.subsurface").wanted);
    EXPECT_NE(find(d, "effects.subsurface").reason.find("forced on"), std::string::npos);
    EXPECT_FALSE(find(d, "effects.skyInjection").wanted);
    EXPECT_NE(find(d, "effects.skyInjection").reason.find("forced off"), std::string::npos);
}

TEST(SceneAnalysis, SunRaysOnlyWhenTheSunIsOnScreen) {
    const scene::Scene s = groundWithSun();
    const auto traits = renderer::analyseSceneTraits(s);
    scene::Camera towardSun;
    towardSun.position = {0.0f, 1.0f, 0.0f};
    towardSun.target = towardSun.position - s.lights[0].direction;
    towardSun.up = {0.0f, 0.0f, 1.0f};
    EXPECT_TRUE(find(renderer::decideEffects(s, traits, {}, &towardSun), "effects.sunRays").wanted);
    scene::Camera away = towardSun;
    away.target = towardSun.position + s.lights[0].direction;
    EXPECT_FALSE(find(renderer::decideEffects(s, traits, {}, &away), "effects.sunRays").wanted);
}

TEST(SceneAnalysis, LpvNeedsADirectionalLight) {
    scene::Scene s = groundWithSun();
    EXPECT_TRUE(renderer::decideEffects(s, renderer::analyseSceneTraits(s), {}, nullptr).front().runs());
    s.lights.clear();
    const auto d = renderer::decideEffects(s, renderer::analyseSceneTraits(s), {}, nullptr);
    EXPECT_FALSE(d.front().runs());
    EXPECT_NE(d.front().reason.find("no directional light"), std::string::npos);
}

TEST(SceneAnalysis, SubsurfaceRunsOnlyWithTheLpvAndIsImplemented) {
    scene::Scene s = groundWithSun();
    s.materials[0].translucency = 0.5f;
    const auto traits = renderer::analyseSceneTraits(s);
    const auto byDefault = renderer::decideEffects(s, traits, {}, nullptr);
    const auto on = find(byDefault, "effects.subsurface");
    EXPECT_TRUE(on.runs()) << on.reason;
    EXPECT_TRUE(on.implemented);
    scene::ParameterSet params;
    ASSERT_TRUE(params.setFromText("lpv.intensity", "0"));
    ASSERT_TRUE(params.setFromText("effects.subsurface", "on"));
    const auto decisions = renderer::decideEffects(s, traits, params, nullptr);
    const auto noLpv = find(decisions, "effects.subsurface");
    EXPECT_FALSE(noLpv.runs());
    EXPECT_NE(noLpv.reason.find("the LPV does not run"), std::string::npos) << noLpv.reason;
}

// gi.method = radiosity: the LPV does not run and says what lights the frame
// instead; the baked solution's own decision needs a solution.
TEST(SceneAnalysis, RadiosityRunsNoLpvAndNeedsASolution) {
    const scene::Scene s = groundWithSun();
    scene::ParameterSet params;
    ASSERT_TRUE(params.setFromText("gi.method", "radiosity", "test").has_value());
    const auto d = renderer::decideEffects(s, renderer::analyseSceneTraits(s), params, nullptr);
    EXPECT_FALSE(d.front().runs());
    EXPECT_EQ(d.front().reason, "gi.method is radiosity: the indirect light is a baked solution's");
    EXPECT_FALSE(find(d, "lpv.localLights").runs());
    EXPECT_TRUE(renderer::showsBakedRadiosity(params));
    const auto none = renderer::decideBakedRadiosity(params, 0, 0.0);
    EXPECT_FALSE(none.runs());
    EXPECT_EQ(none.reason, "no radiosity solution: run lpv radiosity (direct light only)");
    const auto baked = renderer::decideBakedRadiosity(params, 438, 0.0977);
    EXPECT_TRUE(baked.runs());
    EXPECT_EQ(baked.reason, "a baked solution of 438 patches, residual 0.0977");
    ASSERT_TRUE(params.setFromText("gi.method", "lpv", "test").has_value());
    EXPECT_FALSE(renderer::decideBakedRadiosity(params, 438, 0.0977).runs());
    EXPECT_FALSE(renderer::showsBakedRadiosity(params));
}
