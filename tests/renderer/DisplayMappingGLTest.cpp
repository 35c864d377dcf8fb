// tonemap.frag against its CPU twin (DisplayMapping.h), every operator, on a
// Cornell box exposed into the shoulder: the editor's reference views and the
// sweeps' images go through the CPU twin and must show what the frame shows.
#include "GlFixture.h"

#include "lpv/renderer/DisplayMapping.h"
#include "lpv/renderer/ForwardRenderer.h"
#include "lpv/scene/CornellBox.h"

#include <algorithm>
#include <cstdlib>
#include <string>

using namespace lpv;

class DisplayMappingGL : public GlTest {};

TEST_F(DisplayMappingGL, TonemapShaderMatchesTheCpuDisplayMappingForEveryOperator) {
    constexpr int kWidth = 96, kHeight = 72;
    auto r = renderer::ForwardRenderer::create();
    ASSERT_TRUE(r.has_value()) << r.error().describe();
    scene::Project project = scene::makeCornellBoxProject();
    scene::ParameterSet params = project.parameters;
    // Two stops over the meter: the lit walls and the lamp run through every shoulder.
    ASSERT_TRUE(params.set("output.exposure", 2.0).has_value());
    for (const char* op : {"aces", "reinhard", "uncharted2", "linear", "neutral"}) {
        SCOPED_TRACE(op);
        ASSERT_TRUE(params.set("output.tonemapper", std::string(op)).has_value());
        auto ok = r->render(project.scene, params, project.scene.cameras.front(), kWidth, kHeight);
        ASSERT_TRUE(ok.has_value()) << ok.error().describe();
        const std::vector<float> hdr = r->readHdr();
        std::vector<glm::vec3> rgb(hdr.size() / 4);
        for (std::size_t i = 0; i < rgb.size(); ++i)
            rgb[i] = {hdr[i * 4], hdr[i * 4 + 1], hdr[i * 4 + 2]};
        const renderer::DisplayMapping mapping{r->displayExposure(params), renderer::tonemapperOf(op)};
        const scene::Image8 cpu = renderer::tonemapImage(rgb, kWidth, kHeight, mapping);
        const std::vector<std::uint8_t> gpu = r->readDisplay();
        ASSERT_EQ(gpu.size(), cpu.pixels.size());
        int worst = 0, shoulder = 0;
        for (std::size_t i = 0; i < gpu.size(); i += 4)
            for (std::size_t c = 0; c < 3; ++c) {
                worst = std::max(worst, std::abs(int(gpu[i + c]) - int(cpu.pixels[i + c])));
                shoulder += cpu.pixels[i + c] > 200;
            }
        // One code: float rounding of the GPU's pow and of the exposure read back.
        EXPECT_LE(worst, 1);
        EXPECT_GT(shoulder, 0) << "the frame must reach the shoulder for this test to see it";
    }
}
