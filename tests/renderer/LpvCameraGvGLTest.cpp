// The geometry volume's camera surfels (lpv_gv_inject.comp, GV_FROM_CAMERA)
// against their CPU twin, lpvref::cameraSurfels + injectSurfels, at
// lpv.gvCameraStride 1, 2 and 3 (issue #25: one surfel per stride^2 pixels
// with the block's area, for fewer atomics). A hand-made G-buffer: a camera
// looking at a wall and a floor, depth and normals computed here, so the GPU
// and the CPU read the same numbers.
#include "GlFixture.h"
#include "LpvPassFixture.h"

#include "passes/lpv/LpvPass.h"
#include "lpv/renderer/GpuTimer.h"
#include "lpv/renderer/lpv/LpvReference.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <iostream>

using namespace lpv::renderer;
namespace ref = lpv::renderer::lpvref;

namespace {

constexpr int kWidth = 64, kHeight = 48;

// The camera at (2, 1.5, -1) looking along +z at a wall z = 2.5 (facing -z)
// above a floor y = 0.25 (facing +y); the top rows see nothing (w = 0).
ref::CameraGBuffer makeGBuffer() {
    ref::CameraGBuffer g;
    g.width = kWidth;
    g.height = kHeight;
    g.position = glm::vec3(2.0f, 1.5f, -1.0f);
    const float fovY = glm::radians(60.0f);
    const glm::mat4 view = glm::lookAt(g.position, g.position + glm::vec3(0, 0, 1), glm::vec3(0, 1, 0));
    const glm::mat4 proj = glm::perspective(fovY, float(kWidth) / float(kHeight), 0.1f, 50.0f);
    const glm::mat4 viewProj = proj * view;
    g.inverseViewProj = glm::inverse(viewProj);
    g.pixelAngle = 2.0f * std::tan(0.5f * fovY) / float(kHeight);
    g.depth.assign(std::size_t(kWidth * kHeight), 1.0f);
    g.normal.assign(std::size_t(kWidth * kHeight), glm::vec4(0.0f));
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const std::size_t i = std::size_t(x + kWidth * y);
            if (y >= kHeight - 6)
                continue; // sky
            const glm::vec2 ndc = (glm::vec2(float(x), float(y)) + 0.5f) / glm::vec2(kWidth, kHeight) * 2.0f - 1.0f;
            const glm::vec4 far = g.inverseViewProj * glm::vec4(ndc, 1.0f, 1.0f);
            const glm::vec3 ray = glm::normalize(glm::vec3(far) / far.w - g.position);
            const float toWall = (2.5f - g.position.z) / ray.z;
            const float toFloor = ray.y < 0.0f ? (0.25f - g.position.y) / ray.y : 1e9f;
            const bool floor = toFloor < toWall;
            const glm::vec3 p = g.position + ray * (floor ? toFloor : toWall);
            const glm::vec4 clip = viewProj * glm::vec4(p, 1.0f);
            g.depth[i] = 0.5f * (clip.z / clip.w) + 0.5f;
            g.normal[i] = glm::vec4(floor ? glm::vec3(0, 1, 0) : glm::vec3(0, 0, -1), 1.0f);
        }
    return g;
}

double dcSum(const std::vector<glm::vec4>& potential) {
    double sum = 0.0;
    for (const glm::vec4& v : potential)
        sum += double(v.x);
    return sum;
}

class LpvCameraGvGLTest : public GlTest {};

} // namespace

TEST_F(LpvCameraGvGLTest, CameraSurfelsMatchTheCpuTwinAtEveryStride) {
    const ref::CameraGBuffer g = makeGBuffer();
    Texture depth = createTexture(GL_TEXTURE_2D), normal = createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(depth.id(), 1, GL_DEPTH_COMPONENT32F, kWidth, kHeight);
    glTextureSubImage2D(depth.id(), 0, 0, 0, kWidth, kHeight, GL_DEPTH_COMPONENT, GL_FLOAT, g.depth.data());
    glTextureStorage2D(normal.id(), 1, GL_RGBA16F, kWidth, kHeight); // as the G-buffer; +-1 and 0 are exact in half
    glTextureSubImage2D(normal.id(), 0, 0, 0, kWidth, kHeight, GL_RGBA, GL_FLOAT, g.normal.data());

    auto pass = LpvPass::create();
    ASSERT_TRUE(pass.has_value()) << pass.error().describe();
    // The LPV needs an RSM tile to run: one texel far outside the grid, which neither injects nor blocks.
    const FakeRsm rsm(2, {{Texel{glm::vec3(1000.0f), glm::vec3(0, 1, 0), glm::vec3(0.0f)}}});
    const ref::GridFrame grid{glm::vec3(0.0f), 0.25f, 16};
    GpuTimer timer;
    double total[4] = {0.0, 0.0, 0.0, 0.0};
    for (int stride : {1, 2, 3}) {
        LpvSettings settings;
        settings.gridSize = grid.n;
        settings.propagationSteps = 0;
        settings.occlusion = true;
        settings.gvFromCamera = true;
        settings.gvCameraStride = stride;
        const LpvRsmInput input = rsmInputOf(rsm, {LpvCascade{grid.origin, grid.cellSize, grid.n}}, {0.01f});
        LpvCameraInput camera;
        camera.depth = depth.id();
        camera.normal = normal.id();
        camera.inverseViewProj = g.inverseViewProj;
        camera.position = g.position;
        camera.pixelAngle = g.pixelAngle;
        timer.beginFrame();
        auto ok = pass->run(settings, input, &camera, timer);
        ASSERT_TRUE(ok.has_value()) << ok.error().describe();
        ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
        const std::vector<glm::vec4> gpu = pass->readGeometryVolume(0);

        const std::vector<ref::Surfel> surfels = ref::cameraSurfels(g, stride);
        const ref::GvGrid expected = ref::mergeByMax(ref::GvGrid(grid.n), ref::injectSurfels(grid, surfels));
        ASSERT_EQ(gpu.size(), expected.potential.size());
        float worst = 0.0f, peak = 0.0f;
        for (std::size_t i = 0; i < gpu.size(); ++i)
            for (int j = 0; j < 4; ++j) {
                worst = std::max(worst, std::abs(gpu[i][j] - expected.potential[i][j]));
                peak = std::max(peak, std::abs(expected.potential[i][j]));
            }
        total[stride] = dcSum(expected.potential);
        std::cout << "[ figures ] camera GV, stride " << stride << ": " << surfels.size()
                  << " surfels, max |GPU - CPU| / peak = " << worst / peak << ", total DC " << total[stride] << "\n";
        EXPECT_GT(peak, 0.5f) << "the wall and floor must reach the grid";
        // Fixed point 2^-16 per coefficient and surfel, up to ~100 surfels per GV cell.
        EXPECT_LT(worst / peak, 1e-3f) << "stride " << stride;
    }
    // Fewer, larger surfels keep the coverage while min(A / s^2, 1) clamps none
    // of them: stride 2 keeps 94% of stride 1's total DC here. At stride 3 a
    // grazing floor surfel covers more than a cell face and is clamped (and the
    // image's last partial column of blocks has no middle pixel): 66%.
    EXPECT_NEAR(total[2] / total[1], 1.0, 0.1);
    EXPECT_LT(total[3], total[2]);
    EXPECT_NE(total[2], total[1]) << "the stride must change the surfels, or this tests nothing";
}
