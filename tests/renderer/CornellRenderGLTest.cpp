#include "GlFixture.h"

#include "lpv/renderer/ForwardRenderer.h"
#include "lpv/scene/CornellBox.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

using namespace lpv;

namespace {

constexpr int kSize = 256;

struct Hdr {
    std::vector<float> px;
    glm::vec3 at(int x, int y) const {
        const std::size_t i = (std::size_t(y) * kSize + std::size_t(x)) * 4;
        return {px[i], px[i + 1], px[i + 2]};
    }
};

// Projects a world point with the camera and returns its pixel (rows top to bottom).
glm::ivec2 pixelOf(const scene::Camera& cam, const glm::vec3& world) {
    const glm::vec4 clip = cam.projection(1.0f) * cam.view() * glm::vec4(world, 1.0f);
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return {int((ndc.x * 0.5f + 0.5f) * kSize), int((1.0f - (ndc.y * 0.5f + 0.5f)) * kSize)};
}

// Mean HDR radiance over a small window around a world point.
glm::vec3 sampleAround(const Hdr& hdr, const scene::Camera& cam, const glm::vec3& world) {
    const glm::ivec2 p = pixelOf(cam, world);
    glm::vec3 sum(0.0f);
    int n = 0;
    for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) {
            const int x = p.x + dx, y = p.y + dy;
            if (x < 0 || y < 0 || x >= kSize || y >= kSize)
                continue;
            sum += hdr.at(x, y);
            ++n;
        }
    return n ? sum / float(n) : glm::vec3(0.0f);
}

class CornellRender : public GlTest {
protected:
    Hdr renderCornell(const scene::ParameterSet& params) {
        auto r = renderer::ForwardRenderer::create();
        EXPECT_TRUE(r.has_value()) << (r ? "" : r.error().describe());
        if (!r)
            return {};
        r->setScene(project.scene);
        auto ok = r->render(project.scene, params, camera(), kSize, kSize);
        EXPECT_TRUE(ok.has_value()) << (ok ? "" : ok.error().describe());
        return Hdr{r->readHdr()};
    }
    const scene::Camera& camera() const { return project.scene.cameras.front(); }

    scene::Project project = scene::makeCornellBoxProject();
};

} // namespace

TEST_F(CornellRender, HdrBufferHasNoNaNOrInf) {
    const Hdr hdr = renderCornell(project.parameters);
    ASSERT_EQ(hdr.px.size(), std::size_t(kSize) * kSize * 4);
    for (float v : hdr.px)
        ASSERT_TRUE(std::isfinite(v));
}

TEST_F(CornellRender, LeftWallIsRedAndRightWallIsGreen) {
    const Hdr hdr = renderCornell(project.parameters);
    // Points on each wall above the tall block (so outside its shadow), half way back.
    const glm::vec3 red = sampleAround(hdr, camera(), {5.50f, 3.5f, 3.0f});
    const glm::vec3 green = sampleAround(hdr, camera(), {0.02f, 3.5f, 3.0f});
    EXPECT_GT(red.r, 0.01f) << "left wall must receive direct light";
    EXPECT_GT(red.r, 3.0f * red.g);
    EXPECT_GT(red.r, 3.0f * red.b);
    EXPECT_GT(green.g, 0.01f);
    EXPECT_GT(green.g, 2.0f * green.r);
    EXPECT_GT(green.g, 2.0f * green.b);
    // And the image is not mirrored: red is on the left half.
    EXPECT_LT(pixelOf(camera(), {5.50f, 3.5f, 3.0f}).x, kSize / 2);
}

TEST_F(CornellRender, FloorUnderLightIsBrighterThanFloorInBlockShadow) {
    const Hdr hdr = renderCornell(project.parameters);
    // Floor left of the short block, in the open, vs. floor left of the tall
    // block where the line to the light passes through the tall block's centre.
    // Both are visible from the camera and about as far from the light.
    const glm::vec3 lit = sampleAround(hdr, camera(), {3.5f, 0.001f, 1.5f});
    const glm::vec3 shadowed = sampleAround(hdr, camera(), {5.2f, 0.001f, 4.2f});
    const float litLum = glm::dot(lit, glm::vec3(0.2126f, 0.7152f, 0.0722f));
    const float shadowLum = glm::dot(shadowed, glm::vec3(0.2126f, 0.7152f, 0.0722f));
    EXPECT_GT(litLum, 0.0f);
    EXPECT_GT(litLum, 4.0f * shadowLum) << "lit " << litLum << " shadowed " << shadowLum;
}

TEST_F(CornellRender, ShadowComesFromTheShadowMapNotFromDistance) {
    // Without the blocks' occlusion the same floor point is lit: proves the
    // darkness above is a shadow and not just fall-off.
    project.scene.lights[0].castShadows = false;
    const Hdr hdr = renderCornell(project.parameters);
    const glm::vec3 p = sampleAround(hdr, camera(), {5.2f, 0.001f, 4.2f});
    const glm::vec3 lit = sampleAround(hdr, camera(), {3.5f, 0.001f, 1.5f});
    EXPECT_GT(glm::dot(p, glm::vec3(1.0f)), 0.25f * glm::dot(lit, glm::vec3(1.0f)));
}

TEST_F(CornellRender, ExposureScalesDisplayMonotonically) {
    auto r = renderer::ForwardRenderer::create();
    ASSERT_TRUE(r.has_value());
    r->setScene(project.scene);
    scene::ParameterSet dark = project.parameters, bright = project.parameters;
    ASSERT_TRUE(dark.set("output.exposure", -2.0).has_value());
    ASSERT_TRUE(bright.set("output.exposure", 2.0).has_value());
    auto sum = [&](const scene::ParameterSet& p) {
        EXPECT_TRUE(r->render(project.scene, p, camera(), kSize, kSize).has_value());
        double total = 0.0;
        for (std::uint8_t v : r->readDisplay())
            total += v;
        return total;
    };
    EXPECT_LT(sum(dark), sum(bright));
}

TEST_F(CornellRender, TooLargeShadowMapIsAnErrorNotACrash) {
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    if (maxSize >= 8192)
        GTEST_SKIP() << "GL_MAX_TEXTURE_SIZE " << maxSize << " allows the registry's largest shadow map";
    scene::ParameterSet p = project.parameters;
    ASSERT_TRUE(p.set("shadow.mapSize", 8192).has_value());
    auto r = renderer::ForwardRenderer::create();
    ASSERT_TRUE(r.has_value());
    auto ok = r->render(project.scene, p, camera(), 64, 64);
    ASSERT_FALSE(ok.has_value());
    EXPECT_NE(ok.error().location.find("shadow.mapSize"), std::string::npos);
}

// The editor's view changes size between frames (a dock opens): the geometry
// volume read last frame's camera G-buffer, whose textures the new size had
// already replaced, a GL error on the first frame after every resize.
TEST_F(CornellRender, AFrameAfterAResizeRendersWithoutAnError) {
    auto r = renderer::ForwardRenderer::create();
    ASSERT_TRUE(r.has_value()) << r.error().describe();
    r->setScene(project.scene);
    const scene::ParameterSet params = project.parameters;
    ASSERT_TRUE(params.getBool("lpv.gvFromCamera")) << "the default reads the camera G-buffer";
    for (const auto& [w, h] : {std::pair{64, 64}, std::pair{64, 64}, std::pair{96, 48}, std::pair{40, 72}}) {
        auto ok = r->render(project.scene, params, camera(), w, h);
        EXPECT_TRUE(ok.has_value()) << w << "x" << h << ": " << (ok ? "" : ok.error().describe());
    }
}
