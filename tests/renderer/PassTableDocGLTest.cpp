// docs/renderer.md's pass table is generated from the passes' declarations
// (issue #44): the reads and writes of a frame of imported Sponza with every
// effect on and the depth pre-pass, as formatGraphMarkdown writes them.
// When a pass's declaration changes, regenerate the table in the same commit:
//   LPV_UPDATE_DOCS=1 build/tests/renderer/renderer_golden_gl_tests --gtest_filter='PassTableDoc*'
#include "GlFixture.h"
#include "OpeningViews.h"

#include "lpv/renderer/ForwardRenderer.h"
#include "lpv/renderer/FrameGraphReport.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

using namespace lpv;

namespace {

constexpr const char* kBegin = "<!-- pass table: generated from the passes' declarations (PassTableDocGLTest) -->\n";
constexpr const char* kEnd = "<!-- end of the generated pass table -->\n";

std::filesystem::path doc() { return std::filesystem::path(test::kSourceDir) / "docs/renderer.md"; }

std::string readAll(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

class PassTableDoc : public GlTest {};

} // namespace

TEST_F(PassTableDoc, RendererDocTableIsTheGeneratedOne) {
    test::OpeningView view = test::importedScene("sponza/sponza.obj");
    ASSERT_FALSE(view.project.scene.objects.empty());
    for (const auto& [key, value] : {std::pair{"effects.glossyReflections", "on"}, std::pair{"effects.sunRays", "on"},
                                     std::pair{"effects.subsurface", "on"}, std::pair{"lpv.bounces", "2"},
                                     std::pair{"lpv.directedPropagation", "on"}, std::pair{"effects.skyInjection", "on"},
                                     std::pair{"output.depthPrepass", "true"}})
        ASSERT_TRUE(view.project.parameters.setFromText(key, value).has_value()) << key;
    auto r = renderer::ForwardRenderer::create();
    ASSERT_TRUE(r.has_value()) << r.error().describe();
    // Two frames: the second is the one whose geometry volume reads the first's G-buffer.
    for (int frame = 0; frame < 2; ++frame)
        ASSERT_TRUE(r->render(view.project.scene, view.project.parameters, view.camera, 64, 36).has_value());
    const std::string generated = renderer::formatGraphMarkdown(r->graphReport());

    std::string text = readAll(doc());
    const std::size_t begin = text.find(kBegin), end = text.find(kEnd);
    ASSERT_NE(begin, std::string::npos) << doc() << " has no line " << kBegin;
    ASSERT_NE(end, std::string::npos) << doc() << " has no line " << kEnd;
    const std::size_t tableStart = begin + std::string(kBegin).size();
    const std::string documented = text.substr(tableStart, end - tableStart);
    if (const char* update = std::getenv("LPV_UPDATE_DOCS"); update && std::string(update) == "1") {
        text.replace(tableStart, end - tableStart, generated);
        std::ofstream(doc(), std::ios::binary) << text;
        return;
    }
    EXPECT_EQ(documented, generated) << "docs/renderer.md's pass table is not what the passes declare. Regenerate it "
                                        "in the same commit as the declaration: LPV_UPDATE_DOCS=1 "
                                        "build/tests/renderer/renderer_golden_gl_tests --gtest_filter='PassTableDoc*'";
}
