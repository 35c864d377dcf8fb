#include "lpv/scene/CornellBox.h"
#include "lpv/scene/Picking.h"
#include "lpv/scene/Primitives.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

using namespace lpv::scene;

namespace {

// Every triangle's winding agrees with its vertex normals (front faces counter-clockwise).
void expectOutwardWinding(const Mesh& m) {
    for (std::size_t i = 0; i + 2 < m.indices.size(); i += 3) {
        const glm::vec3 a = m.positions[m.indices[i]], b = m.positions[m.indices[i + 1]], c = m.positions[m.indices[i + 2]];
        const glm::vec3 face = glm::cross(b - a, c - a);
        const glm::vec3 n = m.normals[m.indices[i]] + m.normals[m.indices[i + 1]] + m.normals[m.indices[i + 2]];
        EXPECT_GT(glm::dot(face, n), 0.0f) << m.name << " triangle " << i / 3;
    }
}

Scene sceneWith(Mesh mesh, const std::vector<glm::vec3>& positions) {
    Scene s;
    s.meshes.push_back(std::move(mesh));
    s.materials.emplace_back();
    for (std::size_t i = 0; i < positions.size(); ++i) {
        Object o;
        o.name = "o" + std::to_string(i);
        o.mesh = 0;
        o.transform.translation = positions[i];
        s.objects.push_back(o);
    }
    return s;
}

} // namespace

TEST(Primitives, UnitSizedWithConsistentStreams) {
    for (const Mesh& m : {makePlane(4), makeBox(), makeSphere(24, 12)}) {
        SCOPED_TRACE(m.name);
        ASSERT_EQ(m.normals.size(), m.positions.size());
        ASSERT_EQ(m.tangents.size(), m.positions.size());
        ASSERT_EQ(m.uvs.size(), m.positions.size());
        ASSERT_EQ(m.submeshes.size(), 1u);
        EXPECT_EQ(m.submeshes[0].indexCount, m.indices.size());
        const Bounds b = m.computeBounds();
        EXPECT_NEAR(b.size().x, 1.0f, 1e-5f);
        EXPECT_NEAR(b.size().z, 1.0f, 1e-5f);
        EXPECT_NEAR(glm::length(b.center()), 0.0f, 1e-5f);
        expectOutwardWinding(m);
    }
    EXPECT_EQ(makePlane(4).triangleCount(), 32u);
    EXPECT_EQ(makeBox().triangleCount(), 12u);
    // Poles have one triangle per segment, other rings two.
    EXPECT_EQ(makeSphere(24, 12).triangleCount(), std::size_t(24 * (2 * 12 - 2)));
}

TEST(Picking, NearestVisibleObjectAlongTheRay) {
    Scene s = sceneWith(makeBox(), {{0, 0, 0}, {0, 0, -3}, {3, 0, 0}});
    auto hit = pickObject(s, {0, 0, 5}, {0, 0, -1});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->object, 0);
    EXPECT_NEAR(hit->distance, 4.5f, 1e-4f);
    EXPECT_NEAR(hit->position.z, 0.5f, 1e-4f);

    s.objects[0].visible = false; // hidden objects cannot be clicked
    hit = pickObject(s, {0, 0, 5}, {0, 0, -1});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->object, 1);
    EXPECT_NEAR(hit->distance, 7.5f, 1e-4f);

    EXPECT_FALSE(pickObject(s, {0, 5, 5}, {0, 0, -1})); // passes above everything
}

TEST(Picking, FollowsScaleRotationAndParents) {
    Scene s = sceneWith(makeBox(), {{0, 0, 0}, {0, 0, 0}});
    s.objects[0].transform.translation = {10, 0, 0};
    s.objects[1].parent = 0;
    s.objects[1].transform.translation = {0, 4, 0};
    s.objects[1].transform.scale = glm::vec3(2.0f);
    auto hit = pickObject(s, {10, 4, 10}, {0, 0, -1});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->object, 1);
    EXPECT_NEAR(hit->position.z, 1.0f, 1e-4f); // scaled box: half size 1
    EXPECT_NEAR(objectWorldBounds(s, 1).size().y, 2.0f, 1e-5f);
}

TEST(Picking, CameraRayThroughTheImageCentreLooksAtTheTarget) {
    Camera c;
    c.position = {1, 2, 3};
    c.target = {4, 2, -1};
    const Ray r = cameraRay(c, 320, 240, 640, 480);
    EXPECT_NEAR(glm::length(r.direction - glm::normalize(c.target - c.position)), 0.0f, 1e-4f);
    // A pixel left of centre points left of the view direction.
    const Ray left = cameraRay(c, 0, 240, 640, 480);
    const glm::vec3 right = glm::cross(r.direction, c.up);
    EXPECT_LT(glm::dot(left.direction, right), 0.0f);
}

TEST(Picking, CornellBoxTallBlockIsHitFromTheCamera) {
    const Project p = makeCornellBoxProject();
    ASSERT_FALSE(p.scene.cameras.empty());
    const Camera& c = p.scene.cameras.front();
    const Ray r = cameraRay(c, 320, 240, 640, 480);
    auto hit = pickObject(p.scene, r.origin, r.direction);
    ASSERT_TRUE(hit);
    EXPECT_GE(hit->object, 0);
    EXPECT_GT(hit->distance, c.nearPlane);
}
