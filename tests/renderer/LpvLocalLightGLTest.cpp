// Spot and point lights injected into the LPV (LocalRsmPass, lpv_inject_local.comp)
// through the whole renderer, on llvmpipe: in the closed Cornell box a spot
// light aimed at one wall lights that side indirectly far more than the
// other; the local RSM and its memory exist only while the scene has a spot
// or point light (the scene analysis says why).
#include "GlFixture.h"

#include "lpv/renderer/ForwardRenderer.h"
#include "lpv/renderer/GpuTimer.h"
#include "lpv/scene/CornellBox.h"

#include <cmath>
#include <iostream>

using namespace lpv;

namespace {

constexpr int kWidth = 160, kHeight = 120;

// The closed Cornell box, its ceiling light replaced by a narrow spot under
// the ceiling aimed down at the wall at +x (side > 0, the red wall) or -x (the green one).
scene::Project spotLitBox(float side) {
    scene::Project project = scene::makeCornellBoxProject();
    scene::Light spot;
    spot.name = "spot";
    spot.type = scene::LightType::Spot;
    spot.position = {2.78f, 5.2f, 2.8f};
    spot.direction = glm::normalize(glm::vec3(0.9f * side, -1.0f, 0.0f));
    spot.color = glm::vec3(1.0f);
    spot.intensity = 40.0f;
    spot.innerConeAngle = 0.2f;
    spot.outerConeAngle = 0.35f;
    project.scene.lights = {spot};
    // Inside the box's open front, looking in: the cascades follow the camera,
    // so a small LPV (2 cascades of 32^3, 0.25 m) then holds the whole room.
    scene::Camera& camera = project.scene.cameras.front();
    camera.position = {2.78f, 2.74f, 0.2f};
    camera.target = {2.78f, 2.74f, 5.0f};
    camera.fovY = 1.3f;
    return project;
}

scene::ParameterSet smallLpv(const scene::Project& project) {
    scene::ParameterSet params = project.parameters;
    for (const auto& [key, value] : {std::pair<const char*, const char*>{"lpv.localLights", "auto"},
                                     {"lpv.gridSize", "32"},
                                     {"lpv.cascades", "2"},
                                     {"lpv.cellSize", "0.25"},
                                     {"lpv.localRsmSize", "64"},
                                     {"output.view", "indirect"},
                                     {"lpv.reuse", "false"}})
        EXPECT_TRUE(params.setFromText(key, value, "test").has_value()) << key;
    return params;
}

struct Frame {
    std::vector<float> hdr, albedo;
};

Frame render(renderer::ForwardRenderer& r, const scene::Project& project, const scene::ParameterSet& params) {
    r.setScene(project.scene);
    for (int i = 0; i < 2; ++i) { // the second frame's geometry volume sees the first frame's G-buffer
        auto ok = r.render(project.scene, params, project.scene.cameras.front(), kWidth, kHeight);
        EXPECT_TRUE(ok.has_value()) << (ok ? "" : ok.error().describe());
    }
    return {r.readHdr(), r.readGBufferAlbedo()};
}

// Mean indirect irradiance (r + g + b) over the pixels of the wall with albedo `wall`.
double meanOnWall(const Frame& f, const glm::vec3& wall, int* count) {
    double sum = 0.0;
    *count = 0;
    for (std::size_t i = 0; i < std::size_t(kWidth) * kHeight; ++i) {
        const glm::vec3 a(f.albedo[4 * i], f.albedo[4 * i + 1], f.albedo[4 * i + 2]);
        if (glm::length(a - wall) > 0.02f)
            continue;
        ++*count;
        sum += double(f.hdr[4 * i]) + double(f.hdr[4 * i + 1]) + double(f.hdr[4 * i + 2]);
    }
    return *count > 0 ? sum / *count : 0.0;
}

const renderer::EffectDecision* decision(const renderer::ForwardRenderer& r, const std::string& parameter) {
    for (const auto& e : r.frameEffects())
        if (e.parameter == parameter)
            return &e;
    return nullptr;
}

bool timed(renderer::ForwardRenderer& r, const std::string& pass) {
    r.timer().resolveAll();
    for (const auto& row : r.timer().table())
        if (row.pass == pass)
            return true;
    return false;
}

class LpvLocalLightGLTest : public GlTest {};

} // namespace

TEST_F(LpvLocalLightGLTest, SpotLightLightsItsSideOfTheRoom) {
    auto r = renderer::ForwardRenderer::create();
    ASSERT_TRUE(r.has_value()) << r.error().describe();
    const glm::vec3 red{0.63f, 0.065f, 0.05f}, green{0.14f, 0.45f, 0.091f};
    for (float side : {1.0f, -1.0f}) {
        const scene::Project project = spotLitBox(side);
        const Frame f = render(*r, project, smallLpv(project));
        EXPECT_NE(r->lpvNote().find("1 local-light RSM face injected"), std::string::npos) << r->lpvNote();
        int redCount = 0, greenCount = 0;
        const double onRed = meanOnWall(f, red, &redCount), onGreen = meanOnWall(f, green, &greenCount);
        ASSERT_GT(redCount, 300);
        ASSERT_GT(greenCount, 300);
        const double lit = side > 0 ? onRed : onGreen, other = side > 0 ? onGreen : onRed;
        std::cout << "[ figures ] spot aimed at the " << (side > 0 ? "red" : "green")
                  << " wall: mean indirect irradiance there " << lit << ", on the opposite wall " << other
                  << ", ratio " << lit / other << "\n";
        EXPECT_GT(lit, 0.0);
        EXPECT_GT(lit, 10.0 * other);
    }
}

TEST_F(LpvLocalLightGLTest, LocalRsmExistsOnlyWithSpotOrPointLights) {
    auto r = renderer::ForwardRenderer::create();
    ASSERT_TRUE(r.has_value()) << r.error().describe();
    // A sun only: the LPV runs, the local RSM does not, and holds nothing.
    scene::Project sunOnly = spotLitBox(1.0f);
    sunOnly.scene.lights.front().type = scene::LightType::Directional;
    sunOnly.scene.lights.front().intensity = 2.0f;
    const scene::ParameterSet params = smallLpv(sunOnly);
    r->timer().clearHistory();
    render(*r, sunOnly, params);
    const auto* d = decision(*r, "lpv.localLights");
    ASSERT_NE(d, nullptr);
    EXPECT_FALSE(d->runs());
    EXPECT_EQ(d->reason, "no spot, point or area light with a positive intensity");
    EXPECT_TRUE(r->debugImages("localRsm").empty());
    EXPECT_FALSE(timed(*r, "localRsm"));
    EXPECT_EQ(r->lpvNote().find("local-light"), std::string::npos) << r->lpvNote();

    // A point light: six cube faces, timed, and the LPV runs without a sun.
    scene::Project point = spotLitBox(1.0f);
    point.scene.lights.front().type = scene::LightType::Point;
    r->timer().clearHistory();
    render(*r, point, params);
    d = decision(*r, "lpv.localLights");
    ASSERT_NE(d, nullptr);
    EXPECT_TRUE(d->runs()) << d->reason;
    EXPECT_EQ(r->debugImages("localRsm").size(), 18u); // position, normal, flux of 6 faces
    EXPECT_TRUE(timed(*r, "localRsm"));
    EXPECT_NE(r->lpvNote().find("6 local-light RSM faces injected"), std::string::npos) << r->lpvNote();

    // Forced off: the pass and its targets go away again; with no sun the LPV is off.
    scene::ParameterSet off = params;
    ASSERT_TRUE(off.setFromText("lpv.localLights", "off", "test").has_value());
    // The box's lamp quad is an emitter of its own here (no area light covers it): off too.
    ASSERT_TRUE(off.setFromText("lpv.emissive", "off", "test").has_value());
    render(*r, point, off);
    EXPECT_TRUE(r->debugImages("localRsm").empty());
    EXPECT_NE(r->lpvNote().find("off"), std::string::npos) << r->lpvNote();
}
