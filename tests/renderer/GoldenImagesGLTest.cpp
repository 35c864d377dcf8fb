// Issue #44: restructuring the renderer must not move a pixel. The three
// scenes (the Cornell template, Sponza and Sibenik as `lpv import` makes
// them) are rendered as `lpv render --width 320 --height 180 --frames 2`
// renders them, in settings that between them run every pass family, and
// the pixels' hashes are compared with golden/hashes.txt. Baked radiosity
// needs a solved project, which the template does not carry: its pass is
// guarded by RadiosityIndirectGLTest and the golden script's radiosity image.
//
// Hashes are exact, so they hold only on the GL renderer that made them
// (the file's first line); on another the test skips and says so.
// A deliberate image change regenerates the file in the same commit:
//   LPV_GOLDEN_REGENERATE=1 build/tests/renderer/renderer_golden_gl_tests
#include "GlFixture.h"
#include "OpeningViews.h"

#include "lpv/importers/SceneTextures.h"
#include "lpv/renderer/ForwardRenderer.h"
#include "lpv/scene/ProjectTextures.h"

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using namespace lpv;
namespace fs = std::filesystem;

namespace {

constexpr int kWidth = 320, kHeight = 180; // the golden set's size (tools/golden/golden-renders.sh)
constexpr int kFrames = 2;

fs::path hashesFile() { return fs::path(test::kSourceDir) / "tests/renderer/golden/hashes.txt"; }

bool regenerating() {
    const char* v = std::getenv("LPV_GOLDEN_REGENERATE");
    return v && std::strcmp(v, "0") != 0 && *v != '\0';
}

// FNV-1a over bytes: stable across compilers and platforms, unlike std::hash.
std::uint64_t fnv1a(const void* data, std::size_t size, std::uint64_t h = 0xcbf29ce484222325ull) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i)
        h = (h ^ p[i]) * 0x100000001b3ull;
    return h;
}

// RGB only: the PNG that `lpv render` writes carries no alpha, so this hash
// can be checked against a PNG's decoded pixels.
template <typename T> std::string rgbHash(const std::vector<T>& rgba) {
    std::uint64_t h = 0xcbf29ce484222325ull;
    for (std::size_t i = 0; i + 3 < rgba.size(); i += 4)
        h = fnv1a(&rgba[i], 3 * sizeof(T), h);
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h));
    return text;
}

std::string glRendererLine() {
    const renderer::GlInfo gl = renderer::queryCurrentGlInfo();
    return gl.renderer + " | " + gl.version;
}

// A project as `lpv render` meets it: saved with its textures beside it, then
// loaded again, so the image sees exactly what a saved project holds.
struct SavedProject {
    fs::path file;
    scene::Project project;
    scene::Camera camera;
};

// The folders this process saved projects into, removed when its tests end.
std::vector<fs::path>& savedFolders() {
    static std::vector<fs::path> folders;
    return folders;
}

SavedProject savedImport(const std::string& relative, const std::string& name) {
    test::OpeningView view = test::importedScene(relative);
    // One folder per test that imports: ctest runs each test in its own
    // process, two at a time, and two must not save into one folder.
    const fs::path dir = fs::path(test::kBinaryDir) / "golden-scenes" /
                         (name + "-" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir);
    savedFolders().push_back(dir);
    fs::create_directories(dir);
    SavedProject s{dir / (name + ".lpvproj"), {}, {}};
    view.project.name = name;
    EXPECT_TRUE(scene::copyTexturesIntoProject(view.project.scene, s.file).has_value());
    const auto saved = scene::saveProject(view.project, s.file);
    EXPECT_TRUE(saved.has_value()) << (saved ? "" : saved.error().describe());
    auto loaded = scene::loadProject(s.file);
    EXPECT_TRUE(loaded.has_value()) << (loaded ? "" : loaded.error().describe());
    if (loaded)
        s.project = std::move(*loaded);
    s.camera = app::firstView(s.project.scene);
    return s;
}

SavedProject cornellTemplate() {
    test::OpeningView view = test::builtInCornellBox();
    return {test::builtInCornellBoxFile(), std::move(view.project), view.camera};
}

struct Configuration {
    std::string name;
    std::vector<std::pair<std::string, std::string>> sets;
};

class GoldenImagesGL : public GlTest {
protected:
    static void SetUpTestSuite() {
        GlTest::SetUpTestSuite();
        std::ifstream in(hashesFile());
        std::string line;
        while (std::getline(in, line)) {
            if (line.rfind("# gl: ", 0) == 0)
                goldenGl_ = line.substr(6);
            else if (!line.empty() && line[0] != '#') {
                std::istringstream words(line);
                std::string name, hashes;
                words >> name;
                std::getline(words >> std::ws, hashes);
                golden_[name] = hashes;
            }
        }
    }
    static void TearDownTestSuite() {
        if (regenerating() && !produced_.empty()) {
            std::ofstream out(hashesFile());
            out << "# gl: " << glRendererLine() << "\n"
                << "# Pixel hashes of GoldenImagesGLTest.cpp's renders (FNV-1a of RGB: display bytes, HDR floats).\n"
                << "# Regenerate: LPV_GOLDEN_REGENERATE=1 build/tests/renderer/renderer_golden_gl_tests\n";
            for (const auto& [name, hashes] : produced_)
                out << name << " " << hashes << "\n";
        }
        for (const fs::path& dir : savedFolders())
            fs::remove_all(dir);
        GlTest::TearDownTestSuite();
    }

    void expectGolden(const SavedProject& s, const Configuration& c) {
        ASSERT_FALSE(s.project.scene.objects.empty());
        if (!regenerating() && goldenGl_ != glRendererLine())
            GTEST_SKIP() << "golden hashes were made on '" << goldenGl_ << "'; this context is '" << glRendererLine()
                         << "', whose rounding differs: compare two binaries with tools/golden/golden-renders.sh instead";
        scene::Project project = s.project;
        for (const auto& [key, value] : c.sets)
            ASSERT_TRUE(project.parameters.setFromText(key, value).has_value()) << key;
        auto r = renderer::ForwardRenderer::create();
        ASSERT_TRUE(r.has_value()) << r.error().describe();
        const auto textures = importers::loadSceneTextures(project.scene, fs::absolute(s.file).parent_path());
        r->setScene(project.scene, textures.images);
        for (int f = 0; f < kFrames; ++f) {
            const auto ok = r->render(project.scene, project.parameters, s.camera, kWidth, kHeight);
            ASSERT_TRUE(ok.has_value()) << ok.error().describe();
        }
        const std::string hashes = "display=" + rgbHash(r->readDisplay()) + " hdr=" + rgbHash(r->readHdr());
        produced_[c.name] = hashes;
        if (regenerating())
            return;
        EXPECT_EQ(golden_[c.name], hashes)
            << c.name << ": the image changed. If that was not meant, the change moved a pixel. A deliberate image "
            << "change must regenerate " << hashesFile().string() << " in the same commit: "
            << "LPV_GOLDEN_REGENERATE=1 build/tests/renderer/renderer_golden_gl_tests";
    }

    static inline std::string goldenGl_;
    static inline std::map<std::string, std::string> golden_, produced_;
};

// Each scene is imported once: Sponza's import is the slow part.
const SavedProject& sponza() {
    static const SavedProject s = savedImport("sponza/sponza.obj", "sponza");
    return s;
}
const SavedProject& sibenik() {
    static const SavedProject s = savedImport("sibenik/sibenik.obj", "sibenik");
    return s;
}

} // namespace

TEST_F(GoldenImagesGL, CornellTemplate) { expectGolden(cornellTemplate(), {"cornell", {}}); }

TEST_F(GoldenImagesGL, CornellIndirectView) {
    expectGolden(cornellTemplate(), {"cornell-indirect", {{"output.view", "indirect"}}});
}

TEST_F(GoldenImagesGL, ImportedSponza) { expectGolden(sponza(), {"sponza", {}}); }

// Glossy reflections, sun rays, subsurface, bounces, directed propagation and sky injection at once.
TEST_F(GoldenImagesGL, ImportedSponzaWithEveryEffect) {
    expectGolden(sponza(), {"sponza-effects",
                            {{"effects.glossyReflections", "on"},
                             {"effects.sunRays", "on"},
                             {"effects.subsurface", "on"},
                             {"lpv.bounces", "2"},
                             {"lpv.directedPropagation", "on"},
                             {"effects.skyInjection", "on"}}});
}

// The geometry volume from the views, raster scatter, tile draws by geometry shader.
TEST_F(GoldenImagesGL, ImportedSponzaGeometryFromViews) {
    expectGolden(sponza(), {"sponza-views",
                            {{"lpv.geometrySource", "views"},
                             {"lpv.variant", "rasterScatter"},
                             {"rsm.tileDraws", "geometryShader"}}});
}

TEST_F(GoldenImagesGL, ImportedSibenik) { expectGolden(sibenik(), {"sibenik", {}}); }

// Compute scatter with the visibility lookup and two cascades.
TEST_F(GoldenImagesGL, ImportedSibenikComputeScatter) {
    expectGolden(sibenik(), {"sibenik-scatter",
                             {{"lpv.variant", "computeScatter"},
                              {"lpv.visibilityLookup", "true"},
                              {"lpv.cascades", "2"}}});
}

// Raster gather with glossy reflections.
TEST_F(GoldenImagesGL, ImportedSibenikRasterGather) {
    expectGolden(sibenik(), {"sibenik-rastergather",
                             {{"lpv.variant", "rasterGather"}, {"effects.glossyReflections", "on"}}});
}
