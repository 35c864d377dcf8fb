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
    EXPECT_EQ(s.lights[0].type, LightType::Spot);
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
