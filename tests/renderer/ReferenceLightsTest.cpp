// Which lights the path-traced reference traces (ReferenceLights.h): on
// `auto` the sky and emissive surfaces light it exactly where the LPV
// injects them, so the two are compared like for like (issue #22); on/off
// (and the older true/false) force them.
#include "lpv/renderer/ReferenceLights.h"
#include "lpv/scene/CornellBox.h"
#include "lpv/scene/Primitives.h"

#include <gtest/gtest.h>

using namespace lpv;

namespace {

scene::ParameterSet with(std::initializer_list<std::pair<const char*, const char*>> values) {
    scene::ParameterSet params;
    for (const auto& [key, value] : values)
        EXPECT_TRUE(params.setFromText(key, value, "test").has_value()) << key << "=" << value;
    return params;
}

// A ground plane and a box under a sun and a bright sky: open to the sky.
scene::Scene openGround() {
    scene::Scene s;
    s.meshes.push_back(scene::makePlane(2));
    s.meshes.push_back(scene::makeBox());
    s.materials.emplace_back();
    scene::Object ground;
    ground.mesh = 0;
    ground.transform.scale = glm::vec3(10.0f);
    s.objects.push_back(ground);
    scene::Object box;
    box.mesh = 1;
    box.transform.translation = {0.0f, 0.5f, 0.0f};
    s.objects.push_back(box);
    scene::Light sun;
    sun.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
    s.lights.push_back(sun);
    s.sky.intensity = 1.0f;
    return s;
}

renderer::ReferenceLights decide(const scene::Scene& s, const scene::ParameterSet& params) {
    return renderer::decideReferenceLights(s, renderer::analyseSceneTraits(s), params);
}

} // namespace

TEST(ReferenceLights, AutoTracesTheSkyWhereTheLpvInjectsIt) {
    const scene::Scene open = openGround();
    const auto lights = decide(open, {});
    EXPECT_TRUE(lights.sky) << lights.skyReason;
    EXPECT_EQ(lights.skyReason.rfind("auto: the LPV injects it (", 0), 0u) << lights.skyReason;

    // The LPV injects no sky when effects.skyInjection is off: neither does the reference.
    const auto noSky = decide(open, with({{"effects.skyInjection", "off"}}));
    EXPECT_FALSE(noSky.sky) << noSky.skyReason;
    EXPECT_EQ(noSky.skyReason, "auto: the LPV does not inject it (forced off by effects.skyInjection)");

    // A closed box: no sky in the LPV, none in the reference.
    scene::Project cornell = scene::makeCornellBoxProject();
    cornell.scene.sky.intensity = 1.0f;
    EXPECT_FALSE(decide(cornell.scene, {}).sky);
}

TEST(ReferenceLights, AutoFollowsTheLpvsEmissiveInjection) {
    // The Cornell template's lamp is an area light whose quad lies in its outline:
    // the LPV injects it as that light, not as emissive VPLs, and so the reference
    // does not sample the quad again.
    scene::Project cornell = scene::makeCornellBoxProject();
    const auto lamp = decide(cornell.scene, cornell.parameters);
    EXPECT_FALSE(lamp.emissive) << lamp.emissiveReason;

    // Without the area light the quad is an emitter the LPV injects: the reference samples it.
    cornell.scene.lights.clear();
    const auto quad = decide(cornell.scene, cornell.parameters);
    EXPECT_TRUE(quad.emissive) << quad.emissiveReason;
    const auto forcedOff = decide(cornell.scene, with({{"reference.emissiveLight", "off"}}));
    EXPECT_FALSE(forcedOff.emissive);
    EXPECT_EQ(forcedOff.emissiveReason, "forced off by reference.emissiveLight");
    // lpv.emissive=off: the LPV leaves the quad out, and so does the reference on auto.
    EXPECT_FALSE(decide(cornell.scene, with({{"lpv.emissive", "off"}})).emissive);
}

TEST(ReferenceLights, GiOffStillTracesWhatTheLpvWouldInject) {
    // The reference measures the LPV even while the viewport shows direct light only.
    const auto lights = decide(openGround(), with({{"gi.method", "off"}}));
    EXPECT_TRUE(lights.sky) << lights.skyReason;
}

TEST(ReferenceLights, TrueAndFalseStillReadAsOnAndOff) {
    // reference.skyLight and reference.emissiveLight were booleans before `auto`.
    const scene::ParameterSet params = with({{"reference.skyLight", "true"}, {"reference.emissiveLight", "false"}});
    EXPECT_EQ(params.getEnum("reference.skyLight"), "on");
    EXPECT_EQ(params.getEnum("reference.emissiveLight"), "off");
    scene::Project cornell = scene::makeCornellBoxProject();
    const auto lights = decide(cornell.scene, params);
    EXPECT_TRUE(lights.sky);
    EXPECT_EQ(lights.skyReason, "forced on by reference.skyLight");
    // A project file that stored the old boolean loads as on/off.
    scene::ParameterSet fromJson;
    ASSERT_TRUE(fromJson.set("reference.skyLight", scene::ParameterValue(false), "test").has_value());
    EXPECT_EQ(fromJson.getEnum("reference.skyLight"), "off");
    // Anything else is still an error that names the choices.
    scene::ParameterSet bad;
    const auto error = bad.setFromText("reference.skyLight", "maybe", "test");
    ASSERT_FALSE(error.has_value());
    EXPECT_NE(error.error().describe().find("'maybe' is not one of: auto, on, off"), std::string::npos)
        << error.error().describe();
}
