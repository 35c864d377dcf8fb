// Sun rays (issue #6, item 6): they appear when the sun is on screen, the pass
// does not run when it is not, and a forced "off" wins.
#include "GlFixture.h"

#include "lpv/renderer/ForwardRenderer.h"
#include "lpv/scene/Primitives.h"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>

using namespace lpv;

namespace {

constexpr int kW = 160, kH = 90;

// Open ground with a row of pillars between the camera and a low sun: the
// pillars cut the sky into gaps through which shafts fall.
scene::Scene pillarsAgainstTheSun() {
    scene::Scene s;
    s.meshes.push_back(scene::makePlane(1));
    s.meshes.push_back(scene::makeBox());
    s.materials.emplace_back();
    scene::Object ground;
    ground.mesh = 0;
    ground.transform.scale = glm::vec3(200.0f);
    s.objects.push_back(ground);
    for (int i = -4; i <= 4; ++i) {
        scene::Object pillar;
        pillar.mesh = 1;
        pillar.transform.translation = {float(i) * 3.0f, 4.0f, -20.0f};
        pillar.transform.scale = {1.0f, 8.0f, 1.0f};
        s.objects.push_back(pillar);
    }
    scene::Light sun;
    sun.direction = glm::normalize(glm::vec3(0.0f, -0.25f, 1.0f)); // low, from -Z towards +Z
    sun.intensity = 3.0f;
    s.lights.push_back(sun);
    s.sky.intensity = 0.3f;
    return s;
}

scene::Camera lookingAt(const glm::vec3& direction) {
    scene::Camera c;
    c.position = {0.0f, 2.0f, 0.0f};
    c.target = c.position + direction;
    c.fovY = glm::radians(60.0f);
    return c;
}

struct Frame {
    double meanHdr = 0.0;
    bool ran = false;
    std::string reason;
    bool timed = false;
};

class SunRaysGLTest : public GlTest {
protected:
    Frame render(const scene::Camera& camera, const std::string& setting) {
        auto r = renderer::ForwardRenderer::create();
        EXPECT_TRUE(r) << r.error().describe();
        const scene::Scene s = pillarsAgainstTheSun();
        scene::ParameterSet params;
        EXPECT_TRUE(params.setFromText("effects.sunRays", setting));
        EXPECT_TRUE(params.setFromText("lpv.intensity", "0")); // only direct light and the rays
        auto ok = r->render(s, params, camera, kW, kH);
        EXPECT_TRUE(ok) << ok.error().describe();
        Frame f;
        const std::vector<float> hdr = r->readHdr();
        for (std::size_t i = 0; i < hdr.size(); i += 4)
            f.meanHdr += (hdr[i] + hdr[i + 1] + hdr[i + 2]) / 3.0;
        f.meanHdr /= double(hdr.size() / 4);
        // The decisions of the frame end with the sun rays'.
        EXPECT_EQ(r->frameEffects().back().effect, "Sun rays");
        f.ran = r->frameEffects().back().runs();
        f.reason = r->frameEffects().back().reason;
        r->timer().resolveAll();
        const auto table = r->timer().table();
        f.timed = std::any_of(table.begin(), table.end(), [](const auto& t) { return t.pass == "sunRays"; });
        return f;
    }
};

} // namespace

TEST_F(SunRaysGLTest, RaysAppearWhenTheSunIsOnScreen) {
    const scene::Camera towardSun = lookingAt({0.0f, 0.2f, -1.0f});
    const Frame with = render(towardSun, "auto");
    const Frame without = render(towardSun, "off");
    EXPECT_TRUE(with.ran) << with.reason;
    EXPECT_TRUE(with.timed);
    EXPECT_NE(with.reason.find("on screen"), std::string::npos) << with.reason;
    EXPECT_FALSE(without.ran);
    EXPECT_NE(without.reason.find("forced off"), std::string::npos) << without.reason;
    EXPECT_FALSE(without.timed);
    // The shafts add light: a clearly brighter image, not a rounding difference.
    EXPECT_GT(with.meanHdr, without.meanHdr * 1.05) << with.meanHdr << " vs " << without.meanHdr;
}

TEST_F(SunRaysGLTest, PassDoesNotRunWhenTheSunIsBehindTheCamera) {
    const Frame away = render(lookingAt({0.0f, 0.0f, 1.0f}), "auto");
    EXPECT_FALSE(away.ran);
    EXPECT_FALSE(away.timed) << "the pass must not run at all";
    EXPECT_NE(away.reason.find("not on screen"), std::string::npos) << away.reason;
    // Forced on, it runs even then (for comparisons), and says why.
    const Frame forced = render(lookingAt({0.0f, 0.0f, 1.0f}), "on");
    EXPECT_TRUE(forced.ran);
    EXPECT_NE(forced.reason.find("forced on"), std::string::npos);
}
