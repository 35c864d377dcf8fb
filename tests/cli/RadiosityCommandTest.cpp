// `lpv radiosity` as a user runs it, on a temporary copy of the Cornell box
// with coarse patches: solve, save, resume, image.
#include "RunLpv.h"

#include "lpv/scene/Project.h"

#include <gtest/gtest.h>

#include <filesystem>

using namespace lpv::test;
namespace fs = std::filesystem;
using namespace lpv;

namespace {

} // namespace

TEST(RadiosityCommand, SolvesSavesAndResumesTheCornellBox) {
    const fs::path dir = fs::path(kBinaryDir) / "tests" / "cli-radiosity";
    fs::remove_all(dir);
    fs::create_directories(dir);
    const fs::path solved = dir / "solved.lpvproj";
    const std::string coarse = " --set radiosity.maxPatchArea=0.5 --set radiosity.hemicubeResolution=32";

    // The hemicube image needs hemicube form factors: with the default ray
    // casting it says so and writes none.
    auto cast = runLpv("radiosity " + cornellProject() + coarse + " --residual 0.5 -o " +
                       (dir / "cast.lpvproj").string() + " --hemicube-image " + (dir / "none.png").string());
    ASSERT_EQ(cast.exitCode, 0) << cast.output;
    EXPECT_TRUE(contains(cast.output, "form factors: raycast")) << cast.output;
    EXPECT_TRUE(contains(cast.output, "--hemicube-image needs radiosity.formFactors=hemicube")) << cast.output;
    EXPECT_FALSE(fs::exists(dir / "none.png"));

    auto first = runLpv("radiosity " + cornellProject() + coarse +
                        " --set radiosity.formFactors=hemicube --residual 0.3 -o " + solved.string() +
                        " --image " + (dir / "cornell.png").string() + " --hemicube-image " +
                        (dir / "hemicube.png").string());
    ASSERT_EQ(first.exitCode, 0) << first.output;
    EXPECT_TRUE(contains(first.output, "stopped: converged")) << first.output;
    EXPECT_TRUE(fs::exists(solved));
    EXPECT_TRUE(fs::exists(dir / "solved.assets" / "radiosity.lpvrad"));
    EXPECT_TRUE(fs::exists(dir / "cornell.png"));
    EXPECT_TRUE(fs::exists(dir / "hemicube.png"));

    auto second = runLpv("radiosity " + solved.string() + coarse + " --residual 0.1");
    ASSERT_EQ(second.exitCode, 0) << second.output;
    EXPECT_TRUE(contains(second.output, "resuming the saved solution")) << second.output;
    EXPECT_TRUE(contains(second.output, "reached residual 0.1 after")) << second.output;
    EXPECT_TRUE(contains(second.output, "stopped: converged")) << second.output;

    auto restarted = runLpv("radiosity " + solved.string() + coarse + " --residual 0.5 --restart");
    ASSERT_EQ(restarted.exitCode, 0) << restarted.output;
    EXPECT_FALSE(contains(restarted.output, "resuming")) << restarted.output;
}

TEST(RadiosityCommand, BadOptionsAreUsageErrors) {
    auto r = runLpv("radiosity " + cornellProject() + " --residual 2");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_TRUE(contains(r.output, "--residual: '2' is not a number in (0, 1]")) << r.output;
    auto v = runLpv("radiosity " + cornellProject() + " --view sideways");
    EXPECT_EQ(v.exitCode, 2) << v.output;
    EXPECT_TRUE(contains(v.output, "--view: 'sideways' is not radiosity, ambient, unshot or shot")) << v.output;
}

// Issue #27 items 2 and 6: the imported Box, lit by the sun `lpv import`
// gives it and with no emissive surface, solves; without its sun nothing
// shoots, which is a clear error and no solution file (Sponza used to
// "converge" at once and save 158 MB of black); a scene over
// radiosity.maxPatches is refused with the count and the limit before it is
// meshed.
TEST(RadiosityCommand, NothingThatEmitsAndTooManyPatchesAreRefusedAndWriteNothing) {
    const fs::path dir = fs::path(kBinaryDir) / "tests" / "cli-radiosity-refused";
    fs::remove_all(dir);
    fs::create_directories(dir);
    const fs::path box = dir / "box.lpvproj";
    auto imported = runLpv("import '" + (fs::path(kSharedScenesDir) / "gltf-small/Box/glTF/Box.gltf").string() +
                           "' -o '" + box.string() + "'");
    ASSERT_EQ(imported.exitCode, 0) << imported.output;
    auto project = scene::loadProject(box);
    ASSERT_TRUE(project.has_value()) << project.error().describe();
    ASSERT_FALSE(project->scene.lights.empty()) << "lpv import places a sun in an unlit scene";
    const fs::path sunlit = dir / "sunlit.lpvproj";
    auto lit = runLpv("radiosity '" + box.string() + "' --residual 0.5 -o '" + sunlit.string() + "'");
    EXPECT_EQ(lit.exitCode, 0) << lit.output;
    EXPECT_TRUE(contains(lit.output, "lights: direct light at 4 points per patch")) << lit.output;
    EXPECT_TRUE(fs::exists(dir / "sunlit.assets" / "radiosity.lpvrad"));

    project->scene.lights.clear();
    const fs::path unlit = dir / "unlit.lpvproj";
    ASSERT_TRUE(scene::saveProject(*project, unlit).has_value());
    auto dark = runLpv("radiosity '" + unlit.string() + "' --residual 0.5");
    EXPECT_EQ(dark.exitCode, 1) << dark.output;
    EXPECT_TRUE(contains(dark.output, "nothing in the scene shoots light")) << dark.output;
    EXPECT_FALSE(fs::exists(dir / "unlit.assets" / "radiosity.lpvrad")) << "no solution may be written";

    const fs::path copy = dir / "cornell.lpvproj";
    auto many = runLpv("radiosity " + cornellProject() + " --set radiosity.maxPatchArea=0.5 --set "
                       "radiosity.maxPatches=100 -o '" + copy.string() + "'");
    EXPECT_EQ(many.exitCode, 1) << many.output;
    EXPECT_TRUE(contains(many.output, "over radiosity.maxPatches = 100")) << many.output;
    EXPECT_TRUE(contains(many.output, "would mesh into ")) << many.output;
    EXPECT_FALSE(fs::exists(copy)) << "a refused solve writes no project";
}
