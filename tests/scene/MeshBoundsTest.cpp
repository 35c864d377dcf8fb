// Bounds of a mesh with non-finite positions (docs/hard-cases.md): the
// renderer fits the sun's shadow and RSM frusta to them, so one NaN must not
// make them NaN.
#include "lpv/scene/Mesh.h"
#include "lpv/scene/Scene.h"

#include <gtest/gtest.h>

#include <limits>

using namespace lpv::scene;

TEST(HardCaseMeshBounds, NonFinitePositionsAreLeftOutOfTheBounds) {
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    Mesh m;
    m.positions = {{nan, 0, 0}, {-1, 0, 2}, {0, inf, 0}, {3, -4, 5}, {-inf, nan, 1}};
    const Bounds b = m.computeBounds();
    EXPECT_EQ(b.min, glm::vec3(-1, -4, 2));
    EXPECT_EQ(b.max, glm::vec3(3, 0, 5));

    Scene s;
    s.meshes.push_back(m);
    Object o;
    o.mesh = 0;
    s.objects.push_back(o);
    EXPECT_EQ(s.worldBounds().min, glm::vec3(-1, -4, 2));

    Mesh onlyBad;
    onlyBad.positions = {{nan, nan, nan}};
    EXPECT_TRUE(onlyBad.computeBounds().empty());
}
