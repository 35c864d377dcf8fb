// Material shading on small synthetic scenes with known light: normal-map
// orientation, alpha masks, sRGB texture decoding and metallic-roughness PBR.
// Expected values follow from the radiometry (a white Lambert surface under
// irradiance E reflects radiance E / pi), not from stored images.
#include "GlFixture.h"

#include "lpv/renderer/ForwardRenderer.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <string>

using namespace lpv;

namespace {

constexpr int kSize = 128;
constexpr float kPi = 3.14159265358979f;

// A square in the z = `z` plane facing +z, side 2 * half, u along +x, v along +y
// (tangent +x, handedness +1: bitangent = cross(+z, +x) = +y).
scene::Mesh quad(float half, float z, std::uint32_t material) {
    scene::Mesh m;
    m.positions = {{-half, -half, z}, {half, -half, z}, {half, half, z}, {-half, half, z}};
    m.normals.assign(4, {0.0f, 0.0f, 1.0f});
    m.tangents.assign(4, {1.0f, 0.0f, 0.0f, 1.0f});
    m.uvs = {{0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 1.0f}, {0.0f, 1.0f}};
    m.indices = {0, 1, 2, 0, 2, 3};
    m.submeshes = {{0, 6, material}};
    return m;
}

scene::Image8 solid(std::uint8_t r, std::uint8_t g, std::uint8_t b, std::uint8_t a = 255, int size = 4) {
    scene::Image8 img{size, size, 4, {}};
    for (int i = 0; i < size * size; ++i)
        img.pixels.insert(img.pixels.end(), {r, g, b, a});
    return img;
}

// Tangent-space normal encoded as a texel.
scene::Image8 normalTexel(glm::vec3 n) {
    n = glm::normalize(n);
    auto enc = [](float c) { return std::uint8_t(std::lround((c * 0.5f + 0.5f) * 255.0f)); };
    return solid(enc(n.x), enc(n.y), enc(n.z));
}

// Camera on +z looking at the origin; a sun travelling along -toLight with irradiance E.
struct TestScene {
    scene::Scene scene;
    scene::TextureImages images;
    scene::ParameterSet params;

    TestScene() {
        scene.sky.intensity = 0.0f; // black background, no sky term
        scene::Camera cam;
        cam.position = {0.0f, 0.0f, 3.0f};
        cam.target = {0.0f, 0.0f, 0.0f};
        cam.nearPlane = 0.1f;
        cam.farPlane = 20.0f;
        scene.cameras = {cam};
        EXPECT_TRUE(params.set("output.tonemapper", std::string("linear")).has_value());
        // A fixed exposure of 0 EV: the display shows the linear values themselves.
        EXPECT_TRUE(params.set("output.exposureMode", std::string("manual")).has_value());
        // Direct light only: these tests compare with analytic shading (the LPV has its own tests).
        EXPECT_TRUE(params.set("lpv.intensity", 0.0).has_value());
    }
    void addSun(glm::vec3 toLight, float irradiance) {
        scene::Light sun;
        sun.type = scene::LightType::Directional;
        sun.direction = -glm::normalize(toLight);
        sun.intensity = irradiance;
        sun.castShadows = false; // these tests are about materials, not shadows
        scene.lights.push_back(sun);
    }
    std::uint32_t addMaterial(const scene::Material& m) {
        scene.materials.push_back(m);
        return std::uint32_t(scene.materials.size() - 1);
    }
    void addMesh(const scene::Mesh& mesh) {
        scene.meshes.push_back(mesh);
        scene::Object o;
        o.mesh = int(scene.meshes.size() - 1);
        scene.objects.push_back(o);
    }
    const scene::Camera& camera() const { return scene.cameras.front(); }
};

struct Frame {
    std::vector<float> hdr;
    std::vector<std::uint8_t> display;
    glm::vec3 at(int x, int y) const {
        const std::size_t i = (std::size_t(y) * kSize + std::size_t(x)) * 4;
        return {hdr[i], hdr[i + 1], hdr[i + 2]};
    }
    // Mean over a 5x5 window.
    glm::vec3 around(glm::ivec2 p) const {
        glm::vec3 sum(0.0f);
        int n = 0;
        for (int dy = -2; dy <= 2; ++dy)
            for (int dx = -2; dx <= 2; ++dx) {
                const int x = p.x + dx, y = p.y + dy;
                if (x >= 0 && y >= 0 && x < kSize && y < kSize) {
                    sum += at(x, y);
                    ++n;
                }
            }
        return sum / float(std::max(n, 1));
    }
};

// Pixel of a world point, rows top to bottom.
glm::ivec2 pixelOf(const scene::Camera& cam, const glm::vec3& world) {
    const glm::vec4 clip = cam.projection(1.0f) * cam.view() * glm::vec4(world, 1.0f);
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return {int((ndc.x * 0.5f + 0.5f) * kSize), int((1.0f - (ndc.y * 0.5f + 0.5f)) * kSize)};
}

class MaterialShading : public GlTest {
public:
    Frame render(const TestScene& t) {
        auto r = renderer::ForwardRenderer::create();
        EXPECT_TRUE(r.has_value()) << (r ? "" : r.error().describe());
        if (!r)
            return {};
        r->setScene(t.scene, t.images);
        auto ok = r->render(t.scene, t.params, t.camera(), kSize, kSize);
        EXPECT_TRUE(ok.has_value()) << (ok ? "" : ok.error().describe());
        return {r->readHdr(), r->readDisplay()};
    }
};

// A white Lambert plane facing the camera, lit at a grazing angle, with a
// constant normal map: the radiance at the centre, E/pi * max(n.l, 0).
float planeRadianceWithNormalMap(MaterialShading& test, glm::vec3 mapNormal, glm::vec3 toLight) {
    TestScene t;
    t.addSun(toLight, kPi); // E = pi: radiance = albedo * n.l
    scene::Material m;
    m.diffuseColor = glm::vec3(1.0f);
    m.normalTexture = "normal.png";
    t.images["normal.png"] = normalTexel(mapNormal);
    t.addMesh(quad(1.0f, 0.0f, t.addMaterial(m)));
    const Frame f = test.render(t);
    return f.around(pixelOf(t.camera(), {0.0f, 0.0f, 0.0f})).r;
}

} // namespace

TEST_F(MaterialShading, NormalMapTiltedTowardsTheLightBrightensAndAwayDarkens) {
    // Light from +x at a grazing angle: 73 degrees from the plane's normal.
    const glm::vec3 toLight = glm::normalize(glm::vec3(1.0f, 0.0f, 0.3f));
    const float flat = planeRadianceWithNormalMap(*this, {0.0f, 0.0f, 1.0f}, toLight);
    const float towards = planeRadianceWithNormalMap(*this, {0.5f, 0.0f, 0.87f}, toLight);
    const float away = planeRadianceWithNormalMap(*this, {-0.5f, 0.0f, 0.87f}, toLight);
    // Expected: n.l with the quantised texel normals.
    const float expectFlat = glm::dot(glm::vec3(0, 0, 1), toLight);
    const float expectTowards = glm::dot(glm::normalize(glm::vec3(0.5f, 0.0f, 0.87f)), toLight);
    EXPECT_NEAR(flat, expectFlat, 0.02f) << "flat " << flat;
    EXPECT_NEAR(towards, expectTowards, 0.03f) << "tilted towards +x " << towards;
    EXPECT_GT(towards, 2.0f * flat) << "towards " << towards << " flat " << flat;
    EXPECT_LT(away, 0.2f * flat) << "away " << away << " flat " << flat;
}

TEST_F(MaterialShading, NormalMapGreenAxisIsIncreasingV) {
    // The bitangent (w * cross(n, t)) is +y here: a map tilted towards +v
    // faces a light from +y.
    const glm::vec3 toLight = glm::normalize(glm::vec3(0.0f, 1.0f, 0.3f));
    const float flat = planeRadianceWithNormalMap(*this, {0.0f, 0.0f, 1.0f}, toLight);
    const float up = planeRadianceWithNormalMap(*this, {0.0f, 0.5f, 0.87f}, toLight);
    const float down = planeRadianceWithNormalMap(*this, {0.0f, -0.5f, 0.87f}, toLight);
    EXPECT_GT(up, 2.0f * flat) << "up " << up << " flat " << flat;
    EXPECT_LT(down, 0.2f * flat) << "down " << down << " flat " << flat;
}

TEST_F(MaterialShading, AlphaMaskShowsTheBackdropThroughCutOutTexels) {
    TestScene t;
    t.addSun({0.0f, 0.0f, 1.0f}, kPi);
    scene::Material backdrop;
    backdrop.diffuseColor = {0.0f, 1.0f, 0.0f};
    scene::Material leaf;
    leaf.diffuseColor = {1.0f, 0.0f, 0.0f};
    leaf.alphaMode = scene::AlphaMode::Mask;
    leaf.alphaTexture = "checker.png";
    // 2x2 checker, rows top to bottom: top-left and bottom-right cut out.
    // Top-left of the image is uv (0, 1): the quad's upper left.
    scene::Image8 checker{8, 8, 4, {}};
    for (int row = 0; row < 8; ++row)
        for (int x = 0; x < 8; ++x) {
            const bool cut = (row < 4) == (x < 4);
            const std::uint8_t a = cut ? 0 : 255;
            checker.pixels.insert(checker.pixels.end(), {a, a, a, 255});
        }
    t.images["checker.png"] = checker;
    t.addMesh(quad(2.0f, -1.0f, t.addMaterial(backdrop)));
    t.addMesh(quad(1.0f, 0.0f, t.addMaterial(leaf)));
    const Frame f = render(t);
    const glm::vec3 upperLeft = f.around(pixelOf(t.camera(), {-0.5f, 0.5f, 0.0f}));
    const glm::vec3 upperRight = f.around(pixelOf(t.camera(), {0.5f, 0.5f, 0.0f}));
    const glm::vec3 lowerLeft = f.around(pixelOf(t.camera(), {-0.5f, -0.5f, 0.0f}));
    const glm::vec3 lowerRight = f.around(pixelOf(t.camera(), {0.5f, -0.5f, 0.0f}));
    // Lit: radiance = albedo (E = pi, n.l = 1).
    for (const glm::vec3& cut : {upperLeft, lowerRight}) {
        EXPECT_NEAR(cut.g, 1.0f, 0.02f) << "backdrop shows through: g = " << cut.g;
        EXPECT_LT(cut.r, 0.01f) << "no leaf colour: r = " << cut.r;
    }
    for (const glm::vec3& kept : {upperRight, lowerLeft}) {
        EXPECT_NEAR(kept.r, 1.0f, 0.02f) << "leaf: r = " << kept.r;
        EXPECT_LT(kept.g, 0.01f) << "backdrop hidden: g = " << kept.g;
    }
}

TEST_F(MaterialShading, SrgbTextureIsDecodedToLinearAndEncodedBackForDisplay) {
    TestScene t;
    t.addSun({0.0f, 0.0f, 1.0f}, kPi);
    scene::Material m;
    m.diffuseColor = glm::vec3(1.0f);
    m.diffuseTexture = "grey.png";
    t.images["grey.png"] = solid(128, 64, 200);
    t.addMesh(quad(1.0f, 0.0f, t.addMaterial(m)));
    const Frame f = render(t);
    const glm::ivec2 c = pixelOf(t.camera(), {0.0f, 0.0f, 0.0f});
    const glm::vec3 hdr = f.around(c);
    auto srgbToLinear = [](float s) {
        s /= 255.0f;
        return s <= 0.04045f ? s / 12.92f : std::pow((s + 0.055f) / 1.055f, 2.4f);
    };
    // radiance = E / pi * albedo * n.l = albedo
    EXPECT_NEAR(hdr.r, srgbToLinear(128), 0.01f * srgbToLinear(128) + 0.002f) << "linear of sRGB 128: " << hdr.r;
    EXPECT_NEAR(hdr.g, srgbToLinear(64), 0.01f * srgbToLinear(64) + 0.002f) << "linear of sRGB 64: " << hdr.g;
    EXPECT_NEAR(hdr.b, srgbToLinear(200), 0.01f * srgbToLinear(200) + 0.002f) << "linear of sRGB 200: " << hdr.b;
    // Exposure 0 EV and the linear operator: the display shows the texel again.
    const std::uint8_t* d = &f.display[(std::size_t(c.y) * kSize + std::size_t(c.x)) * 4];
    EXPECT_NEAR(int(d[0]), 128, 1);
    EXPECT_NEAR(int(d[1]), 64, 1);
    EXPECT_NEAR(int(d[2]), 200, 1);
}

namespace {

scene::Material pbr(float metallic, float roughness) {
    scene::Material m;
    m.shading = scene::ShadingModel::MetallicRoughness;
    m.diffuseColor = glm::vec3(0.9f);
    m.metallic = metallic;
    m.roughness = roughness;
    return m;
}

} // namespace

TEST_F(MaterialShading, MetalHasAMirrorHighlightAndNoDiffuse) {
    // Light from the camera's side: the mirror direction hits the plane's centre.
    TestScene t;
    t.addSun({0.0f, 0.0f, 1.0f}, kPi);
    t.addMesh(quad(1.0f, 0.0f, t.addMaterial(pbr(1.0f, 0.2f))));
    const Frame f = render(t);
    int bx = 0, by = 0;
    float best = -1.0f;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x)
            if (f.at(x, y).r > best) {
                best = f.at(x, y).r;
                bx = x;
                by = y;
            }
    const glm::ivec2 centre = pixelOf(t.camera(), {0.0f, 0.0f, 0.0f});
    EXPECT_LE(std::abs(bx - centre.x), 2) << "highlight at " << bx << "," << by;
    EXPECT_LE(std::abs(by - centre.y), 2) << "highlight at " << bx << "," << by;
    const float off = f.around(pixelOf(t.camera(), {0.6f, 0.0f, 0.0f})).r;
    // At the mirror point n = h = l = v: D = 1 / (pi alpha^2), V = 1 / 4, F = base colour,
    // so L = 0.9 / (4 pi alpha^2) * E with alpha = 0.2^2.
    const float alpha = 0.2f * 0.2f;
    const float expectedPeak = 0.9f / (4.0f * kPi * alpha * alpha) * kPi;
    EXPECT_NEAR(best, expectedPeak, 0.05f * expectedPeak) << "peak " << best;
    // 0.6 m off, the half vector is 5.7 degrees from the normal and D has
    // fallen about fifty-fold (measured 46x).
    EXPECT_GT(best, 30.0f * off) << "peak " << best << " at 0.6 m off the mirror point " << off;

    // Grazing light from +x: the mirror direction leaves the picture. A metal
    // reflects (almost) nothing towards the camera, a dielectric its diffuse.
    TestScene metalScene, plasticScene;
    metalScene.addSun({1.0f, 0.0f, 0.5f}, kPi);
    plasticScene.addSun({1.0f, 0.0f, 0.5f}, kPi);
    metalScene.addMesh(quad(1.0f, 0.0f, metalScene.addMaterial(pbr(1.0f, 0.2f))));
    plasticScene.addMesh(quad(1.0f, 0.0f, plasticScene.addMaterial(pbr(0.0f, 0.2f))));
    const Frame metal = render(metalScene), plastic = render(plasticScene);
    for (float x : {-0.6f, 0.0f, 0.6f}) {
        const glm::ivec2 p = pixelOf(t.camera(), {x, 0.0f, 0.0f});
        const float m = metal.around(p).r, d = plastic.around(p).r;
        // Dielectric: (1 - F) * 0.9 / pi * E * n.l, about 0.38.
        EXPECT_GT(d, 0.3f) << "dielectric at x = " << x << ": " << d;
        EXPECT_LT(m, 0.1f * d) << "metal at x = " << x << ": " << m << " vs dielectric " << d;
    }
}

TEST_F(MaterialShading, BlendedQuadIsPremultipliedOverTheBackdropAndLeavesTheGBuffer) {
    TestScene t;
    t.addSun({0.0f, 0.0f, 1.0f}, kPi);
    scene::Material backdrop;
    backdrop.diffuseColor = {0.0f, 1.0f, 0.0f};
    scene::Material glass;
    glass.diffuseColor = {1.0f, 0.0f, 0.0f};
    glass.alphaMode = scene::AlphaMode::Blend;
    glass.opacity = 0.25f;
    scene::Material glow = glass;
    glow.additive = true;
    glow.opacity = 1.0f;
    glow.diffuseColor = {0.0f, 0.0f, 0.5f};
    t.addMesh(quad(2.0f, -1.0f, t.addMaterial(backdrop)));
    scene::Mesh left = quad(0.5f, 0.0f, t.addMaterial(glass)), right = quad(0.5f, 0.0f, t.addMaterial(glow));
    for (auto& p : left.positions)
        p.x -= 0.6f;
    for (auto& p : right.positions)
        p.x += 0.6f;
    t.addMesh(left);
    t.addMesh(right);
    auto r = renderer::ForwardRenderer::create();
    ASSERT_TRUE(r.has_value());
    r->setScene(t.scene, t.images);
    ASSERT_TRUE(r->render(t.scene, t.params, t.camera(), kSize, kSize).has_value());
    const Frame f{r->readHdr(), {}};
    const glm::ivec2 pl = pixelOf(t.camera(), {-0.6f, 0.0f, 0.0f}), pr = pixelOf(t.camera(), {0.6f, 0.0f, 0.0f});
    const glm::vec3 over = f.around(pl), added = f.around(pr);
    // over: 0.25 * red + 0.75 * green; additive: green + blue.
    EXPECT_NEAR(over.r, 0.25f, 0.02f) << over.r;
    EXPECT_NEAR(over.g, 0.75f, 0.02f) << over.g;
    EXPECT_NEAR(added.g, 1.0f, 0.02f) << added.g;
    EXPECT_NEAR(added.b, 0.5f, 0.02f) << added.b;
    // The G-buffer still holds the backdrop (green albedo, depth of z = -1 plane).
    const auto albedo = r->readGBufferAlbedo();
    const std::size_t i = (std::size_t(pl.y) * kSize + std::size_t(pl.x)) * 4;
    EXPECT_NEAR(albedo[i + 1], 1.0f, 0.01f);
    EXPECT_NEAR(albedo[i + 0], 0.0f, 0.01f);
}

TEST_F(MaterialShading, DerivedImagesAreLookedUpUnderTheirSuffixedKeys) {
    // Height map: the renderer draws the normal map stored under
    // path + kHeightNormalSuffix (made by importers::loadSceneTextures).
    const glm::vec3 toLight = glm::normalize(glm::vec3(1.0f, 0.0f, 0.3f));
    auto withHeight = [&](bool derivedPresent) {
        TestScene t;
        t.addSun(toLight, kPi);
        scene::Material m;
        m.diffuseColor = glm::vec3(1.0f);
        m.heightTexture = "bump.png";
        t.images["bump.png"] = solid(128, 128, 128); // the raw height: never sampled as normals
        if (derivedPresent)
            t.images[std::string("bump.png") + scene::kHeightNormalSuffix] = normalTexel({0.5f, 0.0f, 0.87f});
        t.addMesh(quad(1.0f, 0.0f, t.addMaterial(m)));
        return render(t).around(pixelOf(t.camera(), {0.0f, 0.0f, 0.0f})).r;
    };
    const float flat = withHeight(false), bumped = withHeight(true);
    EXPECT_NEAR(flat, toLight.z, 0.02f) << "without the derived map the plane is flat: " << flat;
    EXPECT_GT(bumped, 2.0f * flat) << "bumped " << bumped << " flat " << flat;

    // Colour key: a colour-keyed material draws the keyed copy (alpha 0 here)
    // and so shows the backdrop; the plain file is opaque red.
    TestScene t;
    t.addSun({0.0f, 0.0f, 1.0f}, kPi);
    scene::Material backdrop;
    backdrop.diffuseColor = {0.0f, 1.0f, 0.0f};
    scene::Material keyed;
    keyed.diffuseColor = glm::vec3(1.0f);
    keyed.diffuseTexture = "leaf.png";
    keyed.colorKey = true;
    keyed.alphaMode = scene::AlphaMode::Mask;
    t.images["leaf.png"] = solid(255, 0, 0);
    t.images[std::string("leaf.png") + scene::kColorKeySuffix] = solid(255, 0, 0, 0);
    t.addMesh(quad(2.0f, -1.0f, t.addMaterial(backdrop)));
    t.addMesh(quad(1.0f, 0.0f, t.addMaterial(keyed)));
    const glm::vec3 centre = render(t).around(pixelOf(t.camera(), {0.0f, 0.0f, 0.0f}));
    EXPECT_NEAR(centre.g, 1.0f, 0.02f) << "backdrop through the keyed texels: g = " << centre.g;
    EXPECT_LT(centre.r, 0.01f) << "r = " << centre.r;
}
