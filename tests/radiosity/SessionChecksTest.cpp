// The checks RadiositySession::create makes before it meshes (issue #27 item
// 6): countPatches must agree with the mesher exactly, a scene where nothing
// emits is refused, and so is one over radiosity.maxPatches, with the count.
#include "lpv/radiosity/PatchMesh.h"
#include "lpv/radiosity/RadiositySession.h"
#include "lpv/scene/CornellBox.h"

#include <gtest/gtest.h>

using namespace lpv;

TEST(RadiositySessionChecks, CountingPatchesAgreesWithTheMesher) {
    const scene::Project project = scene::makeCornellBoxProject();
    for (const float area : {0.5f, 0.05f, 0.013f}) {
        const std::size_t counted = radiosity::countPatches(project.scene, {area});
        EXPECT_EQ(counted, radiosity::buildPatchMesh(project.scene, {area}).size()) << "max area " << area;
        EXPECT_GT(counted, 20u);
    }
}

TEST(RadiositySessionChecks, ASceneOverTheLimitIsRefusedWithTheCountAndTheLimit) {
    const scene::Project project = scene::makeCornellBoxProject();
    const std::size_t patches = radiosity::countPatches(project.scene, {0.05f});
    auto refused = radiosity::RadiositySession::create(project.scene, {}, 0.05f, patches - 1);
    ASSERT_FALSE(refused.has_value());
    EXPECT_EQ(refused.error().location, "radiosity.maxPatches");
    EXPECT_NE(refused.error().message.find("would mesh into " + std::to_string(patches) + " patches"),
              std::string::npos)
        << refused.error().message;
    EXPECT_NE(refused.error().message.find("radiosity.maxPatches = " + std::to_string(patches - 1)), std::string::npos)
        << refused.error().message;
    auto accepted = radiosity::RadiositySession::create(project.scene, {}, 0.05f, patches);
    ASSERT_TRUE(accepted.has_value()) << accepted.error().describe();
    EXPECT_EQ(accepted->mesh().size(), patches);
}

TEST(RadiositySessionChecks, ASceneWhereNothingShootsIsRefused) {
    scene::Project project = scene::makeCornellBoxProject();
    ASSERT_TRUE(radiosity::RadiositySession::create(project.scene, {}, 0.5f, 1000000).has_value())
        << "the Cornell box's area light shoots";
    // No emitter and no light.
    for (scene::Material& m : project.scene.materials)
        m.emissive = glm::vec3(0.0f);
    project.scene.lights.clear();
    auto dark = radiosity::RadiositySession::create(project.scene, {}, 0.5f, 1000000);
    ASSERT_FALSE(dark.has_value());
    EXPECT_NE(dark.error().message.find("nothing in the scene shoots light"), std::string::npos)
        << dark.error().message;
    // A light of zero intensity is no light.
    scene::Project dim = scene::makeCornellBoxProject();
    for (scene::Material& m : dim.scene.materials)
        m.emissive = glm::vec3(0.0f);
    for (scene::Light& l : dim.scene.lights)
        l.intensity = 0.0f;
    EXPECT_FALSE(radiosity::RadiositySession::create(dim.scene, {}, 0.5f, 1000000).has_value());
    // A light that reaches no patch: a spot far outside the box, pointing away.
    scene::Project away = dim;
    scene::Light spot;
    spot.type = scene::LightType::Spot;
    spot.position = {2.78f, 50.0f, 2.8f};
    spot.direction = {0.0f, 1.0f, 0.0f};
    spot.intensity = 100.0f;
    away.scene.lights = {spot};
    auto unlit = radiosity::RadiositySession::create(away.scene, {}, 0.5f, 1000000);
    ASSERT_FALSE(unlit.has_value());
    EXPECT_NE(unlit.error().message.find("the lights reach no patch"), std::string::npos) << unlit.error().message;
    // An emitter that is hidden does not count either.
    scene::Project hidden = scene::makeCornellBoxProject();
    hidden.scene.lights.clear();
    for (scene::Object& o : hidden.scene.objects)
        for (const scene::Submesh& sub : hidden.scene.meshes[std::size_t(o.mesh)].submeshes)
            if (hidden.scene.materials[sub.materialIndex].emissive != glm::vec3(0.0f))
                o.visible = false;
    EXPECT_FALSE(radiosity::RadiositySession::create(hidden.scene, {}, 0.5f, 1000000).has_value());
}
