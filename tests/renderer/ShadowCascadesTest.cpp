// Cascade math of the sun's shadow maps: splits, sphere fit, texel snapping.
#include "passes/direct/ShadowCascades.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>

using namespace lpv::renderer;

namespace {

lpv::scene::Bounds sceneBox() {
    lpv::scene::Bounds b;
    b.extend({-40.0f, 0.0f, -40.0f});
    b.extend({40.0f, 20.0f, 40.0f});
    return b;
}

CascadeCamera camera() {
    CascadeCamera c;
    c.position = {1.3f, 2.0f, 7.1f};
    c.forward = glm::normalize(glm::vec3(0.2f, -0.1f, -1.0f));
    c.fovY = glm::radians(60.0f);
    c.aspect = 16.0f / 9.0f;
    c.nearPlane = 0.1f;
    c.farPlane = 1000.0f;
    return c;
}

const glm::vec3 kSun = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));

// Where the world origin lands in cascade `c`'s shadow map, in texels.
glm::vec2 originTexel(const ShadowCascade& c, int mapSize) {
    const glm::vec4 clip = c.viewProj * glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    return (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * float(mapSize);
}

float distanceToInteger(glm::vec2 v) {
    return std::max(std::abs(v.x - std::round(v.x)), std::abs(v.y - std::round(v.y)));
}

} // namespace

TEST(ShadowCascades, SplitsIncreaseAndCoverNearToFar) {
    for (int count : {1, 2, 6, 8}) {
        const auto s = cascadeSplits(count, 0.1f, 120.0f);
        ASSERT_EQ(s.size(), std::size_t(count) + 1);
        EXPECT_FLOAT_EQ(s.front(), 0.1f);
        EXPECT_FLOAT_EQ(s.back(), 120.0f);
        for (std::size_t i = 1; i < s.size(); ++i)
            EXPECT_GT(s[i], s[i - 1]) << "split " << i << " of " << count;
    }
    // The practical scheme lies between the logarithmic and the uniform split.
    const auto s = cascadeSplits(4, 1.0f, 100.0f, 0.5f);
    const float logSplit = std::pow(100.0f, 0.25f), uniformSplit = 1.0f + 99.0f * 0.25f;
    EXPECT_NEAR(s[1], 0.5f * (logSplit + uniformSplit), 1e-4f);
}

TEST(ShadowCascades, FarDistanceIsClampedToTheScene) {
    const CascadeCamera c = camera();
    const float far = cascadeFarDistance(c, sceneBox());
    EXPECT_LT(far, c.farPlane);
    EXPECT_GT(far, 50.0f) << far; // the farthest corner is more than 50 m away
    const auto cascades = buildCascades(c, kSun, sceneBox(), {});
    ASSERT_EQ(cascades.size(), 6u);
    EXPECT_FLOAT_EQ(cascades.back().splitFar, far);
}

TEST(ShadowCascades, EachSphereContainsItsFrustumSlice) {
    const CascadeCamera c = camera();
    const auto cascades = buildCascades(c, kSun, sceneBox(), {6, 1024, false});
    const glm::mat4 view = glm::lookAt(c.position, c.position + c.forward, glm::vec3(0, 1, 0));
    const glm::mat4 invView = glm::inverse(view);
    const float tanY = std::tan(0.5f * c.fovY), tanX = tanY * c.aspect;
    for (const ShadowCascade& k : cascades)
        for (float d : {k.splitNear, k.splitFar})
            for (float sx : {-1.0f, 1.0f})
                for (float sy : {-1.0f, 1.0f}) {
                    const glm::vec3 p = glm::vec3(invView * glm::vec4(sx * tanX * d, sy * tanY * d, -d, 1.0f));
                    EXPECT_LE(glm::length(p - k.center), k.radius * 1.0001f);
                    // ... and the corner projects inside the cascade's map (its
                    // depth may lie outside: beyond the scene there is nothing to cast).
                    const glm::vec4 clip = k.viewProj * glm::vec4(p, 1.0f);
                    EXPECT_LE(std::abs(clip.x / clip.w), 1.0001f);
                    EXPECT_LE(std::abs(clip.y / clip.w), 1.0001f);
                }
}

TEST(ShadowCascades, DepthRangeCoversTheWholeSceneAlongTheLight) {
    // A caster far outside the camera frustum (a scene corner) must still be
    // inside every cascade's depth range.
    const auto cascades = buildCascades(camera(), kSun, sceneBox(), {});
    const lpv::scene::Bounds b = sceneBox();
    for (const ShadowCascade& k : cascades)
        for (int corner = 0; corner < 8; ++corner) {
            const glm::vec3 p{corner & 1 ? b.max.x : b.min.x, corner & 2 ? b.max.y : b.min.y,
                              corner & 4 ? b.max.z : b.min.z};
            const float z = (k.viewProj * glm::vec4(p, 1.0f)).z;
            EXPECT_GE(z, -1.0f);
            EXPECT_LE(z, 1.0f);
        }
}

TEST(ShadowCascades, StabilisedGridStaysAlignedWhenTheCameraMovesLessThanATexel) {
    constexpr int kMap = 1024;
    CascadeCamera c = camera();
    const auto before = buildCascades(c, kSun, sceneBox(), {6, kMap, true});
    c.position += glm::vec3(0.37f, 0.0f, 0.21f) * before[0].texelWorld;
    const auto after = buildCascades(c, kSun, sceneBox(), {6, kMap, true});
    for (std::size_t i = 0; i < before.size(); ++i) {
        EXPECT_FLOAT_EQ(before[i].texelWorld, after[i].texelWorld) << "cascade " << i;
        const glm::vec2 a = originTexel(before[i], kMap), b = originTexel(after[i], kMap);
        // The world origin sits on a texel corner in both, so the grid is the
        // same one, shifted by whole texels at most.
        EXPECT_LT(distanceToInteger(a), 2e-3f) << "cascade " << i << " origin at " << a.x << "," << a.y;
        EXPECT_LT(distanceToInteger(b - a), 2e-3f) << "cascade " << i << " moved by " << (b - a).x << "," << (b - a).y;
    }
    // Without snapping the grid slides with the camera (so the check above can fail).
    CascadeCamera u = camera();
    const auto unsnapped0 = buildCascades(u, kSun, sceneBox(), {6, kMap, false});
    u.position += glm::vec3(0.37f, 0.0f, 0.21f) * unsnapped0[0].texelWorld;
    const auto unsnapped1 = buildCascades(u, kSun, sceneBox(), {6, kMap, false});
    const glm::vec2 shift = originTexel(unsnapped1[0], kMap) - originTexel(unsnapped0[0], kMap);
    EXPECT_GT(distanceToInteger(shift), 0.05f) << shift.x << "," << shift.y;
}

TEST(ShadowCascades, RotatingTheCameraKeepsCascadeSizes) {
    CascadeCamera c = camera();
    const auto before = buildCascades(c, kSun, sceneBox(), {6, 1024, true});
    for (float yaw : {0.3f, 1.7f, 3.0f}) {
        c.forward = glm::vec3(glm::rotate(glm::mat4(1.0f), yaw, glm::vec3(0, 1, 0)) * glm::vec4(camera().forward, 0.0f));
        const auto after = buildCascades(c, kSun, sceneBox(), {6, 1024, true});
        for (std::size_t i = 0; i < before.size(); ++i) {
            EXPECT_FLOAT_EQ(before[i].radius, after[i].radius) << "cascade " << i << " yaw " << yaw;
            EXPECT_FLOAT_EQ(before[i].texelWorld, after[i].texelWorld);
        }
    }
}

TEST(ShadowCascades, UnionBoxContainsEveryCascade) {
    const auto cascades = buildCascades(camera(), kSun, sceneBox(), {});
    const glm::mat4 u = cascadeUnionViewProj(cascades, kSun, sceneBox());
    for (const ShadowCascade& k : cascades) {
        const glm::vec4 clip = u * glm::vec4(k.center, 1.0f);
        EXPECT_LE(std::abs(clip.x), 1.0f);
        EXPECT_LE(std::abs(clip.y), 1.0f);
    }
}

// shadow.farCascadeInterval keeps the last cascade only while
// cascadeCovers(): its slice's sphere inside the square drawn earlier.
TEST(ShadowCascades, ACascadeCoversItsOwnSliceButNotOneTurnedAway) {
    CascadeCamera c = camera();
    const auto drawn = buildCascades(c, kSun, sceneBox(), {6, 1024, true});
    for (std::size_t i = 0; i < drawn.size(); ++i)
        EXPECT_TRUE(cascadeCovers(drawn[i], drawn[i], kSun)) << "cascade " << i;
    c.forward = glm::vec3(glm::rotate(glm::mat4(1.0f), 0.5f, glm::vec3(0, 1, 0)) * glm::vec4(camera().forward, 0.0f));
    const auto turned = buildCascades(c, kSun, sceneBox(), {6, 1024, true});
    EXPECT_FALSE(cascadeCovers(drawn.back(), turned.back(), kSun)) << "a 29 degree turn moves the far slice out";
    // The rounded-up radius leaves room for a small move of the slice's
    // centre across the light, less the snapping (under one texel).
    const ShadowCascade& last = drawn.back();
    const float slack = last.radius - last.sphereRadius;
    ASSERT_GT(slack, 4.0f * last.texelWorld);
    // The light view's own x axis in the world (its rotation's first row).
    const glm::mat4 light = lightRotation(kSun);
    const glm::vec3 across(light[0][0], light[1][0], light[2][0]);
    ShadowCascade nudged = last;
    nudged.center += across * (0.5f * slack);
    EXPECT_TRUE(cascadeCovers(last, nudged, kSun));
    nudged.center = last.center + across * (slack + 2.0f * last.texelWorld);
    EXPECT_FALSE(cascadeCovers(last, nudged, kSun));
}
