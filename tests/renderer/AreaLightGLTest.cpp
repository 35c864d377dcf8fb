// Area lights in the forward pass (issue #22): the floor's radiance under a
// rectangle and a disc is albedo / pi * L * F, F from the shader's CPU twin
// (scene::areaLightIrradianceFactor, itself tested against Lambert's formula);
// nothing lands behind a one-sided light; a blocker casts a shadow whose
// penumbra widens with the light; a glossy metal floor reflects the light's
// specular lobe as the LTC CPU twin (scene::areaLightSpecularFactor) says.
#include "GlFixture.h"
#include "GreyFloor.h"

#include "lpv/renderer/ForwardRenderer.h"
#include "lpv/scene/AreaLight.h"
#include "lpv/scene/LtcSpecular.h"
#include "lpv/scene/Primitives.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

using namespace lpv;

namespace {

constexpr int kSize = 96;
constexpr float kPi = 3.14159265f;
constexpr float kAlbedo = 0.8f;

class AreaLightGL : public GlTest {
protected:
    void SetUp() override {
        GlTest::SetUp();
        scene::Material m;
        m.diffuseColor = glm::vec3(kAlbedo);
        m.specularColor = glm::vec3(0.0f);
        scene = test::greyFloor(m, 20.0f);
        light.type = scene::LightType::Area;
        light.size = {1.0f, 0.6f};
        light.position = {0.2f, 1.0f, 0.1f};
        light.direction = {0.0f, -1.0f, 0.0f};
        light.tangent = {1.0f, 0.0f, 0.3f};
        light.intensity = 3.0f;
        light.castShadows = false;
        camera.position = {0.0f, 4.0f, 2.5f};
        camera.target = {0.0f, 0.0f, 0.0f};
        camera.fovY = 1.0f;
        for (const auto& [k, v] : {std::pair<const char*, const char*>{"gi.method", "off"},
                                   {"output.exposureMode", "manual"}})
            EXPECT_TRUE(params.setFromText(k, v, "test").has_value());
    }
    std::vector<float> render() {
        scene.lights = {light};
        auto r = renderer::ForwardRenderer::create();
        EXPECT_TRUE(r.has_value());
        r->setScene(scene);
        auto ok = r->render(scene, params, camera, kSize, kSize);
        EXPECT_TRUE(ok.has_value()) << (ok ? "" : ok.error().describe());
        return r->readHdr();
    }
    // Where the ray through pixel (x, y) (rows top to bottom) meets the floor y = 0.
    glm::vec3 floorPoint(int x, int y) const {
        const glm::mat4 inv = glm::inverse(camera.projection(1.0f) * camera.view());
        const float nx = 2.0f * (float(x) + 0.5f) / kSize - 1.0f, ny = 1.0f - 2.0f * (float(y) + 0.5f) / kSize;
        const glm::vec4 a = inv * glm::vec4(nx, ny, -1.0f, 1.0f), b = inv * glm::vec4(nx, ny, 1.0f, 1.0f);
        const glm::vec3 pa = glm::vec3(a) / a.w, pb = glm::vec3(b) / b.w;
        return pa + (pb - pa) * (pa.y / (pa.y - pb.y));
    }
    // The largest relative error of the floor's radiance against albedo/pi * L * F over the image.
    float worstError(const std::vector<float>& hdr, int* compared) const {
        float worst = 0.0f;
        *compared = 0;
        for (int y = 0; y < kSize; y += 3)
            for (int x = 0; x < kSize; x += 3) {
                const glm::vec3 p = floorPoint(x, y);
                const float expected =
                    kAlbedo / kPi * scene::areaLightRadiance(light).r * scene::areaLightIrradianceFactor(light, p, {0, 1, 0});
                if (expected < 1e-3f)
                    continue; // far out: the 16-bit target's absolute steps dominate
                const float got = hdr[(std::size_t(y) * kSize + std::size_t(x)) * 4];
                worst = std::max(worst, std::abs(got - expected) / expected);
                ++*compared;
            }
        return worst;
    }

    scene::Scene scene;
    scene::Light light;
    scene::Camera camera;
    scene::ParameterSet params;
};

} // namespace

TEST_F(AreaLightGL, TheFloorUnderARectangleMatchesTheCpuTwin) {
    int compared = 0;
    const float worst = worstError(render(), &compared);
    EXPECT_GT(compared, 200);
    EXPECT_LT(worst, 0.01f) << "over " << compared << " pixels";
}

TEST_F(AreaLightGL, TheFloorUnderADiscGivenByItsPowerMatchesTheCpuTwin) {
    light.shape = scene::AreaShape::Disc;
    light.radius = 0.4f;
    light.unit = scene::AreaUnit::Power;
    light.intensity = 20.0f;
    int compared = 0;
    const float worst = worstError(render(), &compared);
    EXPECT_GT(compared, 200);
    EXPECT_LT(worst, 0.01f) << "over " << compared << " pixels";
}

TEST_F(AreaLightGL, NothingLandsBehindAOneSidedLight) {
    light.direction = {0.0f, 1.0f, 0.0f}; // facing away from the floor
    for (float v : render())
        ASSERT_TRUE(v == 0.0f || v == 1.0f) << v; // radiance 0; alpha 1
}

TEST_F(AreaLightGL, ABlockerCastsAShadowWhosePenumbraGrowsWithTheLight) {
    light.castShadows = true;
    // The small light's penumbra on the floor, about 7 cm, must span more than one pixel
    // (5 cm here) to be seen; a 2 cm light's (3.7 cm) fell between pixel centres once the
    // normal offset shrank to one texel (issue #46).
    light.size = {0.04f, 0.04f};
    scene.meshes.push_back(scene::makeBox());
    scene::Object blocker;
    blocker.mesh = 1;
    blocker.transform.translation = {0.2f, 0.5f, 0.1f};
    blocker.transform.scale = glm::vec3(0.3f);
    scene.objects.push_back(blocker);
    // Visibility along the floor from under the blocker outward: the radiance over what the
    // light would give unshadowed (the CPU twin); the penumbra is where it is neither 0 nor 1.
    auto penumbraSamples = [&](const std::vector<float>& hdr, float* under) {
        int partial = 0;
        for (int i = 0; i <= 100; ++i) {
            const glm::vec3 p{0.2f + 0.01f * float(i), 0.0f, 0.1f};
            const glm::vec4 clip = camera.projection(1.0f) * camera.view() * glm::vec4(p, 1.0f);
            const int x = int((clip.x / clip.w * 0.5f + 0.5f) * kSize), y = int((0.5f - 0.5f * clip.y / clip.w) * kSize);
            const float open =
                kAlbedo / kPi * scene::areaLightRadiance(light).r * scene::areaLightIrradianceFactor(light, p, {0, 1, 0});
            const float visibility = hdr[(std::size_t(y) * kSize + std::size_t(x)) * 4] / open;
            if (i == 0)
                *under = visibility;
            partial += visibility > 0.05f && visibility < 0.95f ? 1 : 0;
        }
        return partial;
    };
    float underSmall = 1.0f, underLarge = 1.0f;
    const int small = penumbraSamples(render(), &underSmall);
    light.size = {0.16f, 0.16f};
    const int large = penumbraSamples(render(), &underLarge);
    EXPECT_LT(underSmall, 0.05f) << "the small light leaves an umbra under the blocker";
    EXPECT_GT(large, small) << "the penumbra widens with the light (its points are sampled, issue #46)";
    EXPECT_GT(small, 0) << "even the small light has a penumbra";
}

// The specular lobe by LTC: a metal floor (no diffuse term) reflects
// L * (F0 x + (1 - F0) y), (x, y) from the CPU twin at each pixel's point and
// view direction. The twin is tested against brute-force integrals of the GGX
// lobe (LtcSpecularTest); this checks the shader computes what it computes.
TEST_F(AreaLightGL, AGlossyMetalFloorReflectsTheLtcLobeOfTheCpuTwin) {
    constexpr float kRoughness = 0.35f;
    const glm::vec3 f0(0.9f, 0.6f, 0.3f);
    scene.materials[0].shading = scene::ShadingModel::MetallicRoughness;
    scene.materials[0].diffuseColor = f0; // the base colour: a metal's F0
    scene.materials[0].metallic = 1.0f;
    scene.materials[0].roughness = kRoughness;
    const std::vector<float> hdr = render();
    int compared = 0;
    float worst = 0.0f, brightest = 0.0f;
    for (int y = 0; y < kSize; y += 2)
        for (int x = 0; x < kSize; x += 2) {
            const glm::vec3 p = floorPoint(x, y);
            const glm::vec3 v = glm::normalize(camera.position - p);
            const glm::vec2 xy = scene::areaLightSpecularFactor(light, p, {0, 1, 0}, v, kRoughness);
            const glm::vec3 expected =
                scene::areaLightRadiance(light) * (f0 * xy.x + (glm::vec3(1.0f) - f0) * xy.y);
            brightest = std::max(brightest, expected.r);
            if (expected.b < 2e-3f)
                continue; // outside the highlight: the 16-bit target's absolute steps dominate
            const std::size_t i = (std::size_t(y) * kSize + std::size_t(x)) * 4;
            for (int c = 0; c < 3; ++c)
                worst = std::max(worst, std::abs(hdr[i + std::size_t(c)] - expected[c]) / expected[c]);
            ++compared;
        }
    EXPECT_GT(compared, 100);
    EXPECT_GT(brightest, 0.1f) << "the camera sees the highlight";
    EXPECT_LT(worst, 0.02f) << "over " << compared << " pixels";
}

TEST_F(AreaLightGL, ADiffuseFloorHasNoSpecularLobe) {
    // Blinn-Phong with a zero specular colour: exactly the diffuse term (as the first test),
    // however shiny; with a specular colour the highlight adds light where the mirror
    // direction meets the light.
    scene.materials[0].shininess = 200.0f;
    const std::vector<float> matte = render();
    scene.materials[0].specularColor = glm::vec3(0.5f);
    const std::vector<float> shiny = render();
    float added = 0.0f;
    for (std::size_t i = 0; i < matte.size(); i += 4) {
        ASSERT_GE(shiny[i] + 1e-3f, matte[i]) << "a specular lobe only adds light";
        added = std::max(added, shiny[i] - matte[i]);
    }
    EXPECT_GT(added, 0.05f) << "the highlight of a shiny floor";
}
