#include "lpv/renderer/DrawList.h"
#include "lpv/renderer/SceneGpu.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

using namespace lpv::renderer;
using lpv::scene::Bounds;

namespace {

Bounds box(glm::vec3 center, float half) {
    Bounds b;
    b.extend(center - glm::vec3(half));
    b.extend(center + glm::vec3(half));
    return b;
}

DrawItem item(glm::vec3 center, std::uint32_t material, DrawBucket bucket = DrawBucket::Opaque) {
    DrawItem d;
    d.worldBounds = box(center, 0.5f);
    d.material = material;
    d.bucket = bucket;
    return d;
}

// Camera at the origin looking down -Z, 90 degree field of view, near 0.1, far 100.
const glm::mat4 kViewProj = glm::perspective(glm::radians(90.0f), 1.0f, 0.1f, 100.0f) *
                            glm::lookAt(glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(0.0f, 1.0f, 0.0f));

} // namespace

TEST(Frustum, BoxesInFrontAreKeptBehindAndBeyondAreCulled) {
    const FrustumPlanes p = frustumPlanes(kViewProj);
    EXPECT_TRUE(boxIntersectsFrustum(box({0, 0, -5}, 0.5f), p));
    EXPECT_FALSE(boxIntersectsFrustum(box({0, 0, 5}, 0.5f), p));     // behind the camera
    EXPECT_FALSE(boxIntersectsFrustum(box({0, 0, -200}, 0.5f), p));  // beyond the far plane
    EXPECT_FALSE(boxIntersectsFrustum(box({20, 0, -5}, 0.5f), p));   // far to the right of a 90 degree cone
    EXPECT_TRUE(boxIntersectsFrustum(box({5.2f, 0, -5}, 0.5f), p));  // straddles the right plane
    EXPECT_FALSE(boxIntersectsFrustum(Bounds{}, p));                 // empty boxes are never drawn
}

TEST(Frustum, PlanesAreNormalisedSoDistancesAreInWorldUnits) {
    const FrustumPlanes p = frustumPlanes(kViewProj);
    // Near plane (index 4) faces -Z at z = -0.1: a point at z = -1.1 is 1 unit inside it.
    EXPECT_NEAR(glm::dot(glm::vec3(p[4]), glm::vec3(0, 0, -1.1f)) + p[4].w, 1.0f, 1e-4f);
}

TEST(DrawList, CullsAndCountsAndSortsByBucketThenMaterial) {
    const std::vector<DrawItem> items{item({0, 0, -5}, 3), item({0, 0, 5}, 1), item({1, 0, -5}, 1),
                                      item({0, 1, -5}, 0, DrawBucket::Masked), item({0, 0, -6}, 2)};
    DrawListStats stats;
    const auto list = buildDrawList(items, kViewProj, glm::vec3(0.0f), &stats);
    EXPECT_EQ(stats.total, 5u);
    EXPECT_EQ(stats.culled, 1u);
    ASSERT_EQ(list.size(), 4u);
    EXPECT_EQ(list[0]->material, 1u);
    EXPECT_EQ(list[1]->material, 2u);
    EXPECT_EQ(list[2]->material, 3u);
    EXPECT_EQ(list[3]->bucket, DrawBucket::Masked); // masked after every opaque item, whatever its material
}

TEST(DrawList, BlendedItemsAreDrawnBackToFront) {
    const std::vector<DrawItem> items{item({0, 0, -3}, 0, DrawBucket::Blended), item({0, 0, -9}, 0, DrawBucket::Blended),
                                      item({0, 0, -6}, 0, DrawBucket::Blended), item({0, 0, -4}, 5)};
    const auto list = buildDrawList(items, kViewProj, glm::vec3(0.0f));
    ASSERT_EQ(list.size(), 4u);
    EXPECT_EQ(list[0]->bucket, DrawBucket::Opaque);
    EXPECT_FLOAT_EQ(list[1]->worldBounds.center().z, -9.0f);
    EXPECT_FLOAT_EQ(list[2]->worldBounds.center().z, -6.0f);
    EXPECT_FLOAT_EQ(list[3]->worldBounds.center().z, -3.0f);
}

TEST(DrawList, MaterialBucketFollowsAlphaModeColourKeyAndAdditive) {
    lpv::scene::Material m;
    EXPECT_EQ(bucketOf(m), DrawBucket::Opaque);
    m.alphaMode = lpv::scene::AlphaMode::Mask;
    EXPECT_EQ(bucketOf(m), DrawBucket::Masked);
    m = {};
    m.colorKey = true;
    EXPECT_EQ(bucketOf(m), DrawBucket::Masked);
    m = {};
    m.additive = true;
    EXPECT_EQ(bucketOf(m), DrawBucket::Blended);
    m = {};
    m.alphaMode = lpv::scene::AlphaMode::Blend;
    EXPECT_EQ(bucketOf(m), DrawBucket::Blended);
}
