// Lengths that scale (issue #41 item 3, docs/radiosity.md "GPU hemicube"):
// the GPU hemicube's form factors of a box are the same at the origin, in
// centimetres and kilometres, and 100 km from the origin. Its near plane is
// 1e-5 of the scene; 100 km out a float view matrix rounds the eye to 8 mm,
// so the patches are drawn relative to their own centre.
#include "GlFixture.h"

#include "lpv/radiosity/PatchMesh.h"
#include "lpv/renderer/GpuHemicube.h"

#include <gtest/gtest.h>

using namespace lpv;

namespace {

// A closed box of side `side` whose corner is at `corner`, walls facing in.
scene::Scene box(float side, const glm::dvec3& corner) {
    scene::Scene s;
    s.materials.emplace_back();
    auto quad = [&](std::array<glm::vec3, 4> c, const glm::vec3& normal) {
        if (glm::dot(glm::cross(c[1] - c[0], c[2] - c[0]), normal) < 0.0f)
            std::swap(c[1], c[3]);
        scene::Mesh m;
        for (const glm::vec3& p : c)
            m.positions.push_back(p * side);
        m.normals.assign(4, normal);
        m.indices = {0, 1, 2, 0, 2, 3};
        m.submeshes = {{0, 6, 0}};
        s.meshes.push_back(m);
        scene::Object o;
        o.mesh = int(s.meshes.size() - 1);
        o.transform.translation = glm::vec3(corner);
        s.objects.push_back(o);
    };
    quad({{{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}}}, {0, 1, 0});
    quad({{{0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1}}}, {0, -1, 0});
    quad({{{0, 0, 0}, {0, 1, 0}, {0, 1, 1}, {0, 0, 1}}}, {1, 0, 0});
    quad({{{1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1}}}, {-1, 0, 0});
    quad({{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}}, {0, 0, 1});
    quad({{{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}}, {0, 0, -1});
    return s;
}

std::vector<float> rows(const scene::Scene& s, float side) {
    const radiosity::PatchMesh mesh = radiosity::buildPatchMesh(s, {0.04f * side * side});
    auto h = renderer::GpuHemicube::create(mesh, 64, 8);
    EXPECT_TRUE(h.has_value()) << h.error().describe();
    std::vector<std::uint32_t> shooters;
    for (std::uint32_t i = 0; i < mesh.size(); i += 9)
        shooters.push_back(i);
    std::vector<float> out;
    EXPECT_TRUE((*h)->compute(shooters, out).has_value());
    return out;
}

} // namespace

class HemicubeScaleGLTest : public GlTest {};

TEST_F(HemicubeScaleGLTest, FormFactorsAreTheSameAtEveryScaleAndDistance) {
    const std::vector<float> metre = rows(box(1.0f, glm::dvec3(0.0)), 1.0f);
    ASSERT_FALSE(metre.empty());
    struct Case {
        float side;
        glm::dvec3 corner;
    };
    for (const Case& c : {Case{0.01f, glm::dvec3(0.0)}, Case{1000.0f, glm::dvec3(0.0)},
                          Case{1.0f, glm::dvec3(100000.0, 0.0, -100000.0)}}) {
        const std::vector<float> r = rows(box(c.side, c.corner), c.side);
        ASSERT_EQ(r.size(), metre.size());
        double worst = 0.0, sum = 0.0;
        for (std::size_t i = 0; i < r.size(); ++i) {
            worst = std::max(worst, double(std::abs(r[i] - metre[i])));
            sum += r[i];
        }
        // Each shooter's row sums to 1 in a closed box. Scaled, a factor moves
        // by a pixel's worth at most (64 px faces: rasterisation of other
        // numbers). 100 km out the patches' own float corners are rounded to
        // 8 mm (0.8% of this box) and the eye is lifted past that: 0.03. Drawn
        // in world coordinates the rows summed to 0.81 there.
        EXPECT_LT(worst, c.side == 1.0f ? 0.03 : 2e-3) << c.side << " at " << c.corner.x;
        EXPECT_NEAR(
            sum / double(r.size() / radiosity::buildPatchMesh(box(1.0f, glm::dvec3(0.0)), {0.04f}).size()),
            1.0, 2e-3)
            << c.side;
    }
}
