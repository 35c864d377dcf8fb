#include "RadiosityTestScenes.h"

#include "lpv/radiosity/PatchMesh.h"
#include "lpv/scene/CornellBox.h"

#include <gtest/gtest.h>

using namespace lpv;

TEST(PatchMesh, UnitSquareBecomesAGridOfQuadsNoLargerThanTheLimit) {
    const auto mesh = radiosity::buildPatchMesh(test::parallelSquares(), {0.01f});
    EXPECT_EQ(mesh.sourceQuads, 2u);
    EXPECT_EQ(mesh.sourceTriangles, 0u);
    ASSERT_EQ(mesh.size(), 200u);
    for (const auto& p : mesh.patches) {
        EXPECT_EQ(p.cornerCount, 4);
        EXPECT_LE(p.area, 0.01f * 1.0001f);
    }
    EXPECT_NEAR(mesh.totalArea(), 2.0f, 1e-4f);
}

TEST(PatchMesh, GridPatchesKnowTheirEdgeNeighbours) {
    const auto mesh = radiosity::buildPatchMesh(test::parallelSquares(), {0.01f});
    ASSERT_EQ(mesh.neighbourOffsets.size(), mesh.size() + 1);
    std::size_t interior = 0, corners = 0;
    for (std::size_t i = 0; i < mesh.size(); ++i) {
        const auto count = mesh.neighbourOffsets[i + 1] - mesh.neighbourOffsets[i];
        interior += count == 4;
        corners += count == 2;
        for (auto k = mesh.neighbourOffsets[i]; k < mesh.neighbourOffsets[i + 1]; ++k)
            EXPECT_EQ(mesh.patches[mesh.neighbours[k]].object, mesh.patches[i].object); // objects stay apart
    }
    EXPECT_EQ(interior, 2u * 8u * 8u);
    EXPECT_EQ(corners, 2u * 4u);
}

TEST(PatchMesh, LoneTrianglesAreSplitIntoSmallerTriangles) {
    scene::Scene s;
    s.materials = {test::material(glm::vec3(0.5f))};
    scene::Mesh m;
    m.positions = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}};
    m.indices = {0, 1, 2};
    m.submeshes = {{0, 3, 0}};
    s.meshes.push_back(m);
    scene::Object object;
    object.name = "tri";
    object.mesh = 0;
    s.objects.push_back(object);
    const auto mesh = radiosity::buildPatchMesh(s, {0.1f});
    EXPECT_EQ(mesh.sourceTriangles, 1u);
    ASSERT_GT(mesh.size(), 1u);
    for (const auto& p : mesh.patches) {
        EXPECT_EQ(p.cornerCount, 3);
        EXPECT_LE(p.area, 0.1f * 1.0001f);
        EXPECT_NEAR(p.normal.z, 1.0f, 1e-5f);
    }
    EXPECT_NEAR(mesh.totalArea(), 2.0f, 1e-4f);
}

TEST(PatchMesh, RefiningSplitsOnlyTheChosenPatchesAndKeepsTheArea) {
    const auto mesh = radiosity::buildPatchMesh(test::parallelSquares(), {0.25f});
    ASSERT_EQ(mesh.size(), 8u);
    std::vector<std::uint32_t> parentOf;
    const auto refined = radiosity::refinePatches(mesh, {0, 5}, parentOf);
    EXPECT_EQ(refined.size(), 8u - 2u + 2u * 4u);
    ASSERT_EQ(parentOf.size(), refined.size());
    EXPECT_EQ(std::count(parentOf.begin(), parentOf.end(), 0u), 4);
    EXPECT_NEAR(refined.totalArea(), mesh.totalArea(), 1e-5f);
}

TEST(PatchMesh, CornellBoxKeepsItsQuads) {
    const auto project = scene::makeCornellBoxProject();
    const auto mesh = radiosity::buildPatchMesh(project.scene, {0.5f});
    EXPECT_GT(mesh.sourceQuads, 15u); // 5 walls, 2 x 5 block faces, the light
    EXPECT_EQ(mesh.sourceTriangles, 0u);
    double area = 0.0;
    for (std::size_t o = 0; o < project.scene.objects.size(); ++o) {
        const auto& m = project.scene.meshes[std::size_t(project.scene.objects[o].mesh)];
        const glm::mat4 w = project.scene.worldMatrix(int(o));
        for (std::size_t t = 0; t < m.indices.size(); t += 3) {
            const glm::vec3 a0 = w * glm::vec4(m.positions[m.indices[t]], 1.0f);
            const glm::vec3 a1 = w * glm::vec4(m.positions[m.indices[t + 1]], 1.0f);
            const glm::vec3 a2 = w * glm::vec4(m.positions[m.indices[t + 2]], 1.0f);
            area += 0.5 * glm::length(glm::cross(a1 - a0, a2 - a0));
        }
    }
    EXPECT_NEAR(mesh.totalArea(), area, 1e-3 * area);
}
