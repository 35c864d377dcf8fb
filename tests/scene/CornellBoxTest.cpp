#include "lpv/scene/CornellBox.h"

#include <gtest/gtest.h>

using namespace lpv::scene;

TEST(CornellBox, HasPublishedLayout) {
    const Project p = makeCornellBoxProject();
    const Scene& s = p.scene;
    ASSERT_EQ(s.meshes.size(), 4u);
    // 5 room quads + 5 per block + the light: 16 quads, 32 triangles.
    EXPECT_EQ(s.triangleCount(), 32u);
    const Bounds b = s.worldBounds();
    EXPECT_NEAR(b.min.x, 0.0f, 1e-4f);
    EXPECT_NEAR(b.max.x, 5.56f, 1e-4f);
    EXPECT_NEAR(b.max.y, 5.488f, 1e-4f);
    EXPECT_NEAR(b.max.z, 5.592f, 1e-4f);
    ASSERT_EQ(s.lights.size(), 1u);
    // The published lamp: a 130 x 105 mm one-sided rectangle of radiance (17, 12, 4) in the
    // light quad's plane, facing down.
    const Light& lamp = s.lights[0];
    EXPECT_EQ(lamp.type, LightType::Area);
    EXPECT_EQ(lamp.shape, AreaShape::Rectangle);
    EXPECT_FALSE(lamp.twoSided);
    EXPECT_NEAR(lamp.size.x, 1.30f, 1e-6f);
    EXPECT_NEAR(lamp.size.y, 1.05f, 1e-6f);
    EXPECT_NEAR(lamp.position.y, 5.487f, 1e-5f);
    EXPECT_EQ(lamp.direction, glm::vec3(0.0f, -1.0f, 0.0f));
    EXPECT_NEAR(lamp.color.r * lamp.intensity, 17.0f, 1e-4f);
    EXPECT_NEAR(lamp.color.g * lamp.intensity, 12.0f, 1e-4f);
    EXPECT_NEAR(lamp.color.b * lamp.intensity, 4.0f, 1e-4f);
    ASSERT_NE(s.findCamera("default"), nullptr);
}

// Every room face must point into the box and every block face out of its
// block, or one-sided shading and shadow tests would silently go wrong.
TEST(CornellBox, FacesAreOrientedConsistently) {
    const Project p = makeCornellBoxProject();
    const Mesh& room = p.scene.meshes[0];
    const glm::vec3 inside(2.78f, 2.744f, 2.796f);
    for (std::size_t i = 0; i < room.indices.size(); i += 3) {
        const glm::vec3 a = room.positions[room.indices[i]], b = room.positions[room.indices[i + 1]],
                        c = room.positions[room.indices[i + 2]];
        const glm::vec3 n = glm::cross(b - a, c - a);
        EXPECT_GT(glm::dot(n, inside - a), 0.0f) << "room triangle " << i / 3;
        EXPECT_GT(glm::dot(n, room.normals[room.indices[i]]), 0.0f);
    }
    // Red wall at x ~ 5.5 (left as the camera sees it), green at x = 0.
    const Mesh& m = room;
    const Submesh& red = m.submeshes[1];
    EXPECT_EQ(p.scene.materials[red.materialIndex].name, "red");
    EXPECT_GT(m.positions[m.indices[red.firstIndex]].x, 5.0f);
    const Submesh& green = m.submeshes[2];
    EXPECT_EQ(p.scene.materials[green.materialIndex].name, "green");
    EXPECT_LT(m.positions[m.indices[green.firstIndex]].x, 0.01f);
}
