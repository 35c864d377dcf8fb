// Emissive surfaces as VPLs (lpvref::sampleEmissiveVpls): the flux of a
// Lambertian emitter, the side it emits from, the cap on the count, and that
// hidden or non-emitting objects give none.
#include "lpv/renderer/lpv/EmissiveVpls.h"

#include <gtest/gtest.h>

#include <iostream>

using namespace lpv;
namespace ref = lpv::renderer::lpvref;

namespace {

// A 2 x 1.5 quad at height 3 facing down (its normals and winding), radiance (4, 2, 1), moved by its object.
scene::Scene ceilingLamp(bool emits = true) {
    scene::Scene s;
    scene::Mesh quad;
    quad.positions = {{0, 0, 0}, {2, 0, 0}, {2, 0, 1.5f}, {0, 0, 1.5f}};
    quad.normals.assign(4, glm::vec3(0, -1, 0));
    quad.indices = {0, 1, 2, 0, 2, 3}; // wound facing up: the normals decide
    quad.submeshes = {{0, 6, 0}};
    s.meshes = {quad};
    scene::Material lamp;
    lamp.emissive = emits ? glm::vec3(4.0f, 2.0f, 1.0f) : glm::vec3(0.0f);
    s.materials = {lamp};
    scene::Object o;
    o.mesh = 0;
    o.transform.translation = {1.0f, 3.0f, -1.0f};
    s.objects = {o};
    return s;
}

} // namespace

TEST(EmissiveVpls, FluxIsPiRadianceAreaFromTheFrontSide) {
    const scene::Scene s = ceilingLamp();
    ASSERT_TRUE(ref::sceneHasEmissiveSurface(s));
    const auto vpls = ref::sampleEmissiveVpls(s, 0.25f, 100000);
    glm::dvec3 total(0.0);
    for (const ref::Vpl& v : vpls) {
        total += glm::dvec3(v.flux);
        EXPECT_NEAR(v.normal.y, -1.0f, 1e-6f);
        EXPECT_NEAR(v.position.y, 3.0f, 1e-5f);
        EXPECT_GE(v.position.x, 1.0f - 1e-5f);
        EXPECT_LE(v.position.x, 3.0f + 1e-5f);
        EXPECT_GE(v.position.z, -1.0f - 1e-5f);
        EXPECT_LE(v.position.z, 0.5f + 1e-5f);
    }
    const double pi = 3.14159265358979;
    std::cout << "[measured] " << vpls.size() << " VPLs, total flux " << total.r
              << " W (pi L A = " << pi * 4.0 * 3.0 << ")\n";
    EXPECT_NEAR(total.r, pi * 4.0 * 3.0, 1e-4 * pi * 12.0);
    EXPECT_NEAR(total.g, pi * 2.0 * 3.0, 1e-4 * pi * 6.0);
    EXPECT_NEAR(total.b, pi * 1.0 * 3.0, 1e-4 * pi * 3.0);
    // Each triangle (area 1.5) gets ceil(sqrt(1.5) / 0.25) = 5, i.e. 25 VPLs.
    EXPECT_EQ(vpls.size(), 50u);
}

TEST(EmissiveVpls, CapCoarsensTheSpacingAndKeepsTheFlux) {
    const auto vpls = ref::sampleEmissiveVpls(ceilingLamp(), 0.01f, 40);
    EXPECT_LE(vpls.size(), 40u);
    EXPECT_GE(vpls.size(), 2u);
    double total = 0.0;
    for (const ref::Vpl& v : vpls)
        total += double(v.flux.r);
    EXPECT_NEAR(total, 3.14159265358979 * 12.0, 1e-3);
}

TEST(EmissiveVpls, HiddenOrDarkSurfacesGiveNone) {
    EXPECT_FALSE(ref::sceneHasEmissiveSurface(ceilingLamp(false)));
    EXPECT_TRUE(ref::sampleEmissiveVpls(ceilingLamp(false), 0.25f, 1000).empty());
    scene::Scene hidden = ceilingLamp();
    hidden.objects[0].visible = false;
    EXPECT_FALSE(ref::sceneHasEmissiveSurface(hidden));
    EXPECT_TRUE(ref::sampleEmissiveVpls(hidden, 0.25f, 1000).empty());
}

// A lamp modelled as an area light with its emissive quad counts once (issue #22):
// the quad lies in the light's plane and outline, so it gives no VPLs of its own,
// and a quad elsewhere still does.
TEST(EmissiveVpls, AnAreaLightsVisibleSurfaceIsNotInjectedAgain) {
    scene::Scene s = ceilingLamp();
    scene::Light lamp;
    lamp.type = scene::LightType::Area;
    lamp.position = {2.0f, 3.0f, -0.25f}; // the quad's centre (moved by its object)
    lamp.direction = {0.0f, -1.0f, 0.0f};
    lamp.tangent = {1.0f, 0.0f, 0.0f};
    lamp.size = {2.0f, 1.5f};
    s.lights = {lamp};
    EXPECT_FALSE(ref::sceneHasEmissiveSurface(s));
    EXPECT_TRUE(ref::sampleEmissiveVpls(s, 0.25f, 100000).empty());
    s.lights[0].position.y = 2.5f; // the light half a metre below: the quad is an emitter of its own
    EXPECT_TRUE(ref::sceneHasEmissiveSurface(s));
    EXPECT_FALSE(ref::sampleEmissiveVpls(s, 0.25f, 100000).empty());
    s.lights[0].position.y = 3.0f;
    s.lights[0].size = {1.0f, 1.5f}; // half the quad sticks out of the light
    EXPECT_TRUE(ref::sceneHasEmissiveSurface(s));
}
