// Reflective shadow maps on llvmpipe: flux, positions and normals of known
// planes under a sun of known irradiance, nested tiles rendered in one pass,
// and the pass's resource handling (no sun: nothing allocated; GL limits).
#include "GlFixture.h"

#include "scenegpu/MaterialGpu.h"
#include "passes/lpv/RsmPass.h"
#include "lpv/renderer/ForwardRenderer.h"
#include "lpv/renderer/ShaderLibrary.h"
#include "lpv/scene/CornellBox.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <optional>

using namespace lpv;
using renderer::DebugImage;

namespace {

constexpr float kIrradiance = 2.5f; // W/m^2
constexpr float kWhite = 0.8f;      // albedo

// A rectangle centred at `centre` spanned by +-halfU * u and +-halfV * v,
// facing normalize(cross(u, v)), counter-clockwise seen from that side.
scene::Mesh rectangle(const glm::vec3& centre, const glm::vec3& u, const glm::vec3& v, float halfU,
                      float halfV, std::uint32_t material) {
    scene::Mesh m;
    m.name = "rectangle";
    const glm::vec3 n = glm::normalize(glm::cross(u, v));
    const glm::vec2 corners[] = {{-1.0f, -1.0f}, {1.0f, -1.0f}, {1.0f, 1.0f}, {-1.0f, 1.0f}};
    for (const glm::vec2& c : corners) {
        m.positions.push_back(centre + c.x * halfU * u + c.y * halfV * v);
        m.normals.push_back(n);
        m.tangents.emplace_back(u, 1.0f);
        m.uvs.push_back(0.5f * c + 0.5f);
    }
    m.indices = {0, 1, 2, 0, 2, 3};
    m.submeshes = {{0, 6, material}};
    return m;
}

struct SceneBuilder {
    scene::Scene scene;

    std::uint32_t material(const glm::vec3& albedo) {
        scene::Material m;
        m.name = "m" + std::to_string(scene.materials.size());
        m.diffuseColor = albedo;
        scene.materials.push_back(m);
        return std::uint32_t(scene.materials.size() - 1);
    }
    void add(scene::Mesh mesh) {
        scene.meshes.push_back(std::move(mesh));
        scene::Object o;
        o.name = "o" + std::to_string(scene.objects.size());
        o.mesh = int(scene.meshes.size() - 1);
        scene.objects.push_back(o);
    }
    void sun(const glm::vec3& direction, float intensity = kIrradiance,
             const glm::vec3& colour = glm::vec3(1.0f)) {
        scene::Light l;
        l.name = "sun";
        l.type = scene::LightType::Directional;
        l.direction = glm::normalize(direction);
        l.intensity = intensity;
        l.color = colour;
        scene.lights.push_back(l);
    }
};

scene::ParameterSet rsmParams(int tileSize, int cascades, float cellSize = 0.5f, int gridSize = 8) {
    scene::ParameterSet p;
    EXPECT_TRUE(p.set("rsm.tileSize", tileSize).has_value());
    EXPECT_TRUE(p.set("rsm.cascades", cascades).has_value());
    EXPECT_TRUE(p.set("lpv.cellSize", double(cellSize)).has_value());
    EXPECT_TRUE(p.set("lpv.gridSize", gridSize).has_value());
    return p;
}

struct Texel {
    glm::vec4 position, normal, flux;
};

// The tiles of one RsmPass::render, read back.
struct RsmResult {
    std::vector<renderer::RsmTile> tiles;
    std::vector<DebugImage> images; // position, normal, flux per tile
    int size = 0;
    std::size_t bytes = 0;

    const DebugImage& image(int tile, int which) const { return images[std::size_t(tile * 3 + which)]; }
    Texel at(int tile, int x, int y) const {
        const std::size_t i = (std::size_t(y) * std::size_t(size) + std::size_t(x)) * 4;
        auto get = [&](int which) {
            const auto& px = image(tile, which).pixels;
            return glm::vec4(px[i], px[i + 1], px[i + 2], px[i + 3]);
        };
        return {get(0), get(1), get(2)};
    }
    template <class F> void forEachCovered(int tile, F f) const {
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x)
                if (const Texel t = at(tile, x, y); t.position.w > 0.5f)
                    f(x, y, t);
    }
    // World point under texel (x, y) (rows top to bottom) on the near plane, and the ray direction.
    glm::vec3 rayOrigin(int tile, int x, int y) const {
        const glm::vec2 ndc((float(x) + 0.5f) / float(size) * 2.0f - 1.0f,
                            1.0f - (float(y) + 0.5f) / float(size) * 2.0f);
        const glm::vec4 w = glm::inverse(tiles[std::size_t(tile)].viewProj) * glm::vec4(ndc, -1.0f, 1.0f);
        return glm::vec3(w) / w.w;
    }
};

class Rsm : public GlTest {
  protected:
    std::optional<RsmResult> render(const scene::Scene& scene, const scene::ParameterSet& params,
                                    const glm::vec3& cameraPos = glm::vec3(0.0f, 1.0f, 0.0f)) {
        if (!pass) {
            auto created = renderer::RsmPass::create();
            EXPECT_TRUE(created.has_value()) << (created ? "" : created.error().describe());
            if (!created)
                return std::nullopt;
            pass.emplace(std::move(*created));
        }
        scene::Camera camera;
        camera.position = cameraPos;
        camera.target = cameraPos + glm::vec3(0.0f, 0.0f, -1.0f);
        renderer::SceneGpu geometry(scene);
        renderer::MaterialGpu materials(scene, {});
        timer.beginFrame();
        const renderer::FrameContext frame{scene,
                                           params,
                                           camera,
                                           64,
                                           64,
                                           camera.view(),
                                           camera.projection(1.0f),
                                           camera.projection(1.0f) * camera.view(),
                                           timer,
                                           scene.worldBounds()};
        auto ok = pass->render(frame, geometry, materials);
        EXPECT_TRUE(ok.has_value()) << (ok ? "" : ok.error().describe());
        EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
        if (!ok)
            return std::nullopt;
        return RsmResult{pass->tiles(), pass->debugImages(), pass->tileSize(), pass->allocatedBytes()};
    }

    std::optional<renderer::RsmPass> pass;
    renderer::GpuTimer timer;
};

const glm::vec3 kDown(0.0f, -1.0f, 0.0f);

} // namespace

// The test: every texel of a white diffuse plane under a sun of
// irradiance E holds E x albedo x texel area, within 1%.
TEST_F(Rsm, FluxOfWhitePlaneIsIrradianceTimesAlbedoTimesTexelArea) {
    SceneBuilder b;
    b.add(rectangle({0.0f, 0.0f, 0.0f}, {1, 0, 0}, {0, 0, -1}, 20.0f, 20.0f, b.material(glm::vec3(kWhite))));
    b.sun(glm::normalize(glm::vec3(0.2f, -1.0f, 0.1f)));
    const auto r = render(b.scene, rsmParams(64, 2));
    ASSERT_TRUE(r);
    ASSERT_EQ(r->images.size(), 6u);
    for (int k = 0; k < 2; ++k) {
        const float expected = kIrradiance * kWhite * r->tiles[std::size_t(k)].texelArea;
        int covered = 0;
        float worst = 0.0f;
        r->forEachCovered(k, [&](int, int, const Texel& t) {
            ++covered;
            for (int c = 0; c < 3; ++c)
                worst = std::max(worst, std::abs(t.flux[c] / expected - 1.0f));
        });
        EXPECT_EQ(covered, 64 * 64) << "the plane fills tile " << k;
        EXPECT_LT(worst, 0.01f) << "tile " << k << ": worst relative flux error " << worst << " (expected "
                                << expected << " W per texel)";
    }
}

// A plane tilted 45 degrees from the sun covers fewer texels, but each holds
// the same flux; the tile's sum is albedo x E x the projected area.
TEST_F(Rsm, TiltedPlaneKeepsPerTexelFluxAndSumsToProjectedArea) {
    const float half = 1.0f;                                          // a 2 m x 2 m square
    const glm::vec3 v = glm::normalize(glm::vec3(0.0f, 1.0f, -1.0f)); // tilted 45 degrees about x
    for (const bool tilted : {false, true}) {
        SceneBuilder b;
        b.add(rectangle({0.0f, 0.5f, 0.0f}, {1, 0, 0}, tilted ? v : glm::vec3(0, 0, -1), half, half,
                        b.material(glm::vec3(kWhite))));
        b.sun(kDown);
        const auto r = render(b.scene, rsmParams(128, 1));
        ASSERT_TRUE(r);
        const auto& tile = r->tiles[0];
        const float perTexel = kIrradiance * kWhite * tile.texelArea;
        double sum = 0.0;
        float worst = 0.0f;
        int covered = 0;
        r->forEachCovered(0, [&](int, int, const Texel& t) {
            sum += double(t.flux.g);
            worst = std::max(worst, std::abs(t.flux.g / perTexel - 1.0f));
            ++covered;
        });
        const float projectedArea = 4.0f * half * half * (tilted ? std::sqrt(0.5f) : 1.0f);
        const double expectedSum = double(kIrradiance * kWhite * projectedArea);
        // Rasterisation decides the texels along the outline: at most half a texel row per edge.
        const double edgeBound = 0.5 *
                                 (2.0 * (2.0 * half) + 2.0 * (2.0 * half * (tilted ? std::sqrt(0.5) : 1.0))) *
                                 double(tile.texelSize) / double(projectedArea);
        EXPECT_LT(worst, 0.01f) << (tilted ? "tilted" : "flat") << ": worst per-texel flux error " << worst;
        EXPECT_LT(std::abs(sum / expectedSum - 1.0), edgeBound)
            << (tilted ? "tilted" : "flat") << ": sum " << sum << " W, expected " << expectedSum << " W over "
            << covered << " texels (edge bound " << edgeBound << ")";
    }
}

// Positions lie on the plane where each texel's ray meets it; normals are the plane's.
TEST_F(Rsm, PositionsAndNormalsMatchThePlane) {
    const glm::vec3 v = glm::normalize(glm::vec3(0.0f, 1.0f, -1.0f));
    const glm::vec3 n = glm::normalize(glm::cross(glm::vec3(1, 0, 0), v));
    const glm::vec3 centre(0.3f, 0.7f, -0.2f);
    SceneBuilder b;
    b.add(rectangle(centre, {1, 0, 0}, v, 1.5f, 1.5f, b.material(glm::vec3(kWhite))));
    const glm::vec3 sunDir = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
    b.sun(sunDir);
    const auto r = render(b.scene, rsmParams(64, 1));
    ASSERT_TRUE(r);
    float worstPos = 0.0f, worstNormal = 0.0f;
    int covered = 0;
    r->forEachCovered(0, [&](int x, int y, const Texel& t) {
        ++covered;
        // Where the ray through this texel's centre meets the plane.
        const glm::vec3 o = r->rayOrigin(0, x, y);
        const float s = glm::dot(centre - o, n) / glm::dot(sunDir, n);
        const glm::vec3 expected = o + s * sunDir;
        worstPos = std::max(worstPos, glm::length(glm::vec3(t.position) - expected));
        worstNormal = std::max(worstNormal, 1.0f - glm::dot(glm::vec3(t.normal), n));
    });
    EXPECT_GT(covered, 200) << "the plane must show in the tile";
    EXPECT_LT(worstPos, 1e-3f) << "worst position error " << worstPos << " m over " << covered << " texels";
    EXPECT_LT(worstNormal, 1e-3f) << "worst 1 - cos(normal error) " << worstNormal;
}

// The sun sees a single-sided plane from behind: the stored normal faces the sun.
TEST_F(Rsm, NormalsFaceTheSun) {
    SceneBuilder b;
    b.add(rectangle({0.0f, 0.0f, 0.0f}, {1, 0, 0}, {0, 0, 1}, 3.0f, 3.0f,
                    b.material(glm::vec3(kWhite)))); // faces -y
    b.sun(kDown);
    const auto r = render(b.scene, rsmParams(32, 1));
    ASSERT_TRUE(r);
    float lowest = 1.0f;
    r->forEachCovered(0, [&](int, int, const Texel& t) { lowest = std::min(lowest, t.normal.y); });
    EXPECT_GT(lowest, 0.999f) << "normal.y " << lowest;
}

// A red and a white plane side by side: the flux is red exactly where the red material is.
TEST_F(Rsm, FluxHasTheMaterialsColour) {
    SceneBuilder b;
    const glm::vec3 red(0.75f, 0.06f, 0.05f);
    b.add(rectangle({-5.0f, 0.0f, 0.0f}, {1, 0, 0}, {0, 0, -1}, 5.0f, 10.0f, b.material(red)));
    b.add(rectangle({5.0f, 0.0f, 0.0f}, {1, 0, 0}, {0, 0, -1}, 5.0f, 10.0f, b.material(glm::vec3(kWhite))));
    b.sun(kDown, 1.0f, glm::vec3(1.0f, 0.9f, 0.8f));
    const auto r = render(b.scene, rsmParams(64, 1));
    ASSERT_TRUE(r);
    const glm::vec3 e = glm::vec3(1.0f, 0.9f, 0.8f) * r->tiles[0].texelArea;
    int redTexels = 0, whiteTexels = 0;
    float worst = 0.0f;
    r->forEachCovered(0, [&](int, int, const Texel& t) {
        if (std::abs(t.position.x) < 0.05f)
            return; // the seam
        const glm::vec3 albedo = t.position.x < 0.0f ? red : glm::vec3(kWhite);
        (t.position.x < 0.0f ? redTexels : whiteTexels)++;
        const glm::vec3 ratio = glm::vec3(t.flux) / (albedo * e);
        worst =
            std::max({worst, std::abs(ratio.r - 1.0f), std::abs(ratio.g - 1.0f), std::abs(ratio.b - 1.0f)});
    });
    EXPECT_GT(redTexels, 1000);
    EXPECT_GT(whiteTexels, 1000);
    EXPECT_LT(worst, 0.01f) << "worst relative error of flux per channel " << worst;
}

// Tiles of cascades 0..2 render in the one pass: nested, each texel 4x the area of the finer tile's.
TEST_F(Rsm, CascadeTilesNestAndQuadrupleTexelArea) {
    SceneBuilder b;
    b.add(rectangle({0.0f, 0.0f, 0.0f}, {1, 0, 0}, {0, 0, -1}, 30.0f, 30.0f, b.material(glm::vec3(kWhite))));
    b.sun(glm::normalize(glm::vec3(-0.3f, -1.0f, 0.4f)));
    const auto r = render(b.scene, rsmParams(32, 3), {0.4f, 1.0f, 0.3f});
    ASSERT_TRUE(r);
    ASSERT_EQ(r->images.size(), 9u);
    EXPECT_EQ(r->images[4].name, "rsm-1-normal");
    std::vector<scene::Bounds> covered(3);
    std::vector<double> meanFlux(3, 0.0);
    for (int k = 0; k < 3; ++k) {
        int n = 0;
        r->forEachCovered(k, [&](int, int, const Texel& t) {
            covered[std::size_t(k)].extend(glm::vec3(t.position));
            meanFlux[std::size_t(k)] += double(t.flux.r);
            ++n;
        });
        ASSERT_EQ(n, 32 * 32);
        meanFlux[std::size_t(k)] /= n;
    }
    for (int k = 1; k < 3; ++k) {
        const auto& fine = covered[std::size_t(k - 1)];
        const auto& coarse = covered[std::size_t(k)];
        EXPECT_TRUE(glm::all(glm::lessThan(coarse.min, fine.min + glm::vec3(1e-3f))) &&
                    glm::all(glm::greaterThan(coarse.max, fine.max - glm::vec3(1e-3f))))
            << "tile " << k << " must cover tile " << k - 1;
        const float widthRatio = coarse.size().x / fine.size().x;
        EXPECT_NEAR(widthRatio, 2.0f, 0.1f) << "covered width ratio " << widthRatio;
        const double fluxRatio = meanFlux[std::size_t(k)] / meanFlux[std::size_t(k - 1)];
        EXPECT_NEAR(fluxRatio, 4.0, 0.04) << "flux per texel ratio " << fluxRatio;
        EXPECT_NEAR(r->tiles[std::size_t(k)].texelArea / r->tiles[std::size_t(k - 1)].texelArea, 4.0f, 1e-3f);
    }
    // The same pass with another tile count (another geometry-shader program) renders the same tiles.
    const auto fewer = render(b.scene, rsmParams(32, 2), {0.4f, 1.0f, 0.3f});
    ASSERT_TRUE(fewer);
    ASSERT_EQ(fewer->images.size(), 6u);
    for (int which = 0; which < 3; ++which)
        EXPECT_EQ(fewer->image(1, which).pixels, r->image(1, which).pixels) << "image " << which << " of tile 1";
}

// The tiles do not swim: a camera move inside a cell leaves the tile unchanged,
// a move across cells shifts its content by whole texels.
TEST_F(Rsm, TilesDoNotSwimWhenTheCameraMoves) {
    SceneBuilder b;
    b.add(rectangle({0.0f, 0.0f, 0.0f}, {1, 0, 0}, {0, 0, -1}, 30.0f, 30.0f, b.material(glm::vec3(kWhite))));
    b.add(rectangle({0.4f, 0.6f, -0.3f}, {1, 0, 0}, glm::normalize(glm::vec3(0, 1, -1)), 0.7f, 0.5f,
                    b.material(glm::vec3(0.3f, 0.6f, 0.2f))));
    b.sun(glm::normalize(glm::vec3(0.35f, -1.0f, 0.25f)));
    const auto params = rsmParams(64, 1); // cells of 0.5 m
    const auto before = render(b.scene, params, {0.1f, 1.0f, 0.1f});
    const auto inside = render(b.scene, params, {0.2f, 1.05f, 0.15f}); // same cell-rounded corner
    const auto across = render(b.scene, params, {1.1f, 1.0f, -0.4f});  // two cells +x, one cell -z
    ASSERT_TRUE(before && inside && across);
    EXPECT_EQ(before->image(0, 0).pixels, inside->image(0, 0).pixels) << "positions changed within a cell";
    EXPECT_EQ(before->image(0, 2).pixels, inside->image(0, 2).pixels) << "flux changed within a cell";

    const glm::vec2 shift =
        (across->tiles[0].windowMin - before->tiles[0].windowMin) / before->tiles[0].texelSize;
    const glm::ivec2 d = glm::ivec2(glm::round(shift));
    EXPECT_LT(glm::length(shift - glm::vec2(d)), 1e-2f)
        << "window moved by " << shift.x << ", " << shift.y << " texels";
    ASSERT_TRUE(d != glm::ivec2(0)) << "the move must shift the tile";
    float worst = 0.0f;
    int compared = 0;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            // Texel (x, y) of `across` (rows top to bottom) is texel (x + dx, y - dy) of `before`.
            const int bx = x + d.x, by = y - d.y;
            if (bx < 0 || by < 0 || bx >= 64 || by >= 64)
                continue;
            const Texel a = across->at(0, x, y), o = before->at(0, bx, by);
            worst = std::max({worst, glm::length(glm::vec3(a.position) - glm::vec3(o.position)),
                              glm::length(glm::vec3(a.flux) / across->tiles[0].texelArea -
                                          glm::vec3(o.flux) / before->tiles[0].texelArea)});
            ++compared;
        }
    EXPECT_GT(compared, 64 * 32);
    EXPECT_LT(worst, 1e-3f) << "after a shift by (" << d.x << ", " << d.y
                            << ") texels the worst difference is " << worst << " over " << compared
                            << " texels";
}

// A caster above the cube (outside it, toward the sun) still hides what lies below it.
TEST_F(Rsm, CastersAboveTheCascadeOcclude) {
    SceneBuilder b;
    const auto white = b.material(glm::vec3(kWhite));
    b.add(rectangle({0.0f, 0.0f, 0.0f}, {1, 0, 0}, {0, 0, -1}, 10.0f, 10.0f, white));
    b.add(rectangle({0.0f, 12.0f, 0.0f}, {1, 0, 0}, {0, 0, -1}, 1.0f, 1.0f, white)); // 2 m square, 12 m up
    b.sun(kDown);
    const auto r = render(b.scene, rsmParams(64, 1)); // cascade 0: a 4 m cube around y = 1
    ASSERT_TRUE(r);
    int high = 0;
    float areaHigh = 0.0f;
    r->forEachCovered(0, [&](int, int, const Texel& t) {
        if (t.position.y > 11.0f) {
            ++high;
            areaHigh += r->tiles[0].texelArea;
        }
    });
    EXPECT_NEAR(areaHigh, 4.0f, 0.4f) << high << " texels see the caster 12 m up";
}

// Whether MaterialGpu sets coverage uniforms (alpha mode, opacity) for the RSM:
// the stub before the materials work (issue #4, deliverable 1) sets only uDiffuse.
bool materialGpuBindsCoverage(const scene::Scene& scene, std::uint32_t maskedMaterial) {
    auto program = renderer::buildEmbeddedProgram({"rsm.vert", "rsm.geom", "rsm.frag"});
    EXPECT_TRUE(program.has_value()) << (program ? "" : program.error().describe());
    if (!program)
        return false;
    renderer::MaterialGpu materials(scene, {});
    materials.bind(program->id(), maskedMaterial, renderer::MaterialBindMode::Reflectance);
    GLint mode = 0;
    glGetUniformiv(program->id(), glGetUniformLocation(program->id(), "uAlphaMode"), &mode);
    return mode != 0;
}

// Alpha-masked surfaces are holes where their coverage is below the cut-off;
// blended ones reflect (and intercept) only the light they cover.
TEST_F(Rsm, MaskedSurfacesAreCutOutAndBlendedOnesScaleTheFlux) {
    SceneBuilder b;
    b.add(rectangle({0.0f, 0.0f, 0.0f}, {1, 0, 0}, {0, 0, -1}, 10.0f, 10.0f, b.material(glm::vec3(kWhite))));
    const auto masked = b.material(glm::vec3(0.5f));
    b.scene.materials[masked].alphaMode = scene::AlphaMode::Mask;
    b.scene.materials[masked].opacity = 0.2f; // below the 0.5 cut-off everywhere
    const auto blended = b.material(glm::vec3(0.5f));
    b.scene.materials[blended].alphaMode = scene::AlphaMode::Blend;
    b.scene.materials[blended].opacity = 0.5f;
    b.add(rectangle({-1.0f, 2.0f, 0.0f}, {1, 0, 0}, {0, 0, -1}, 0.8f, 0.8f, masked));
    b.add(rectangle({1.0f, 2.0f, 0.0f}, {1, 0, 0}, {0, 0, -1}, 0.8f, 0.8f, blended));
    b.sun(kDown);
    if (!materialGpuBindsCoverage(b.scene, masked))
        GTEST_SKIP() << "MaterialGpu does not bind coverage uniforms yet";
    const auto r = render(b.scene, rsmParams(64, 1));
    ASSERT_TRUE(r);
    const float perTexel = kIrradiance * r->tiles[0].texelArea;
    int maskedSeen = 0, blendedSeen = 0;
    float worstBlend = 0.0f;
    r->forEachCovered(0, [&](int, int, const Texel& t) {
        if (t.position.y > 1.0f && t.position.x < 0.0f)
            ++maskedSeen;
        if (t.position.y > 1.0f && t.position.x > 0.0f) {
            ++blendedSeen;
            worstBlend = std::max(worstBlend, std::abs(t.flux.g / (perTexel * 0.5f * 0.5f) - 1.0f));
        }
    });
    EXPECT_EQ(maskedSeen, 0) << "texels on the masked-out plane";
    EXPECT_GT(blendedSeen, 300);
    EXPECT_LT(worstBlend, 0.01f) << "blended flux = albedo x opacity x E x A, worst error " << worstBlend;
}

TEST_F(Rsm, WithoutSunNothingIsAllocated) {
    SceneBuilder b;
    b.add(rectangle({0.0f, 0.0f, 0.0f}, {1, 0, 0}, {0, 0, -1}, 2.0f, 2.0f, b.material(glm::vec3(kWhite))));
    b.sun(kDown);
    const auto lit = render(b.scene, rsmParams(64, 2));
    ASSERT_TRUE(lit);
    EXPECT_EQ(lit->bytes, std::size_t(64 * 64 * 2 * 44)); // position 16, normal 8, flux 16, depth 4
    b.scene.lights.front().type = scene::LightType::Point;
    const auto dark = render(b.scene, rsmParams(64, 2));
    ASSERT_TRUE(dark);
    EXPECT_EQ(dark->bytes, 0u);
    EXPECT_TRUE(dark->images.empty());
    EXPECT_FALSE(pass->active());
    EXPECT_EQ(pass->positionArray(), 0u);
}

TEST_F(Rsm, TargetsBeyondGlLimitsAreErrorValues) {
    const renderer::RsmTargetLimits small{512, 2048, 2048, 16384};
    const auto tooLarge = renderer::checkRsmTargets(1024, 4, small);
    ASSERT_FALSE(tooLarge.has_value());
    EXPECT_NE(tooLarge.error().describe().find("rsm.tileSize"), std::string::npos)
        << tooLarge.error().describe();
    const auto tooMany = renderer::checkRsmTargets(256, 7, small);
    ASSERT_FALSE(tooMany.has_value());
    EXPECT_NE(tooMany.error().describe().find("rsm.cascades"), std::string::npos)
        << tooMany.error().describe();
    EXPECT_TRUE(renderer::checkRsmTargets(512, 6, small).has_value());
    // The largest setting fits this GPU (llvmpipe: 16384^2, 2048 layers), and renders.
    EXPECT_TRUE(renderer::checkRsmTargets(1024, 6, renderer::RsmTargetLimits::query()).has_value());
    SceneBuilder b;
    b.add(rectangle({0.0f, 0.0f, 0.0f}, {1, 0, 0}, {0, 0, -1}, 2.0f, 2.0f, b.material(glm::vec3(kWhite))));
    b.sun(kDown);
    const auto r = render(b.scene, rsmParams(1024, 6));
    ASSERT_TRUE(r);
    EXPECT_EQ(r->bytes, std::size_t(1024) * 1024 * 6 * 44);
    EXPECT_EQ(r->images.size(), 18u);
}

// Through the renderer: the frame runs the RSM and debugImages("rsm") returns its tiles.
TEST_F(Rsm, ForwardRendererExposesTheTiles) {
    scene::Project project = scene::makeCornellBoxProject();
    auto renderer = renderer::ForwardRenderer::create();
    ASSERT_TRUE(renderer.has_value()) << renderer.error().describe();
    scene::Scene& s = project.scene;
    renderer->setScene(s);
    ASSERT_TRUE(renderer->render(s, project.parameters, s.cameras.front(), 32, 32).has_value());
    EXPECT_TRUE(renderer->debugImages("rsm").empty()) << "the Cornell box has no sun";
    SceneBuilder b;
    b.sun(kDown);
    s.lights.push_back(b.scene.lights.front());
    ASSERT_TRUE(project.parameters.set("rsm.tileSize", 32).has_value());
    ASSERT_TRUE(renderer->render(s, project.parameters, s.cameras.front(), 32, 32).has_value());
    const auto images = renderer->debugImages("rsm");
    ASSERT_EQ(images.size(), std::size_t(3 * project.parameters.getInt("rsm.cascades")));
    EXPECT_EQ(images[0].name, "rsm-0-position");
    EXPECT_EQ(images[2].name, "rsm-0-flux");
    // The sun sees the box's ceiling from above: positions at the ceiling's height, flux > 0.
    const scene::Bounds box = s.worldBounds();
    int top = 0;
    const DebugImage& pos = images[images.size() - 3]; // the coarsest tile's positions
    for (std::size_t i = 0; i < pos.pixels.size(); i += 4)
        if (pos.pixels[i + 3] > 0.5f && pos.pixels[i + 1] > box.max.y - 0.05f)
            ++top;
    EXPECT_GT(top, 0) << "the coarsest tile must see the top of the box";
}
