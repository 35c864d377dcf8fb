// The default Cornell box shows indirect light (issue #22): its ceiling lamp
// is injected on auto, so surfaces the lamp does not reach directly (the
// ceiling, the blocks' faces turned away from it) are lit by the LPV, and
// gi.method = off turns every indirect pass off and frees it.
#include "GlFixture.h"

#include "lpv/renderer/ForwardRenderer.h"
#include "lpv/scene/CornellBox.h"

#include <cmath>
#include <iostream>

using namespace lpv;

namespace {

constexpr int kSize = 160;

struct Frame {
    std::vector<float> hdr;
    std::string note;
    std::size_t localRsmImages = 0;
};

class DefaultGi : public GlTest {
protected:
    Frame render(const std::string& method) {
        scene::ParameterSet params = project.parameters; // the template's own values, defaults elsewhere
        EXPECT_TRUE(params.setFromText("gi.method", method, "test").has_value());
        auto r = renderer::ForwardRenderer::create();
        EXPECT_TRUE(r.has_value());
        if (!r)
            return {};
        r->setScene(project.scene);
        for (int i = 0; i < 2; ++i) { // the second frame's geometry volume sees the first's G-buffer
            auto ok = r->render(project.scene, params, camera(), kSize, kSize);
            EXPECT_TRUE(ok.has_value()) << (ok ? "" : ok.error().describe());
        }
        return {r->readHdr(), r->lpvNote(), r->debugImages("localRsm").size()};
    }
    const scene::Camera& camera() const { return project.scene.cameras.front(); }

    // Mean HDR radiance over a 5x5 window around a world point (rows top to bottom).
    glm::vec3 at(const Frame& f, const glm::vec3& world) const {
        const glm::vec4 clip = camera().projection(1.0f) * camera().view() * glm::vec4(world, 1.0f);
        const glm::vec2 ndc = glm::vec2(clip) / clip.w;
        const int px = int((ndc.x * 0.5f + 0.5f) * kSize), py = int((0.5f - 0.5f * ndc.y) * kSize);
        glm::vec3 sum(0.0f);
        int n = 0;
        for (int y = py - 2; y <= py + 2; ++y)
            for (int x = px - 2; x <= px + 2; ++x)
                if (x >= 0 && y >= 0 && x < kSize && y < kSize) {
                    const std::size_t i = (std::size_t(y) * kSize + std::size_t(x)) * 4;
                    sum += glm::vec3(f.hdr[i], f.hdr[i + 1], f.hdr[i + 2]);
                    ++n;
                }
        return n ? sum / float(n) : glm::vec3(0.0f);
    }

    scene::Project project = scene::makeCornellBoxProject();
};

float sum(const glm::vec3& v) { return v.r + v.g + v.b; }

// Points the lamp does not light directly, each a little in front of its surface.
const glm::vec3 kCeiling{1.2f, 5.47f, 3.8f};
// The short block's face toward the camera (normal about (0.29, 0, -0.96)) faces away from the lamp.
const glm::vec3 kShortBlockFront{2.103f, 0.8f, 0.885f};
// The tall block's face toward the red wall (normal about (0.95, 0, -0.30)), turned away from the lamp.
const glm::vec3 kTallBlockTowardRed{4.485f, 1.0f, 3.262f};

} // namespace

TEST_F(DefaultGi, TheDefaultCornellBoxShowsIndirectLight) {
    const Frame lpv = render("lpv"), off = render("off");
    for (const auto& [name, p] : {std::pair{"ceiling", kCeiling}, std::pair{"short block's front", kShortBlockFront},
                                  std::pair{"tall block's side toward red", kTallBlockTowardRed}}) {
        const float on = sum(at(lpv, p)), without = sum(at(off, p));
        std::cout << name << ": " << on << " with the LPV, " << without << " without\n";
        EXPECT_GT(on, 0.002f) << name << " gets no indirect light";
        EXPECT_GT(on, 10.0f * without) << name;
    }
    EXPECT_EQ(lpv.note.find("LPV: off"), std::string::npos) << lpv.note;
}

TEST_F(DefaultGi, RedDominatesTheTallBlocksFaceTowardTheRedWall) {
    const glm::vec3 c = at(render("lpv"), kTallBlockTowardRed);
    std::cout << "tall block toward red: " << c.r << " " << c.g << " " << c.b << "\n";
    EXPECT_GT(c.r, 1.2f * c.g);
    EXPECT_GT(c.r, 1.2f * c.b);
}

TEST_F(DefaultGi, GiOffRunsAndHoldsNoIndirectPass) {
    const Frame lpv = render("lpv"), off = render("off");
    EXPECT_GT(lpv.localRsmImages, 0u) << "the lamp's RSM runs on auto";
    EXPECT_EQ(off.localRsmImages, 0u);
    EXPECT_NE(off.note.find("gi.method is off"), std::string::npos) << off.note;
}

// No double counting (issue #22): the lamp is an area light and an emissive quad in its
// outline; on the defaults (lpv.emissive = auto) its indirect light equals the area light's alone.
TEST_F(DefaultGi, TheLampCountsOnceThoughItIsAnAreaLightAndAnEmissiveQuad) {
    ASSERT_TRUE(project.parameters.setFromText("output.view", "indirect", "test").has_value());
    const Frame both = render("lpv");
    for (scene::Material& m : project.scene.materials)
        m.emissive = glm::vec3(0.0f); // the quad no longer emits: the area light alone
    const Frame alone = render("lpv");
    ASSERT_EQ(both.hdr.size(), alone.hdr.size());
    double sumBoth = 0.0, sumAlone = 0.0;
    for (std::size_t i = 0; i < both.hdr.size(); i += 4) {
        sumBoth += both.hdr[i] + both.hdr[i + 1] + both.hdr[i + 2];
        sumAlone += alone.hdr[i] + alone.hdr[i + 1] + alone.hdr[i + 2];
    }
    EXPECT_GT(sumAlone, 0.0);
    EXPECT_NEAR(sumBoth / sumAlone, 1.0, 1e-6) << "the quad's light would otherwise be added again";
    EXPECT_EQ(both.note.find("emissive VPLs"), std::string::npos) << both.note;
}
