// Shadows on llvmpipe: cascade stabilisation, penumbra growth (PCSS),
// alpha-masked casters, spot and point light shadows. Test scenes are
// lit so that a white ground's HDR radiance equals its visibility.
#include "CheckerAlpha.h"
#include "GlFixture.h"

#include "passes/direct/ShadowCascades.h"
#include "lpv/renderer/ForwardRenderer.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <cmath>
#include <numbers>

using namespace lpv;

namespace {

constexpr int kSize = 192;

scene::Mesh quadMesh(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& d,
                     std::uint32_t material) {
    scene::Mesh m;
    m.positions = {a, b, c, d};
    const glm::vec3 n = glm::normalize(glm::cross(b - a, d - a));
    m.normals = {n, n, n, n};
    m.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    m.indices = {0, 1, 2, 0, 2, 3};
    m.submeshes = {{0, 6, material}};
    return m;
}

// A horizontal quad facing up, x0..x1 by z0..z1 at height y.
scene::Mesh horizontalQuad(float x0, float x1, float z0, float z1, float y, std::uint32_t material) {
    return quadMesh({x0, y, z1}, {x1, y, z1}, {x1, y, z0}, {x0, y, z0}, material);
}

// An axis-aligned box (outward faces) from `lo` to `hi`.
scene::Mesh boxMesh(const glm::vec3& lo, const glm::vec3& hi, std::uint32_t material) {
    scene::Mesh m;
    auto face = [&](glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d) {
        const scene::Mesh q = quadMesh(a, b, c, d, material);
        const auto base = std::uint32_t(m.positions.size());
        for (int i = 0; i < 4; ++i) {
            m.positions.push_back(q.positions[std::size_t(i)]);
            m.normals.push_back(q.normals[std::size_t(i)]);
            m.uvs.push_back(q.uvs[std::size_t(i)]);
        }
        for (std::uint32_t i : q.indices)
            m.indices.push_back(base + i);
    };
    const glm::vec3 l = lo, h = hi;
    face({l.x, h.y, h.z}, {h.x, h.y, h.z}, {h.x, h.y, l.z}, {l.x, h.y, l.z}); // top
    face({l.x, l.y, h.z}, {h.x, l.y, h.z}, {h.x, h.y, h.z}, {l.x, h.y, h.z}); // +z
    face({h.x, l.y, l.z}, {l.x, l.y, l.z}, {l.x, h.y, l.z}, {h.x, h.y, l.z}); // -z
    face({h.x, l.y, h.z}, {h.x, l.y, l.z}, {h.x, h.y, l.z}, {h.x, h.y, h.z}); // +x
    face({l.x, l.y, l.z}, {l.x, l.y, h.z}, {l.x, h.y, h.z}, {l.x, h.y, l.z}); // -x
    m.submeshes = {{0, std::uint32_t(m.indices.size()), material}};
    return m;
}

// White ground (material 0) plus the caster meshes; no sky light.
scene::Scene groundScene(std::vector<scene::Mesh> casters) {
    scene::Scene s;
    scene::Material white;
    white.name = "white";
    white.diffuseColor = glm::vec3(1.0f);
    s.materials.push_back(white);
    s.meshes.push_back(horizontalQuad(-10, 10, -10, 10, 0.0f, 0));
    for (auto& m : casters)
        s.meshes.push_back(std::move(m));
    for (int i = 0; i < int(s.meshes.size()); ++i)
        s.objects.push_back({"o" + std::to_string(i), i, -1, {}, true, {}});
    s.sky.intensity = 0.0f;
    s.sky.color = glm::vec3(0.0f);
    return s;
}

// A sun whose irradiance on the ground is pi: a lit white ground has radiance 1.
scene::Light sunTowards(const glm::vec3& direction) {
    scene::Light sun;
    sun.type = scene::LightType::Directional;
    sun.direction = glm::normalize(direction);
    sun.intensity = std::numbers::pi_v<float> / -sun.direction.y;
    return sun;
}

// Looking straight down at (x, 0, z) from `height`; image right = +x, image up = -z.
scene::Camera topDown(float x, float z, float height) {
    scene::Camera c;
    c.position = {x, height, z};
    c.target = {x, 0.0f, z};
    c.up = {0.0f, 0.0f, -1.0f};
    c.fovY = glm::radians(45.0f);
    c.nearPlane = 0.1f;
    c.farPlane = 100.0f;
    return c;
}

// World size of one pixel on the ground under a top-down camera.
float groundPixel(const scene::Camera& c) { return 2.0f * c.position.y * std::tan(0.5f * c.fovY) / float(kSize); }

struct Frame {
    std::vector<float> hdr;
    std::vector<float> depth;
    float red(int x, int y) const { return hdr[(std::size_t(y) * kSize + std::size_t(x)) * 4]; }
    float z(int x, int y) const { return depth[std::size_t(y) * kSize + std::size_t(x)]; }
};

glm::vec2 pixelOf(const scene::Camera& cam, const glm::vec3& world) {
    const glm::vec4 clip = cam.projection(1.0f) * cam.view() * glm::vec4(world, 1.0f);
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return {(ndc.x * 0.5f + 0.5f) * kSize, (1.0f - (ndc.y * 0.5f + 0.5f)) * kSize};
}

class ShadowRender : public GlTest {
protected:
    Frame render(const scene::Scene& s, const scene::ParameterSet& settings, const scene::Camera& cam,
                 const scene::TextureImages& textures = {}) {
        auto r = renderer::ForwardRenderer::create();
        EXPECT_TRUE(r.has_value()) << (r ? "" : r.error().describe());
        if (!r)
            return {};
        r->setScene(s, textures);
        auto ok = r->render(s, settings, cam, kSize, kSize);
        EXPECT_TRUE(ok.has_value()) << (ok ? "" : ok.error().describe());
        lastShadowImages = r->debugImages("shadowMaps");
        return Frame{r->readHdr(), r->readDepth()};
    }
    // Mean red radiance in a 3x3 window around a world point.
    float sample(const Frame& f, const scene::Camera& cam, const glm::vec3& world) {
        const glm::ivec2 p = glm::ivec2(pixelOf(cam, world));
        float sum = 0.0f;
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx)
                sum += f.red(std::clamp(p.x + dx, 0, kSize - 1), std::clamp(p.y + dy, 0, kSize - 1));
        return sum / 9.0f;
    }

    // Direct light only: shadows are measured without the LPV's indirect light.
    scene::ParameterSet params = [] {
        scene::ParameterSet p;
        (void)p.set("lpv.intensity", 0.0);
        return p;
    }();
    std::vector<renderer::DebugImage> lastShadowImages;
};

} // namespace

// Moving the camera sideways by a whole number of screen pixels that is less
// than one shadow texel: on the ground (a plane at constant depth under a
// top-down camera) the image shifts by exactly those pixels, so each ground
// pixel's visibility can be compared with the same world point before the move.
TEST_F(ShadowRender, CameraMovesOfLessThanATexelLeaveShadowEdgesUnchanged) {
    scene::Scene s = groundScene({boxMesh({-0.5f, 0.0f, -0.5f}, {0.5f, 1.0f, 0.5f}, 0)});
    s.lights.push_back(sunTowards({0.45f, -1.0f, 0.3f}));
    ASSERT_TRUE(params.set("shadow.mapSize", 256).has_value());
    ASSERT_TRUE(params.set("shadow.cascades", 2).has_value());
    const scene::Camera cam0 = topDown(1.1f, 0.7f, 6.0f);

    // The texel of the cascade the ground falls in (view distance 6).
    renderer::CascadeCamera cc;
    cc.position = cam0.position;
    cc.forward = {0.0f, -1.0f, 0.0f};
    cc.fovY = cam0.fovY;
    cc.nearPlane = cam0.nearPlane;
    cc.farPlane = cam0.farPlane;
    const auto cascades = renderer::buildCascades(cc, s.lights[0].direction, s.worldBounds(), {2, 256, true});
    float texel = 1e9f;
    for (const auto& c : cascades)
        if (c.splitFar > 5.5f) // the ground and the blend band's cascades
            texel = std::min(texel, c.texelWorld);
    const float pixel = groundPixel(cam0);
    const int shiftPx = std::max(1, int(0.45f * texel / pixel));
    const float move = float(shiftPx) * pixel;
    ASSERT_LT(move, texel) << "the premise: less than one texel";
    std::printf("shadow texel %.4f m, pixel %.4f m, camera moved %d px = %.2f texel\n", texel, pixel, shiftPx,
                move / texel);

    auto maxEdgeChange = [&](bool stabilize, int* edgePixels) {
        EXPECT_TRUE(params.set("shadow.stabilize", stabilize).has_value());
        scene::Camera cam1 = cam0;
        cam1.position.x += move;
        cam1.target.x += move;
        const Frame a = render(s, params, cam0), b = render(s, params, cam1);
        if (a.hdr.empty() || b.hdr.empty())
            return -1.0f;
        const float groundDepth = a.z(kSize / 2, kSize / 2);
        float worst = 0.0f;
        *edgePixels = 0;
        for (int y = 0; y < kSize; ++y)
            for (int x = shiftPx; x < kSize; ++x) {
                const float v = a.red(x, y);
                // Ground in both images (not the box), and on the shadow edge.
                if (std::abs(a.z(x, y) - groundDepth) > 1e-6f || std::abs(b.z(x - shiftPx, y) - groundDepth) > 1e-6f)
                    continue;
                if (v < 0.05f || v > 0.95f)
                    continue;
                ++*edgePixels;
                worst = std::max(worst, std::abs(b.red(x - shiftPx, y) - v));
            }
        return worst;
    };
    int edgeStable = 0, edgeUnstable = 0;
    const float stable = maxEdgeChange(true, &edgeStable);
    const float unstable = maxEdgeChange(false, &edgeUnstable);
    std::printf("edge pixels %d: largest visibility change %.4f stabilised, %.4f not (%d edge pixels)\n", edgeStable,
                stable, unstable, edgeUnstable);
    EXPECT_GT(edgeStable, 50) << "the shadow edge must be in view";
    EXPECT_LT(stable, 0.01f) << "stabilised shadow edges changed by " << stable;
    EXPECT_GT(unstable, 0.05f) << "without snapping the edges should swim (" << unstable << "): the test can fail";
}

// A wide horizontal blocker with a straight edge at two heights above the
// ground: the 10%..90% visibility transition across the shadow edge widens
// with the blocker-receiver distance.
TEST_F(ShadowRender, PenumbraGrowsWithBlockerDistance) {
    ASSERT_TRUE(params.set("shadow.softness", 6.0).has_value()); // a sun 6 degrees wide
    auto penumbraWidth = [&](float height) {
        scene::Scene s = groundScene({horizontalQuad(-6.0f, 0.0f, -4.0f, 4.0f, height, 0)});
        s.lights.push_back(sunTowards({1.0f, -1.0f, 0.0f}));
        // The shadow edge lies at x = height (45 degree sun); look at it from above and to the right.
        const float edgeX = height;
        const scene::Camera cam = topDown(edgeX + 1.0f, 0.0f, 6.0f);
        const Frame f = render(s, params, cam);
        if (f.hdr.empty())
            return -1.0f;
        const float groundDepth = f.z(kSize - 1, kSize / 2);
        // Visibility of the ground along the row through z = 0 across the edge.
        std::vector<std::pair<float, float>> profile;
        for (float x = edgeX - 0.4f; x <= edgeX + 0.6f; x += 0.5f * groundPixel(cam)) {
            const glm::vec2 p = pixelOf(cam, {x, 0.0f, 0.0f});
            if (std::abs(f.z(int(p.x), int(p.y)) - groundDepth) < 1e-6f) // not the blocker
                profile.emplace_back(x, f.red(int(p.x), int(p.y)));
        }
        if (profile.size() < 10)
            return std::nanf("");
        auto crossing = [&](float level) {
            for (std::size_t i = 1; i < profile.size(); ++i)
                if (profile[i - 1].second < level && profile[i].second >= level) {
                    const float t = (level - profile[i - 1].second) / (profile[i].second - profile[i - 1].second);
                    return profile[i - 1].first + t * (profile[i].first - profile[i - 1].first);
                }
            return std::nanf("");
        };
        EXPECT_LT(profile.front().second, 0.05f) << "umbra at height " << height;
        EXPECT_GT(profile.back().second, 0.95f) << "lit at height " << height;
        return crossing(0.9f) - crossing(0.1f);
    };
    const float low = penumbraWidth(0.3f), high = penumbraWidth(1.5f);
    std::printf("penumbra width (10%%..90%%): %.3f m with the blocker 0.3 m up, %.3f m at 1.5 m\n", low, high);
    ASSERT_TRUE(std::isfinite(low) && std::isfinite(high)) << low << " " << high;
    EXPECT_GT(high, 2.0f * low) << "low " << low << " high " << high;
    // Geometry bounds it: the full penumbra is 2 tan(3 deg) times the distance
    // along the light (height * sqrt 2), stretched by sqrt 2 on the ground.
    const float fullWidth = 2.0f * std::tan(glm::radians(3.0f)) * 1.5f * 2.0f;
    EXPECT_LT(high, 1.2f * fullWidth) << high << " vs geometric full width " << fullWidth;
}

// An alpha-masked quad with a checker alpha map casts a checker shadow (lit
// holes), an opaque quad beside it a solid one. The checker comes from a
// texture (alpha map on unit 9, coverage.glsl) that MaterialGpu binds.
TEST_F(ShadowRender, AlphaMaskedFoliageCastsMaskedShadows) {
    scene::Scene s = groundScene({horizontalQuad(-2.5f, -0.5f, -1.0f, 1.0f, 1.0f, 1),
                                  horizontalQuad(0.5f, 2.5f, -1.0f, 1.0f, 1.0f, 0)});
    scene::Material leaves;
    leaves.name = "leaves";
    leaves.alphaMode = scene::AlphaMode::Mask;
    leaves.alphaCutoff = 0.5f;
    leaves.alphaTexture = "checker.png";
    s.materials.push_back(leaves);
    scene::TextureImages textures;
    textures["checker.png"] = test::checkerAlpha(); // 4x4 cells of 0.5 m
    s.lights.push_back(sunTowards({0.0001f, -1.0f, 0.35f}));
    ASSERT_TRUE(params.set("shadow.softness", 0.0).has_value());
    // The camera sees the ground under both quads beside them (the sun shifts the shadows by 0.35 m in z).
    const scene::Camera cam = topDown(0.0f, 1.6f, 6.0f);
    const Frame f = render(s, params, cam, textures);
    ASSERT_FALSE(f.hdr.empty());
    // The shadows span z = -0.65..1.35 on the ground; the strip z = 1.05..1.3 is
    // not hidden by the quads themselves as the camera (at z = 1.6) sees them.
    auto litFraction = [&](float x0, float x1) {
        int lit = 0, total = 0;
        for (float x = x0 + 0.05f; x < x1 - 0.05f; x += 0.02f)
            for (float z = 1.05f; z < 1.3f; z += 0.02f) {
                const glm::vec2 p = pixelOf(cam, {x, 0.0f, z});
                const int px = int(p.x), py = int(p.y);
                if (px < 0 || py < 0 || px >= kSize || py >= kSize)
                    continue;
                ++total;
                lit += f.red(px, py) > 0.5f ? 1 : 0;
            }
        return total ? float(lit) / float(total) : -1.0f;
    };
    const float masked = litFraction(-2.5f, -0.5f), opaque = litFraction(0.5f, 2.5f);
    std::printf("lit fraction in the shadow: %.2f under the masked quad, %.2f under the opaque one\n", masked, opaque);
    EXPECT_LT(opaque, 0.02f) << "the opaque quad casts a solid shadow";
    EXPECT_GT(masked, 0.3f) << "the checker's holes must let light through (needs MaterialGpu to bind alpha maps)";
    EXPECT_LT(masked, 0.7f) << "and its opaque cells must still cast";
}

namespace {

// A unit box at x 1..2 beside a local light 4 m above the origin: the ground
// point (2.6, 0, 0) is behind the box as seen from the light, (-2.6, 0, 0)
// the same distance away in the open.
void expectLocalLightShadow(ShadowRender& t, scene::LightType type, const scene::ParameterSet& params,
                            const std::function<Frame(const scene::Scene&)>& render,
                            const std::function<float(const Frame&, const glm::vec3&)>& sample) {
    scene::Scene s = groundScene({boxMesh({1.0f, 0.0f, -0.5f}, {2.0f, 1.0f, 0.5f}, 0)});
    scene::Light light;
    light.type = type;
    light.position = {0.0f, 4.0f, 0.0f};
    light.direction = {0.0f, -1.0f, 0.0f};
    light.outerConeAngle = glm::radians(60.0f);
    light.innerConeAngle = glm::radians(50.0f);
    light.intensity = 20.0f;
    s.lights.push_back(light);
    (void)t;
    (void)params;
    const Frame shadowed = render(s);
    const float behind = sample(shadowed, {2.6f, 0.0f, 0.0f}), open = sample(shadowed, {-2.6f, 0.0f, 0.0f});
    s.lights[0].castShadows = false;
    const Frame unshadowed = render(s);
    const float behindNoShadow = sample(unshadowed, {2.6f, 0.0f, 0.0f});
    std::printf("%s light: behind the box %.4f, in the open %.4f, behind without shadows %.4f\n",
                scene::toString(type), behind, open, behindNoShadow);
    EXPECT_GT(open, 0.01f);
    EXPECT_LT(behind, 0.1f * open) << "behind " << behind << " open " << open;
    EXPECT_GT(behindNoShadow, 0.8f * open) << "the darkness comes from the shadow map, not from the falloff";
}

} // namespace

TEST_F(ShadowRender, SpotAndPointLightsCastShadows) {
    ASSERT_TRUE(params.set("shadow.softness", 0.2).has_value());
    const scene::Camera cam = topDown(0.0f, 0.01f, 9.0f);
    auto renderFn = [&](const scene::Scene& s) { return render(s, params, cam); };
    auto sampleFn = [&](const Frame& f, const glm::vec3& p) { return sample(f, cam, p); };
    expectLocalLightShadow(*this, scene::LightType::Spot, params, renderFn, sampleFn);
    EXPECT_EQ(lastShadowImages.size(), 0u + 0u) << "only the last render's maps (no shadows): none allocated";
    expectLocalLightShadow(*this, scene::LightType::Point, params, renderFn, sampleFn);
}

TEST_F(ShadowRender, DebugImagesNameEveryCascadeAndLocalMap) {
    scene::Scene s = groundScene({boxMesh({1.0f, 0.0f, -0.5f}, {2.0f, 1.0f, 0.5f}, 0)});
    s.lights.push_back(sunTowards({0.3f, -1.0f, 0.2f}));
    scene::Light spot;
    spot.type = scene::LightType::Spot;
    spot.position = {0.0f, 4.0f, 0.0f};
    s.lights.push_back(spot);
    scene::Light point = spot;
    point.type = scene::LightType::Point;
    s.lights.push_back(point);
    ASSERT_TRUE(params.set("shadow.mapSize", 256).has_value());
    ASSERT_TRUE(params.set("shadow.cascades", 3).has_value());
    render(s, params, topDown(0.0f, 0.0f, 8.0f));
    std::vector<std::string> names;
    for (const auto& image : lastShadowImages)
        names.push_back(image.name);
    const std::vector<std::string> expected = {"shadow-cascade-0", "shadow-cascade-1", "shadow-cascade-2",
                                               "shadow-spot-0", "shadow-point-0-px", "shadow-point-0-nx",
                                               "shadow-point-0-py", "shadow-point-0-ny", "shadow-point-0-pz",
                                               "shadow-point-0-nz"};
    EXPECT_EQ(names, expected);
    // Every map saw the ground or the box (depth below the cleared 1), except the
    // point light's faces that look up or away from everything (+y).
    for (const auto& image : lastShadowImages) {
        if (image.name == "shadow-point-0-py")
            continue;
        ASSERT_EQ(image.pixels.size(), std::size_t(image.width) * std::size_t(image.height)) << image.name;
        const float nearest = *std::min_element(image.pixels.begin(), image.pixels.end());
        EXPECT_LT(nearest, 1.0f) << image.name << " is empty";
    }
}
