// The scene analysis' rows for local lights, emissive surfaces and bounces
// (LocalLightAnalysis.h): what each decides and the reason it gives, on the
// Cornell box template (a spot light and an emissive lamp, no sun).
#include "lpv/renderer/LocalLightAnalysis.h"
#include "lpv/scene/CornellBox.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace lpv;

namespace {

const renderer::EffectDecision& find(const std::vector<renderer::EffectDecision>& all,
                                     const std::string& key) {
    auto it = std::find_if(all.begin(), all.end(), [&](const auto& d) { return d.parameter == key; });
    EXPECT_NE(it, all.end()) << key;
    return *it;
}

scene::ParameterSet with(std::initializer_list<std::pair<const char*, const char*>> values) {
    scene::ParameterSet params;
    for (const auto& [key, value] : values)
        EXPECT_TRUE(params.setFromText(key, value, "test").has_value()) << key;
    return params;
}

} // namespace

TEST(LocalLightAnalysis, DefaultsInjectTheCornellBoxLampAndRunTheLpv) {
    const scene::Scene s = scene::makeCornellBoxProject().scene;
    const auto d = renderer::decideEffects(s, renderer::analyseSceneTraits(s), {}, nullptr);
    EXPECT_TRUE(d.front().runs()) << d.front().reason;
    EXPECT_EQ(find(d, "lpv.localLights").reason, "ceilingLight (area) injected through 128^2 RSM faces");
    // The template's lamp is an area light and an emissive quad in its outline: the quad is
    // that light's visible surface, so emissive injection (auto) leaves it out.
    EXPECT_FALSE(find(d, "lpv.emissive").runs());
    EXPECT_EQ(find(d, "lpv.emissive").reason,
              "every emissive surface is an area light's visible surface (injected as that light)");
    EXPECT_FALSE(find(d, "lpv.bounces").runs());
}

TEST(LocalLightAnalysis, GiOffTurnsTheLpvAndEveryInjectionOff) {
    const scene::Scene s = scene::makeCornellBoxProject().scene;
    const auto d = renderer::decideEffects(s, renderer::analyseSceneTraits(s), with({{"gi.method", "off"}}), nullptr);
    EXPECT_FALSE(d.front().runs());
    EXPECT_EQ(d.front().reason, "gi.method is off: direct light only");
    EXPECT_FALSE(find(d, "lpv.localLights").runs());
    EXPECT_EQ(find(d, "lpv.localLights").reason, "gi.method is off");
    EXPECT_EQ(find(d, "lpv.emissive").reason, "gi.method is off");
}

TEST(LocalLightAnalysis, AutoInjectsSpotAndEmissiveLightAndRunsTheLpvWithoutASun) {
    const scene::Scene s = scene::makeCornellBoxProject().scene;
    const auto d =
        renderer::decideEffects(s, renderer::analyseSceneTraits(s),
                                with({{"lpv.localLights", "auto"}, {"lpv.bounces", "3"}}), nullptr);
    EXPECT_TRUE(d.front().runs()) << d.front().reason;
    EXPECT_EQ(d.front().reason, "spot, point or area lights light the scene: their RSMs are injected");
    EXPECT_EQ(find(d, "lpv.localLights").reason, "ceilingLight (area) injected through 128^2 RSM faces");
    EXPECT_TRUE(find(d, "lpv.bounces").runs());
    EXPECT_EQ(find(d, "lpv.bounces").reason, "2 more bounces re-injected at the geometry volume's surfels");

    // Without the area light, the lamp quad is an emitter of its own and is injected on auto.
    scene::Scene quadOnly = s;
    quadOnly.lights.clear();
    const auto e = renderer::decideEffects(quadOnly, renderer::analyseSceneTraits(quadOnly), {}, nullptr);
    EXPECT_TRUE(e.front().runs());
    EXPECT_TRUE(find(e, "lpv.emissive").runs());
    EXPECT_EQ(find(e, "lpv.emissive").reason, "a visible material emits: its triangles are sampled as VPLs");
}

TEST(LocalLightAnalysis, NoSpotPointOrEmitterSaysSo) {
    scene::Scene s = scene::makeCornellBoxProject().scene;
    s.lights.clear();
    for (scene::Material& m : s.materials)
        m.emissive = glm::vec3(0.0f);
    const auto params = with({{"lpv.localLights", "auto"}, {"lpv.emissive", "on"}, {"lpv.bounces", "2"}});
    const auto d = renderer::decideEffects(s, renderer::analyseSceneTraits(s), params, nullptr);
    EXPECT_FALSE(d.front().runs());
    EXPECT_EQ(find(d, "lpv.localLights").reason, "no spot, point or area light with a positive intensity");
    EXPECT_EQ(find(d, "lpv.emissive").reason, "forced on by lpv.emissive, but no visible material emits");
    EXPECT_FALSE(find(d, "lpv.bounces").runs());
    EXPECT_EQ(find(d, "lpv.bounces").reason, "the LPV does not run");
}
