// The bench pack (issue #45) renders bit for bit what its project renders:
// Sponza imported by the real `lpv import`, packed by the real `lpv bench
// pack`, then one renderer fed the project (textures decoded by
// lpv_importers, as `lpv render` does) and one fed the pack, at a small size
// on llvmpipe; the HDR and display read-backs must be identical.
#include "RunLpv.h"

#include "lpv/importers/SceneTextures.h"
#include "lpv/renderer/ForwardRenderer.h"
#include "lpv/renderer/GlContext.h"
#include "lpv/scene/BenchPack.h"
#include "lpv/scene/FramingCamera.h"
#include "lpv/scene/Project.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <fstream>

using namespace lpv;
using namespace lpv::test;
namespace fs = std::filesystem;

namespace {

constexpr int kWidth = 96;
constexpr int kHeight = 54;

struct Frame {
    std::vector<float> hdr;
    std::vector<std::uint8_t> display;
};

// Two frames (the second reads the first's geometry volume), from the camera `lpv render`
// takes for a project without cameras (an import has none): the framing camera.
Frame renderTwice(const scene::Project& project, const scene::TextureImages& textures) {
    auto renderer = renderer::ForwardRenderer::create();
    EXPECT_TRUE(renderer) << renderer.error().describe();
    if (!renderer)
        return {};
    renderer->setScene(project.scene, textures);
    for (int i = 0; i < 2; ++i) {
        auto ok = renderer->render(project.scene, project.parameters, scene::framingCamera(project.scene), kWidth, kHeight);
        EXPECT_TRUE(ok) << ok.error().describe();
    }
    return {renderer->readHdr(), renderer->readDisplay()};
}

} // namespace

TEST(BenchPackRender, APackRendersBitForBitWhatItsProjectRenders) {
    const fs::path dir = freshBuildDir("cli", "BenchPackRender");
    const fs::path project = dir / "sponza.lpvproj", pack = dir / "sponza.lpvpack";
    const RunResult imported =
        runLpv("import " + quoted(fs::path(kSharedScenesDir) / "sponza/sponza.obj") + " -o " + quoted(project));
    ASSERT_EQ(imported.exitCode, 0) << imported.output;
    const RunResult packed = runLpv("bench pack " + quoted(project) + " -o " + quoted(pack));
    ASSERT_EQ(packed.exitCode, 0) << packed.output;
    EXPECT_TRUE(contains(packed.output, "textures")) << packed.output;

    auto context = renderer::HeadlessContext::create();
    ASSERT_TRUE(context) << context.error().describe();

    auto fromProject = scene::loadProject(project);
    ASSERT_TRUE(fromProject) << fromProject.error().describe();
    const auto textures = importers::loadSceneTextures(fromProject->scene, dir);
    EXPECT_TRUE(textures.warnings.empty());
    ASSERT_GT(textures.images.size(), 10u); // Sponza's maps and the normals made from its bump maps
    const Frame a = renderTwice(*fromProject, textures.images);

    auto fromPack = scene::loadBenchPack(pack);
    ASSERT_TRUE(fromPack) << fromPack.error().describe();
    EXPECT_EQ(fromPack->textures.size(), textures.images.size());
    const Frame b = renderTwice(fromPack->project, fromPack->textures);

    ASSERT_EQ(a.hdr.size(), std::size_t(kWidth) * kHeight * 4);
    ASSERT_EQ(a.display.size(), b.display.size());
    // Something is lit, so equal images mean something.
    EXPECT_GT(*std::max_element(a.display.begin(), a.display.end()), 100);
    ASSERT_EQ(a.hdr.size(), b.hdr.size());
    EXPECT_EQ(std::memcmp(a.hdr.data(), b.hdr.data(), a.hdr.size() * sizeof(float)), 0);
    EXPECT_TRUE(a.display == b.display);
}

TEST(BenchPackRender, TheCommandRefusesABadPackWithItsReason) {
    const fs::path dir = freshBuildDir("cli", "BenchPackBad");
    const RunResult packed = runLpv("bench pack " + quoted(fs::path(cornellProject())) + " -o " + quoted(dir / "c.lpvpack"));
    ASSERT_EQ(packed.exitCode, 0) << packed.output;
    std::string bytes = readText(dir / "c.lpvpack");
    bytes.resize(bytes.size() - 7);
    {
        std::ofstream out(dir / "cut.lpvpack", std::ios::binary);
        out << bytes;
    }
    const RunResult cut = runLpv("render " + quoted(dir / "cut.lpvpack") + " -o " + quoted(dir / "x.png"));
    EXPECT_EQ(cut.exitCode, 1) << cut.output;
    EXPECT_TRUE(contains(cut.output, "cut.lpvpack")) << cut.output;
    EXPECT_TRUE(contains(cut.output, "cut off")) << cut.output;
    const RunResult wrongName = runLpv("bench pack " + quoted(fs::path(cornellProject())) + " -o " + quoted(dir / "c.bin"));
    EXPECT_EQ(wrongName.exitCode, 2) << wrongName.output;
}
