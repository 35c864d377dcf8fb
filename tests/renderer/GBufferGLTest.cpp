// The camera G-buffer (depth, normal, albedo) that later passes reuse: it must
// hold the surfaces the camera sees, and nothing where it sees the sky.
#include "GlFixture.h"

#include "lpv/renderer/ForwardRenderer.h"
#include "lpv/scene/CornellBox.h"

#include <glm/gtc/matrix_transform.hpp>

using namespace lpv;

namespace {

constexpr int kSize = 128;

glm::vec4 texel(const std::vector<float>& px, int x, int y) {
    const std::size_t i = (std::size_t(y) * kSize + std::size_t(x)) * 4;
    return {px[i], px[i + 1], px[i + 2], px[i + 3]};
}

} // namespace

class GBuffer : public GlTest {};

TEST_F(GBuffer, HoldsTheCornellWallsNormalsAndAlbedos) {
    scene::Project project = scene::makeCornellBoxProject();
    const scene::Camera& cam = project.scene.cameras.front();
    auto r = renderer::ForwardRenderer::create();
    ASSERT_TRUE(r.has_value()) << r.error().describe();
    r->setScene(project.scene);
    ASSERT_TRUE(r->render(project.scene, project.parameters, cam, kSize, kSize).has_value());
    const auto normals = r->readGBufferNormal();
    const auto albedo = r->readGBufferAlbedo();
    const auto depth = r->readDepth();
    ASSERT_EQ(normals.size(), std::size_t(kSize * kSize * 4));
    ASSERT_EQ(depth.size(), std::size_t(kSize * kSize));

    // The camera looks into the box: the left wall (red) is at the image's
    // left edge, the right wall (green) at its right, mid-height. Their
    // normals face into the box (+X and -X in the Cornell data).
    const glm::vec4 left = texel(normals, 3, kSize / 2), right = texel(normals, kSize - 4, kSize / 2);
    const glm::vec4 leftAlbedo = texel(albedo, 3, kSize / 2), rightAlbedo = texel(albedo, kSize - 4, kSize / 2);
    EXPECT_EQ(left.w, 1.0f);
    EXPECT_GT(std::abs(left.x), 0.95f) << "left wall normal " << left.x << " " << left.y << " " << left.z;
    EXPECT_GT(std::abs(right.x), 0.95f) << "right wall normal " << right.x << " " << right.y << " " << right.z;
    EXPECT_LT(left.x * right.x, 0.0f) << "the side walls face each other";
    // Red wall: red dominates; green wall: green dominates (whichever side each is on).
    const glm::vec4 red = leftAlbedo.r > rightAlbedo.r ? leftAlbedo : rightAlbedo;
    const glm::vec4 green = leftAlbedo.r > rightAlbedo.r ? rightAlbedo : leftAlbedo;
    EXPECT_GT(red.r, 2.0f * red.g) << red.r << " " << red.g;
    EXPECT_GT(green.g, 2.0f * green.r) << green.r << " " << green.g;

    // Depth: every pixel inside the box is geometry (< 1); the floor's normal points up.
    const float centreDepth = depth[std::size_t(kSize / 2) * kSize + kSize / 2];
    EXPECT_GT(centreDepth, 0.0f);
    EXPECT_LT(centreDepth, 1.0f);
    // Bottom centre: the floor in front of the two blocks.
    const glm::vec4 floor = texel(normals, kSize / 2, kSize - 4);
    EXPECT_GT(floor.y, 0.95f) << "floor normal y " << floor.y << " w " << floor.w;
}

TEST_F(GBuffer, BackgroundHasNoSurface) {
    scene::Project project = scene::makeCornellBoxProject();
    scene::Camera cam = project.scene.cameras.front();
    // Turn the camera around: it sees only the open side's outside (empty space).
    cam.target = cam.position + (cam.position - cam.target);
    auto r = renderer::ForwardRenderer::create();
    ASSERT_TRUE(r.has_value());
    r->setScene(project.scene);
    ASSERT_TRUE(r->render(project.scene, project.parameters, cam, kSize, kSize).has_value());
    const auto normals = r->readGBufferNormal();
    const auto depth = r->readDepth();
    EXPECT_EQ(texel(normals, kSize / 2, kSize / 2).w, 0.0f);
    EXPECT_EQ(depth[std::size_t(kSize / 2) * kSize + kSize / 2], 1.0f);
    const auto stats = r->cameraDrawStats();
    EXPECT_GT(stats.total, 0u);
    EXPECT_EQ(stats.culled, stats.total) << "looking away from the box, frustum culling drops every item";
}
