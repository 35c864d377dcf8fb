// `lpv import` as a user runs it: real scenes from ../shared/scenes into a
// project, the summary it prints, and the project rendering afterwards.
#include "RunLpv.h"

#include "lpv/importers/ImageIO.h"
#include "lpv/scene/Project.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace lpv::test;
namespace fs = std::filesystem;

namespace {

fs::path scenes() { return fs::path(kSharedScenesDir); }

// Fraction of pixels that differ from the first one by more than a little.
double nonUniformFraction(const lpv::importers::Image8& img) {
    std::size_t differ = 0, count = std::size_t(img.width) * std::size_t(img.height);
    const auto c = std::size_t(img.channels);
    for (std::size_t i = 0; i < count; ++i)
        for (std::size_t k = 0; k < 3; ++k)
            if (std::abs(int(img.pixels[i * c + k]) - int(img.pixels[k])) > 8) {
                ++differ;
                break;
            }
    return double(differ) / double(count);
}

// Fraction of pixels with some channel above 40 of 255: directly lit surfaces.
double litFraction(const lpv::importers::Image8& img) {
    std::size_t lit = 0, count = std::size_t(img.width) * std::size_t(img.height);
    const auto c = std::size_t(img.channels);
    for (std::size_t i = 0; i < count; ++i)
        if (std::max({img.pixels[i * c], img.pixels[i * c + 1], img.pixels[i * c + 2]}) > 40)
            ++lit;
    return double(lit) / double(count);
}

} // namespace

TEST(ImportCommand, SibenikFourDsWithAllItsTexturesRenders) {
    const fs::path dir = freshTempDir("import", "sibenik4ds");
    const fs::path project = dir / "sibenik.lpvproj";
    const RunResult r = runLpv("import " + quoted(scenes() / "4ds/sibenik.4ds") + " -o " + quoted(project));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    // SOURCE.md: 72,524 LOD 0 triangles, 10 materials; 9 diffuse maps and companions found.
    // 72,524 LOD 0 triangles of which 11 are degenerate (MeshCleanup.SibenikKeepsEveryRealTriangle...).
    EXPECT_NE(r.output.find("72,513 triangles"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("11 degenerate triangles dropped"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("10 materials"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("0 missing"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("added a sun"), std::string::npos) << "the 4ds has no lights";

    auto loaded = lpv::scene::loadProject(project);
    ASSERT_TRUE(loaded.has_value()) << loaded.error().describe();
    std::size_t textures = 0;
    for (const auto& m : loaded->scene.materials)
        if (!m.diffuseTexture.empty()) {
            ++textures;
            EXPECT_TRUE(m.diffuseTexture.starts_with("sibenik.assets/textures/")) << m.diffuseTexture;
            EXPECT_TRUE(fs::is_regular_file(dir / m.diffuseTexture)) << m.diffuseTexture;
        }
    EXPECT_GE(textures, 4u);
    const RunResult info = runLpv("info " + quoted(project));
    // The 9 files the importer found: 3 diffuse maps with their _ddn and _spec companions.
    EXPECT_NE(info.output.find("textures    9 (0 missing)"), std::string::npos) << info.output;

    // Without a camera `lpv render` stands inside the nave, which direct
    // sunlight barely reaches until the LPV exists; look at the outside,
    // which the sun lights, from a camera added to the project.
    const lpv::scene::Bounds bounds = loaded->scene.worldBounds();
    lpv::scene::Camera outside;
    outside.name = "outside";
    outside.target = bounds.center();
    outside.position = bounds.center() + glm::vec3(0.0f, 0.3f, 1.2f) * glm::length(bounds.size());
    outside.farPlane = 10.0f * glm::length(bounds.size());
    loaded->scene.cameras.push_back(outside);
    ASSERT_TRUE(lpv::scene::saveProject(*loaded, project).has_value());
    const fs::path png = dir / "sibenik.png";
    const RunResult render = runLpv("render " + quoted(project) + " -o " + quoted(png) + " --width 96 --height 64");
    ASSERT_EQ(render.exitCode, 0) << render.output;
    auto image = lpv::importers::readImage8(png);
    ASSERT_TRUE(image.has_value()) << image.error().describe();
    EXPECT_GT(nonUniformFraction(*image), 0.2) << "the cathedral is visible, not a blank image";
    fs::remove_all(dir);
}

TEST(ImportCommand, SponzaObjThenAddingTheCornellGltf) {
    const fs::path dir = freshTempDir("import", "sponza");
    const fs::path project = dir / "mix.lpvproj";
    const RunResult first = runLpv("import " + quoted(scenes() / "sponza/sponza.obj") + " -o " + quoted(project));
    ASSERT_EQ(first.exitCode, 0) << first.output;
    EXPECT_NE(first.output.find("66,443 triangles"), std::string::npos) << first.output;
    EXPECT_NE(first.output.find("7 degenerate triangles dropped"), std::string::npos) << first.output;
    EXPECT_NE(first.output.find("17 found / 0 missing"), std::string::npos) << first.output;
    EXPECT_NE(first.output.find("created "), std::string::npos);

    const RunResult second =
        runLpv("import " + quoted(scenes() / "cornell/gltf/cornellBox.gltf") + " -o " + quoted(project));
    ASSERT_EQ(second.exitCode, 0) << second.output;
    EXPECT_NE(second.output.find("added to "), std::string::npos) << second.output;
    auto loaded = lpv::scene::loadProject(project);
    ASSERT_TRUE(loaded.has_value()) << loaded.error().describe();
    EXPECT_EQ(loaded->scene.triangleCount(), 66443u + 16224u);
    EXPECT_EQ(loaded->scene.lights.size(), 1u) << "one sun, added by the first import only";

    const fs::path png = dir / "mix.png";
    const RunResult render = runLpv("render " + quoted(project) + " -o " + quoted(png) + " --width 64 --height 48");
    ASSERT_EQ(render.exitCode, 0) << render.output;
    fs::remove_all(dir);
}

TEST(ImportCommand, CornellObjAndSponza3dsRender) {
    const fs::path dir = freshTempDir("import", "objs");
    // Direct light only until the LPV exists (issue #5): Sponza's own Camera01
    // looks up at the side of the atrium the sun does not reach, so only a
    // few percent of its pixels are lit; the Cornell box is lit all over.
    const std::pair<const char*, double> files[] = {{"cornell/CornellBox-Original.obj", 0.3},
                                                    {"sponza/sponza.3ds", 0.002}};
    for (const auto& [file, litFraction] : files) {
        SCOPED_TRACE(file);
        const fs::path project = dir / (fs::path(file).stem().string() + ".lpvproj");
        const RunResult r = runLpv("import " + quoted(scenes() / file) + " -o " + quoted(project));
        ASSERT_EQ(r.exitCode, 0) << r.output;
        const fs::path png = dir / (fs::path(file).stem().string() + ".png");
        const RunResult render = runLpv("render " + quoted(project) + " -o " + quoted(png) + " --width 96 --height 64");
        ASSERT_EQ(render.exitCode, 0) << render.output;
        auto image = lpv::importers::readImage8(png);
        ASSERT_TRUE(image.has_value());
        EXPECT_GT(nonUniformFraction(*image), litFraction);
    }
    // The 3DS sun (a point light 60 units above the atrium) became a directional light.
    auto sponza = lpv::scene::loadProject(dir / "sponza.lpvproj");
    ASSERT_TRUE(sponza.has_value());
    ASSERT_EQ(sponza->scene.lights.size(), 1u);
    EXPECT_EQ(sponza->scene.lights[0].type, lpv::scene::LightType::Directional);
    ASSERT_EQ(sponza->scene.cameras.size(), 1u);
    EXPECT_NEAR(sponza->scene.cameras[0].position.y, 1.56f, 0.01f) << "Camera01 at head height, not doubled";

    // Without its camera, `lpv render` stands inside the atrium (FramingCamera)
    // and looks along it: the sunlit floor and arcades are in view.
    sponza->scene.cameras.clear();
    ASSERT_TRUE(lpv::scene::saveProject(*sponza, dir / "sponza-front.lpvproj").has_value());
    const fs::path front = dir / "front.png";
    ASSERT_EQ(runLpv("render " + quoted(dir / "sponza-front.lpvproj") + " -o " + quoted(front) +
                     " --width 96 --height 64").exitCode, 0);
    auto image = lpv::importers::readImage8(front);
    ASSERT_TRUE(image.has_value());
    EXPECT_GT(litFraction(*image), 0.04) << "sunlit floor and arcades (measured 0.09 at 96x64)";
    fs::remove_all(dir);
}

TEST(ImportCommand, AFailedImportLeavesTheProjectUnchanged) {
    const fs::path dir = freshTempDir("import", "fail");
    const fs::path project = dir / "p.lpvproj";
    ASSERT_EQ(runLpv("import " + quoted(scenes() / "4ds/cube00.4ds") + " -o " + quoted(project)).exitCode, 0);
    const std::string before = readText(project);
    std::ofstream(dir / "broken.4ds", std::ios::binary) << std::string("4DS\0\x1d\0", 6) << "cut short";
    const RunResult r = runLpv("import " + quoted(dir / "broken.4ds") + " -o " + quoted(project));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.output.find("broken.4ds"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("unchanged"), std::string::npos) << r.output;
    EXPECT_EQ(readText(project), before);
    fs::remove_all(dir);
}

TEST(ImportCommand, UsageErrors) {
    EXPECT_EQ(runLpv("import").exitCode, 2);
    EXPECT_EQ(runLpv("import " + quoted(scenes() / "4ds/cube00.4ds")).exitCode, 2) << "no -o";
    EXPECT_EQ(runLpv("import x.obj -o out.json").exitCode, 2) << "not .lpvproj";
    EXPECT_EQ(runLpv("import x.obj -o out.lpvproj --bogus").exitCode, 2);
    const RunResult help = runLpv("import --help");
    EXPECT_EQ(help.exitCode, 0);
    EXPECT_NE(help.output.find("--texture-path"), std::string::npos);
}
