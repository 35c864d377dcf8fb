#include "passes/lpv/RsmCascades.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace lpv;
using renderer::LpvCascadeSettings;

namespace {

const LpvCascadeSettings kSettings{4, 32, 0.25f, true};
const glm::vec3 kSun = glm::normalize(glm::vec3(0.3f, -1.0f, 0.45f));

bool contains(const scene::Bounds& outer, const scene::Bounds& inner) {
    return glm::all(glm::lessThanEqual(outer.min, inner.min)) &&
           glm::all(glm::greaterThanEqual(outer.max, inner.max));
}

// Distance of x / cell from the nearest integer.
float offGrid(float x, float cell) {
    const double q = double(x) / double(cell);
    return float(std::abs(q - std::round(q)));
}

} // namespace

TEST(RsmCascades, CascadesNestAndDouble) {
    for (const glm::vec3 camera :
         {glm::vec3(0.0f), glm::vec3(3.37f, -1.21f, 12.9f), glm::vec3(-101.3f, 7.7f, 0.13f)}) {
        const auto cascades = renderer::lpvCascades(camera, kSettings);
        ASSERT_EQ(cascades.size(), 4u);
        for (std::size_t k = 0; k < cascades.size(); ++k) {
            const auto& c = cascades[k];
            EXPECT_FLOAT_EQ(c.cellSize, 0.25f * float(1 << k));
            EXPECT_EQ(c.gridSize, 32);
            // The camera stays within half a cell of the centre.
            const glm::vec3 centre = c.bounds().center();
            EXPECT_LE(glm::length(centre - camera), 0.5f * std::sqrt(3.0f) * c.cellSize + 1e-4f)
                << "cascade " << k << " centre is " << glm::length(centre - camera) << " from the camera";
            if (k > 0) {
                EXPECT_FLOAT_EQ(c.extent(), 2.0f * cascades[k - 1].extent());
                EXPECT_TRUE(contains(c.bounds(), cascades[k - 1].bounds()))
                    << "cascade " << k << " must hold " << k - 1;
            }
        }
    }
}

TEST(RsmCascades, SnappingKeepsOriginsOnWholeCells) {
    const glm::vec3 start(1.234f, 5.678f, -9.012f);
    const auto before = renderer::lpvCascades(start, kSettings);
    for (const auto& c : before)
        for (int a = 0; a < 3; ++a)
            EXPECT_LT(offGrid(c.origin[a], c.cellSize), 1e-4f) << "axis " << a << " cell " << c.cellSize;
    // Cascade k+1's cell corners are cell corners of cascade k.
    for (std::size_t k = 1; k < before.size(); ++k)
        for (int a = 0; a < 3; ++a)
            EXPECT_LT(offGrid(before[k].origin[a] - before[k - 1].origin[a], before[k - 1].cellSize), 1e-4f);

    // Whatever the camera's move, the grid either stays or jumps by whole cells; it never slides.
    for (float step : {0.01f, 0.05f, 0.12f, 0.3f, 1.1f}) {
        const auto after = renderer::lpvCascades(start + glm::vec3(step, -step, 0.5f * step), kSettings);
        for (std::size_t k = 0; k < after.size(); ++k) {
            const glm::vec3 moved = (after[k].origin - before[k].origin) / after[k].cellSize;
            for (int a = 0; a < 3; ++a)
                EXPECT_LT(std::abs(moved[a] - std::round(moved[a])), 1e-3f)
                    << "step " << step << " cascade " << k << " moved " << moved[a] << " cells on axis " << a;
        }
    }

    // Without snapping the cube follows the camera exactly.
    LpvCascadeSettings free = kSettings;
    free.snapToCells = false;
    const auto c = renderer::lpvCascade(start, 2, free);
    EXPECT_LT(glm::length(c.bounds().center() - start), 1e-5f);
}

TEST(RsmCascades, TileCoversTheCube) {
    scene::Bounds sceneBounds{{-40.0f, -5.0f, -30.0f}, {40.0f, 25.0f, 30.0f}};
    for (const glm::vec3 sun :
         {kSun, glm::vec3(0.0f, -1.0f, 0.0f), glm::normalize(glm::vec3(1.0f, -0.2f, 0.0f))}) {
        for (const auto& c : renderer::lpvCascades({2.0f, 1.0f, -3.0f}, kSettings)) {
            const auto tile = renderer::makeRsmTile(c, sun, sceneBounds, 256);
            const scene::Bounds b = c.bounds();
            float maxNdc = 0.0f;
            for (int i = 0; i < 8; ++i) {
                const glm::vec3 corner((i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y,
                                       (i & 4) ? b.max.z : b.min.z);
                const glm::vec4 clip = tile.viewProj * glm::vec4(corner, 1.0f);
                maxNdc = std::max({maxNdc, std::abs(clip.x), std::abs(clip.y), std::abs(clip.z)});
            }
            EXPECT_LE(maxNdc, 1.0f) << "cell " << c.cellSize << ": a cube corner is outside the tile";
            // ... and tightly: the footprint fills all but about one texel of the window.
            const scene::Bounds ls = renderer::lightSpaceBounds(tile.view, b);
            const float footprint = std::max(ls.size().x, ls.size().y);
            EXPECT_NEAR(footprint / tile.texelSize, 255.0f, 1e-2f);
            // The depth range reaches back to the scene's top (towards the sun).
            const glm::vec4 sceneTop = tile.viewProj * glm::vec4(0.0f, 25.0f, 0.0f, 1.0f);
            EXPECT_GE(sceneTop.z, -1.0f) << "a caster at the scene's top must be inside the depth range";
        }
    }
}

TEST(RsmCascades, TexelAreaQuadruplesPerCascade) {
    const auto cascades = renderer::lpvCascades({0.5f, 0.5f, 0.5f}, kSettings);
    for (std::size_t k = 1; k < cascades.size(); ++k) {
        const auto fine = renderer::makeRsmTile(cascades[k - 1], kSun, {}, 128);
        const auto coarse = renderer::makeRsmTile(cascades[k], kSun, {}, 128);
        EXPECT_NEAR(coarse.texelArea / fine.texelArea, 4.0f, 1e-4f);
        EXPECT_FLOAT_EQ(fine.texelArea, fine.texelSize * fine.texelSize);
    }
}

TEST(RsmCascades, TileTexelsAreStableInLightSpace) {
    // Same cube -> identical matrices; a moved cube -> the window moves by whole texels.
    const auto c0 = renderer::lpvCascade({0.0f, 0.0f, 0.0f}, 1, kSettings);
    const auto c1 = renderer::lpvCascade({0.9f, 0.4f, -0.6f}, 1, kSettings);
    const auto t0 = renderer::makeRsmTile(c0, kSun, {}, 64);
    const auto t1 = renderer::makeRsmTile(c1, kSun, {}, 64);
    EXPECT_FLOAT_EQ(t0.texelSize, t1.texelSize);
    auto left = [](const renderer::RsmTile& t) { return t.windowMin.x; };
    auto bottom = [](const renderer::RsmTile& t) { return t.windowMin.y; };
    EXPECT_NEAR((t0.windowMax.x - t0.windowMin.x) / t0.texelSize, 64.0f, 1e-3f);
    // The window's edges are those of the projection.
    const glm::vec4 corner =
        t1.viewProj * glm::inverse(t1.view) * glm::vec4(t1.windowMin, -t1.nearDepth, 1.0f);
    EXPECT_NEAR(corner.x, -1.0f, 1e-4f);
    EXPECT_NEAR(corner.y, -1.0f, 1e-4f);
    EXPECT_NEAR(corner.z, -1.0f, 1e-4f);
    EXPECT_LT(offGrid(left(t1) - left(t0), t0.texelSize), 2e-3f)
        << (left(t1) - left(t0)) / t0.texelSize << " texels";
    EXPECT_LT(offGrid(bottom(t1) - bottom(t0), t0.texelSize), 2e-3f)
        << (bottom(t1) - bottom(t0)) / t0.texelSize << " texels";
}

TEST(RsmCascades, UnionViewHoldsEveryTile) {
    const scene::Bounds sceneBounds{{-10.0f, 0.0f, -10.0f}, {10.0f, 8.0f, 10.0f}};
    std::vector<renderer::RsmTile> tiles;
    for (const auto& c : renderer::lpvCascades({1.0f, 2.0f, 3.0f}, kSettings))
        tiles.push_back(renderer::makeRsmTile(c, kSun, sceneBounds, 64));
    const glm::mat4 all = renderer::rsmUnionViewProj(tiles);
    for (const auto& t : tiles) {
        const glm::mat4 tileToUnion = all * glm::inverse(t.viewProj);
        for (int i = 0; i < 8; ++i) {
            const glm::vec4 ndc((i & 1) ? 1.0f : -1.0f, (i & 2) ? 1.0f : -1.0f, (i & 4) ? 1.0f : -1.0f, 1.0f);
            const glm::vec4 p = tileToUnion * ndc;
            EXPECT_LE(std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}), 1.0f + 1e-4f)
                << "cell " << t.cascade.cellSize << " corner " << i;
        }
    }
}

TEST(RsmCascades, SunIsTheFirstDirectionalLight) {
    scene::Scene s;
    EXPECT_EQ(renderer::findSun(s), -1);
    auto light = [](scene::LightType type) {
        scene::Light l;
        l.type = type;
        return l;
    };
    s.lights.push_back(light(scene::LightType::Point));
    EXPECT_EQ(renderer::findSun(s), -1);
    s.lights.push_back(light(scene::LightType::Directional));
    s.lights.push_back(light(scene::LightType::Directional));
    EXPECT_EQ(renderer::findSun(s), 1);
}

// lpv.viewShift (issue #24 item 1): each cube moves ahead of the camera along
// the view direction, still snapped to its own cells, still nested, and the
// camera keeps two cells of every cascade behind it.
TEST(RsmCascades, ViewShiftMovesEachCascadeAheadAndKeepsThemNested) {
    const glm::vec3 directions[] = {glm::vec3(0, 0, 1), glm::vec3(-1, 0, 0), glm::normalize(glm::vec3(0.3f, -0.2f, 0.9f)),
                                    glm::normalize(glm::vec3(1, 1, 1))};
    for (const float shift : {0.25f, 0.5f, 1.0f})
        for (const glm::vec3& dir : directions)
            for (const glm::vec3 camera : {glm::vec3(0.0f), glm::vec3(3.37f, -1.21f, 12.9f), glm::vec3(-101.3f, 7.7f, 0.13f)}) {
                LpvCascadeSettings settings = kSettings;
                settings.viewShift = shift;
                const auto cascades = renderer::lpvCascades(camera, dir * 3.0f, settings); // any length
                ASSERT_EQ(cascades.size(), 4u);
                for (std::size_t k = 0; k < cascades.size(); ++k) {
                    const auto& c = cascades[k];
                    const float wanted = shift * (0.5f * c.extent() - 2.0f * c.cellSize);
                    const glm::vec3 offset = c.bounds().center() - camera;
                    // Ahead by the wanted distance, up to the half-cell snap per axis.
                    EXPECT_NEAR(glm::dot(offset, dir), wanted, 0.5f * std::sqrt(3.0f) * c.cellSize + 1e-3f)
                        << "shift " << shift << " cascade " << k;
                    EXPECT_LE(glm::length(offset - dir * wanted), 0.5f * std::sqrt(3.0f) * c.cellSize + 1e-3f);
                    for (int a = 0; a < 3; ++a) {
                        EXPECT_LT(offGrid(c.origin[a], c.cellSize), 1e-4f);
                        // The camera keeps at least 1.5 cells (2 less the snap) to every face.
                        EXPECT_GE(camera[a] - c.origin[a], 1.5f * c.cellSize - 1e-3f) << "axis " << a;
                        EXPECT_GE(c.origin[a] + c.extent() - camera[a], 1.5f * c.cellSize - 1e-3f) << "axis " << a;
                    }
                    if (k > 0) {
                        EXPECT_TRUE(contains(c.bounds(), cascades[k - 1].bounds()))
                            << "shift " << shift << ": cascade " << k << " must hold " << k - 1;
                    }
                }
            }
}

// What the shift is for: the Cornell template's camera stands 8 m in front
// of its 5.6 m box, so centred cubes put the box only in the coarser
// cascades; with the shift a finer one holds all of it.
TEST(RsmCascades, ViewShiftBringsADistantBoxIntoAFinerCascade) {
    const LpvCascadeSettings centred{4, 32, 0.25f, true, 0.0f};
    LpvCascadeSettings ahead = centred;
    ahead.viewShift = 1.0f;
    const glm::vec3 camera(2.78f, 2.73f, -8.0f), dir(0.0f, 0.0f, 1.0f);
    const scene::Bounds box{glm::vec3(0.0f), glm::vec3(5.56f, 5.49f, 5.59f)};
    auto finestHolding = [&](const LpvCascadeSettings& s) {
        const auto cascades = renderer::lpvCascades(camera, dir, s);
        for (std::size_t k = 0; k < cascades.size(); ++k)
            if (contains(cascades[k].bounds(), box))
                return int(k);
        return -1;
    };
    EXPECT_EQ(finestHolding(centred), 2); // 1 m cells: 5.6 across the box
    EXPECT_EQ(finestHolding(ahead), 1);   // 0.5 m cells: 11 across
}


// lpv.clampToScene: each cascade as near the camera's placement as it can be
// while covering as much of the scene as its extent allows. The Cornell box
// seen from 8 m: the finest cascade holds the whole box; a camera inside a
// long hall keeps its finest cascade and the coarse ones stop at the walls.
TEST(RsmCascades, ClampedToTheSceneCascadesCoverItAndStayNested) {
    const scene::Bounds box{glm::vec3(0.0f), glm::vec3(5.56f, 5.49f, 5.59f)};
    LpvCascadeSettings clamped{4, 32, 0.2f, true, 0.0f};
    clamped.sceneBounds = box;
    const auto outside = renderer::lpvCascades(glm::vec3(2.78f, 2.73f, -8.0f), glm::vec3(0, 0, 1), clamped);
    ASSERT_EQ(outside.size(), 4u);
    for (const auto& c : outside)
        EXPECT_TRUE(contains(c.bounds(), box)) << "every cascade, 6.4 m or more across, holds the 5.6 m box";

    const scene::Bounds hall{glm::vec3(-20.0f, -2.0f, -8.0f), glm::vec3(20.0f, 15.0f, 8.0f)};
    LpvCascadeSettings inHall{4, 32, 0.25f, true, 0.0f};
    inHall.sceneBounds = hall;
    for (const glm::vec3 camera : {glm::vec3(-15.3f, 3.0f, 0.4f), glm::vec3(0.0f, 1.0f, 7.5f), glm::vec3(60.0f, 80.0f, -3.0f)}) {
        const auto cascades = renderer::lpvCascades(camera, glm::vec3(1, 0, 0), inHall);
        const auto centred = renderer::lpvCascades(camera, glm::vec3(1, 0, 0), LpvCascadeSettings{4, 32, 0.25f, true});
        for (std::size_t k = 0; k < cascades.size(); ++k) {
            const auto& c = cascades[k];
            for (int a = 0; a < 3; ++a) {
                EXPECT_LT(offGrid(c.origin[a], c.cellSize), 1e-4f) << "snapped";
                const float span = hall.max[a] - hall.min[a];
                if (c.extent() >= span) { // holds the hall along this axis (up to the snap)
                    EXPECT_LE(c.origin[a], hall.min[a] + 0.5f * c.cellSize + 1e-3f) << "cascade " << k << " axis " << a;
                    EXPECT_GE(c.origin[a] + c.extent(), hall.max[a] - 0.5f * c.cellSize - 1e-3f);
                } else { // lies inside it
                    EXPECT_GE(c.origin[a], hall.min[a] - 0.5f * c.cellSize - 1e-3f) << "cascade " << k << " axis " << a;
                    EXPECT_LE(c.origin[a] + c.extent(), hall.max[a] + 0.5f * c.cellSize + 1e-3f);
                }
            }
            if (k > 0) {
                EXPECT_TRUE(contains(c.bounds(), cascades[k - 1].bounds())) << "cascade " << k << " must hold " << k - 1;
            }
        }
        // Inside the hall, away from its walls, the finest cascade does not move.
        if (camera == glm::vec3(-15.3f, 3.0f, 0.4f)) {
            EXPECT_EQ(cascades[0].origin, centred[0].origin);
        }
    }
}
