// Numerical hard cases through the whole renderer on llvmpipe (issue #11
// item 6, docs/hard-cases.md): a sun 1 degree above the horizon, NaN, Inf and
// zero-area triangles from the OBJ importer, and LPV cascade boundaries
// crossing a sunlit wall. Small images and grids keep each case a few seconds.
#include "GlFixture.h"

#include "lpv/importers/Importer.h"
#include "lpv/renderer/ForwardRenderer.h"
#include "lpv/scene/Primitives.h"
#include "lpv/scene/ProcessId.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>

using namespace lpv;

namespace {

constexpr int kWidth = 160, kHeight = 120;
constexpr float kAlbedo = 0.8f;

// A 16 m floor and a 16 m long, 3 m high wall along z at x = 2 (its face
// toward the camera looks along -x), both of albedo 0.8, lit by a sun that
// travels toward +x at `elevationDeg` above the horizon.
scene::Scene courtyard(float elevationDeg) {
    scene::Scene s;
    scene::Material m;
    m.diffuseColor = glm::vec3(kAlbedo);
    s.materials.push_back(m);
    s.meshes.push_back(scene::makePlane(16));
    s.meshes.push_back(scene::makeBox());
    scene::Object floor;
    floor.mesh = 0;
    floor.transform.scale = glm::vec3(16.0f, 1.0f, 16.0f);
    scene::Object wall;
    wall.mesh = 1;
    wall.transform.translation = glm::vec3(2.1f, 1.5f, 0.0f);
    wall.transform.scale = glm::vec3(0.2f, 3.0f, 16.0f);
    s.objects = {floor, wall};
    scene::Light sun;
    const float e = glm::radians(elevationDeg);
    sun.direction = glm::vec3(std::cos(e), -std::sin(e), 0.0f);
    sun.intensity = 1.0f;
    s.lights.push_back(sun);
    s.sky.intensity = 0.0f; // indirect light from the sun only
    scene::Camera c;
    c.position = {0.5f, 1.2f, -7.5f};
    c.target = {1.6f, 1.0f, 2.0f};
    s.cameras.push_back(c);
    return s;
}

// Small LPV and shadow maps: the cases are about numbers, not resolution.
scene::ParameterSet smallSettings(const char* view) {
    scene::ParameterSet p;
    EXPECT_TRUE(p.set("lpv.gridSize", 16).has_value());
    EXPECT_TRUE(p.set("rsm.tileSize", 128).has_value());
    EXPECT_TRUE(p.set("shadow.mapSize", 512).has_value());
    EXPECT_TRUE(p.set("shadow.cascades", 2).has_value());
    EXPECT_TRUE(p.set("output.view", std::string(view)).has_value());
    return p;
}

struct Frame {
    std::vector<float> hdr, normal, depth;
};

Frame render(renderer::ForwardRenderer& r, const scene::Scene& s, const scene::ParameterSet& params) {
    r.setScene(s);
    // Two frames: the geometry volume also reads the previous frame's G-buffer.
    for (int i = 0; i < 2; ++i) {
        auto ok = r.render(s, params, s.cameras.front(), kWidth, kHeight);
        EXPECT_TRUE(ok.has_value()) << (ok ? "" : ok.error().describe());
    }
    return {r.readHdr(), r.readGBufferNormal(), r.readDepth()};
}

int nonFinitePixels(const std::vector<float>& rgba) {
    int bad = 0;
    for (std::size_t i = 0; i < rgba.size(); i += 4)
        bad += std::isfinite(rgba[i]) && std::isfinite(rgba[i + 1]) && std::isfinite(rgba[i + 2]) ? 0 : 1;
    return bad;
}

// World position of pixel (x, y) (rows top to bottom) from its window depth.
glm::vec3 worldAt(const scene::Camera& c, const Frame& f, int x, int y) {
    const float d = f.depth[std::size_t(y * kWidth + x)];
    const glm::mat4 inv = glm::inverse(c.projection(float(kWidth) / float(kHeight)) * c.view());
    const glm::vec4 ndc((float(x) + 0.5f) / kWidth * 2.0f - 1.0f, 1.0f - (float(y) + 0.5f) / kHeight * 2.0f,
                        d * 2.0f - 1.0f, 1.0f);
    const glm::vec4 w = inv * ndc;
    return glm::vec3(w) / w.w;
}

class HardCaseRenderGLTest : public RendererGLTest {};

} // namespace

// A sun 1 degree above the horizon (89 degrees from the zenith): the floor
// gets E sin(1 deg) = 0.017 E, the wall facing the sun almost E, and the RSM
// sees the floor at a grazing angle where a texel covers 57x its area. The
// indirect light must stay finite and below what one bounce can give.
TEST_F(HardCaseRenderGLTest, GrazingSunStaysFiniteAndBelowOneBounce) {
    double peak[2] = {0.0, 0.0}, mean[2] = {0.0, 0.0};
    const float elevations[2] = {1.0f, 45.0f};
    for (int k = 0; k < 2; ++k) {
        const scene::Scene s = courtyard(elevations[k]);
        const Frame indirect = render(*renderer_, s, smallSettings("indirect"));
        const Frame final = render(*renderer_, s, smallSettings("final"));
        EXPECT_EQ(nonFinitePixels(indirect.hdr), 0);
        EXPECT_EQ(nonFinitePixels(final.hdr), 0);
        int count = 0;
        for (std::size_t i = 0; i < indirect.hdr.size() / 4; ++i) {
            if (indirect.normal[4 * i + 3] <= 0.0f)
                continue;
            const double v = indirect.hdr[4 * i];
            EXPECT_GE(v, 0.0);
            peak[k] = std::max(peak[k], v);
            mean[k] += v;
            ++count;
        }
        mean[k] /= std::max(count, 1);
    }
    std::cout
        << "[ figures ] indirect irradiance (sun irradiance 1), sun 1 deg / 45 deg above the horizon: peak "
        << peak[0] << " / " << peak[1] << ", mean " << mean[0] << " / " << mean[1] << "\n";
    EXPECT_GT(mean[0], 0.0); // the wall still reflects the grazing sun onto the floor
    // One bounce off Lambertian surfaces of albedo 0.8 lit by irradiance <= 1
    // gives irradiance <= 0.8 (radiance <= 0.8 / pi from every direction).
    // Measured peaks 0.267 / 0.344 and means 0.116 / 0.147 (sun 1 / 45
    // degrees up). The bound is the physical one rather than the measured
    // value plus a margin: the LPV's coarse cells can overshoot near the
    // wall's foot, which is an accuracy question (docs/reference.md), not
    // a numerical one.
    EXPECT_LT(peak[0], kAlbedo);
    EXPECT_LT(peak[1], kAlbedo);
}

// An OBJ with a NaN and an Inf vertex, triangles using them, a collinear and
// a repeated-vertex triangle next to a good floor and wall: the import gives
// a scene (or a clear error), and the renderer draws the scene the importer
// returns and also one that still has the bad vertices (an importer that lets
// them through) with every pixel finite and the good geometry still lit.
TEST_F(HardCaseRenderGLTest, NanInfAndZeroAreaTrianglesRenderFinite) {
    const auto dir =
        std::filesystem::temp_directory_path() / ("lpv-hardcase-" + std::to_string(scene::processId()));
    std::filesystem::create_directories(dir);
    const auto file = dir / "degenerate.obj";
    {
        std::ofstream out(file);
        out << "v -4 0 -4\nv 4 0 -4\nv 4 0 4\nv -4 0 4\n"  // floor, facing +y
            << "v -4 0 2\nv 4 0 2\nv 4 3 2\nv -4 3 2\n"    // wall at z = 2, facing -z
            << "v nan 1 0\nv 0 inf 0\nv 1e38 -1e38 1e38\n" // not finite / near the float limit
            << "v 1 1 1\nv 2 2 2\nv 3 3 3\n"               // collinear
            << "f 1 3 2\nf 1 4 3\nf 5 7 6\nf 5 8 7\n"
            << "f 9 10 11\nf 9 1 2\nf 10 2 3\nf 12 13 14\nf 12 12 13\n";
    }
    auto imported = importers::importScene(file);
    std::filesystem::remove_all(dir);
    auto withLightAndCamera = [](scene::Scene s) {
        scene::Light sun;
        sun.direction = glm::normalize(glm::vec3(0.2f, -1.0f, 0.6f));
        s.lights = {sun};
        s.sky.intensity = 0.0f;
        scene::Camera c;
        c.position = {0.0f, 2.0f, -3.5f};
        c.target = {0.0f, 0.5f, 2.0f};
        s.cameras = {c};
        return s;
    };
    std::vector<scene::Scene> scenes;
    if (imported) {
        for (const auto& w : imported->warnings)
            std::cout << "[ warning ] " << w << "\n";
        scenes.push_back(withLightAndCamera(imported->scene));
    } else {
        std::cout << "[ figures ] import refused the file: " << imported.error().describe() << "\n";
        EXPECT_NE(imported.error().describe().find("degenerate.obj"), std::string::npos);
    }
    // The raw soup, as an importer without clean-up would hand it over.
    scene::Scene raw;
    raw.materials.push_back(scene::Material{});
    scene::Mesh mesh;
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    mesh.positions = {{-4, 0, -4},    {4, 0, -4}, {4, 0, 4},  {-4, 0, 4},  {-4, 0, 2},
                      {4, 0, 2},      {4, 3, 2},  {-4, 3, 2}, {nan, 1, 0}, {0, inf, 0},
                      {-inf, 0, nan}, {1, 1, 1},  {2, 2, 2},  {3, 3, 3}};
    mesh.normals = {{0, 1, 0},  {0, 1, 0},   {0, 1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, -1}, {0, 0, -1},
                    {0, 0, -1}, {nan, 0, 0}, {0, 1, 0}, {0, 1, 0}, {0, 0, 0},  {0, 0, 0},  {0, 0, 0}};
    mesh.indices = {0, 2, 1, 0, 3, 2, 4, 6, 5, 4, 7, 6, 8, 9, 10, 8, 0, 1, 9, 1, 2, 11, 12, 13, 11, 11, 12};
    mesh.submeshes = {{0, std::uint32_t(mesh.indices.size()), 0}};
    raw.meshes.push_back(mesh);
    scene::Object o;
    o.mesh = 0;
    raw.objects.push_back(o);
    scenes.push_back(withLightAndCamera(raw));

    for (std::size_t k = 0; k < scenes.size(); ++k) {
        const scene::Scene& s = scenes[k];
        for (const char* view : {"final", "indirect"}) {
            const Frame f = render(*renderer_, s, smallSettings(view));
            EXPECT_EQ(nonFinitePixels(f.hdr), 0)
                << (k + 1 == scenes.size() ? "raw soup" : "imported") << " " << view;
            double lit = 0.0;
            for (std::size_t i = 0; i < f.hdr.size(); i += 4)
                lit += std::isfinite(f.hdr[i]) ? f.hdr[i] : 0.0;
            std::cout << "[ figures ] " << (k + 1 == scenes.size() ? "raw soup" : "imported") << ", " << view
                      << ": summed red " << lit << "\n";
            EXPECT_GT(lit, 0.0) << "the good floor and wall still receive " << view << " light";
        }
    }
}

// LPV cascade boundaries crossing a sunlit wall: where cascade k ends the
// lookup hands over to cascade k + 1 (cells twice as large). Along the wall
// the indirect light should change smoothly; this measures the largest jump
// between neighbouring 10 cm strips at a boundary against the jumps elsewhere.
TEST_F(HardCaseRenderGLTest, CascadeBoundaryOnABrightWallLeavesABoundedSeam) {
    const scene::Scene s = courtyard(30.0f);
    const Frame f = render(*renderer_, s, smallSettings("indirect"));
    EXPECT_EQ(nonFinitePixels(f.hdr), 0);
    const auto cascades = renderer_->lpvCascadeFrames();
    ASSERT_GE(cascades.size(), 2u);
    // Profile of the indirect light on the wall face (normal -x), 0.5..2.5 m high, by z.
    constexpr float kStrip = 0.1f, kZ0 = -8.0f;
    constexpr int kMinPixels = 35;
    std::vector<double> sum(160, 0.0);
    std::vector<int> count(160, 0);
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const std::size_t i = std::size_t(y * kWidth + x);
            if (f.normal[4 * i + 3] <= 0.0f || f.normal[4 * i] > -0.9f)
                continue;
            const glm::vec3 p = worldAt(s.cameras.front(), f, x, y);
            if (p.y < 0.5f || p.y > 2.5f)
                continue;
            const int b = int(std::floor((p.z - kZ0) / kStrip));
            if (b >= 0 && b < int(sum.size())) {
                sum[std::size_t(b)] += f.hdr[4 * i];
                ++count[std::size_t(b)];
            }
        }
    // Which strips lie on a cascade's z faces (the boundaries the camera looks across).
    auto onBoundary = [&](int b) {
        const float z0 = kZ0 + float(b) * kStrip, z1 = z0 + 2.0f * kStrip; // strips b and b + 1
        for (std::size_t k = 0; k + 1 < cascades.size(); ++k)
            for (float face : {cascades[k].origin.z, cascades[k].origin.z + cascades[k].extent()})
                if (face >= z0 - 0.5f * kStrip && face <= z1 + 0.5f * kStrip)
                    return true;
        return false;
    };
    std::vector<double> elsewhere;
    double seam = 0.0;
    int boundaries = 0;
    for (int b = 0; b + 1 < int(sum.size()); ++b) {
        // Far away a strip is a few pixels that land on the bright or the dark
        // side of the LPV's cell-scale pattern; near strips average it out.
        if (count[std::size_t(b)] < kMinPixels || count[std::size_t(b) + 1] < kMinPixels)
            continue;
        const double a = sum[std::size_t(b)] / count[std::size_t(b)];
        const double c = sum[std::size_t(b) + 1] / count[std::size_t(b) + 1];
        if (a + c <= 0.0)
            continue;
        const double jump = std::abs(c - a) / (0.5 * (a + c));
        if (onBoundary(b)) {
            seam = std::max(seam, jump);
            ++boundaries;
        } else {
            elsewhere.push_back(jump);
        }
    }
    ASSERT_GT(boundaries, 0) << "no cascade boundary crosses the visible wall";
    ASSERT_GT(elsewhere.size(), 20u);
    std::sort(elsewhere.begin(), elsewhere.end());
    const double typical = elsewhere[elsewhere.size() * 9 / 10];
    std::cout << "[ figures ] wall across " << cascades.size()
              << " cascades: largest jump between 10 cm strips at a "
              << "boundary " << seam << ", 90th percentile elsewhere " << typical << ", largest elsewhere "
              << elsewhere.back() << "\n";
    // Measured 5.6% at the boundaries (cascades 0|1 at z = -3.6 and 1|2 at
    // z = -0.2) against 11% for the 90th percentile of the other strips
    // (the LPV's own cell-scale pattern, 0.25 m cells): the handover adds no
    // step that stands out. Bounds: below that pattern's 90th percentile,
    // and under 8% (the measured 5.6% plus 40% for other rasterisers'
    // pixel coverage of the strips).
    EXPECT_LT(seam, typical);
    EXPECT_LT(seam, 0.08);
}

// The courtyard moved 1e5 m from the origin (float spacing there: 7.8 mm):
// cascades, RSM and shadow maps follow the camera, so the indirect light
// must stay finite and about what it is at the origin.
TEST_F(HardCaseRenderGLTest, SceneFarFromTheOriginKeepsItsIndirectLight) {
    const glm::vec3 offset(1e5f, 0.0f, -1e5f);
    double mean[2] = {0.0, 0.0};
    for (int k = 0; k < 2; ++k) {
        scene::Scene s = courtyard(30.0f);
        if (k == 1) {
            for (scene::Object& o : s.objects)
                o.transform.translation += offset;
            s.cameras.front().position += offset;
            s.cameras.front().target += offset;
        }
        const Frame f = render(*renderer_, s, smallSettings("indirect"));
        EXPECT_EQ(nonFinitePixels(f.hdr), 0) << (k ? "far" : "origin");
        int count = 0;
        for (std::size_t i = 0; i < f.hdr.size() / 4; ++i)
            if (f.normal[4 * i + 3] > 0.0f) {
                mean[k] += f.hdr[4 * i];
                ++count;
            }
        mean[k] /= std::max(count, 1);
    }
    std::cout << "[ figures ] mean indirect irradiance at the origin " << mean[0] << ", 1e5 m away "
              << mean[1] << " (ratio " << mean[1] / mean[0] << ")\n";
    ASSERT_GT(mean[0], 0.0);
    // Measured ratio 1.017: the snapped cascades sit at other offsets to the
    // geometry out there (1e5 is not a multiple of every cascade's cell
    // relative to the camera), and positions round to 7.8 mm. 5% is 3x that;
    // a lost cascade or NaN frustum would be off by far more.
    EXPECT_NEAR(mean[1] / mean[0], 1.0, 0.05);
}
