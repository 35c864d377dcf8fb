// lpv-gl-bench (issue #45): the GPU bench that runs where only glibc and a
// GL driver are. It must stay free of the image, scene-file, video, Qt and
// path-tracing libraries (what `ldd` lists), print the tables `lpv bench
// render` prints for the same pack, write an image without an image
// library, and refuse a project with a clear message.
#include "RunLpv.h"

#include <gtest/gtest.h>

#include <regex>
#include <set>
#include <sstream>

using namespace lpv::test;
namespace fs = std::filesystem;

namespace {

std::string glBench() { return std::string(kBinaryDir) + "/app/glbench/lpv-gl-bench"; }

RunResult runGlBench(const std::string& args) { return runShell(glBench() + " " + args); }

// The pass names of a `bench render` table: the rows between its "pass" header and its "total".
std::set<std::string> passNames(const std::string& output) {
    std::set<std::string> names;
    std::istringstream in(output);
    std::string line;
    bool inTable = false;
    while (std::getline(in, line)) {
        if (line.rfind("pass ", 0) == 0) {
            inTable = true;
            continue;
        }
        if (!inTable)
            continue;
        const std::string name = line.substr(0, line.find(' '));
        if (name == "total")
            break;
        names.insert(name);
    }
    return names;
}

} // namespace

TEST(GlBench, LinksNoImageSceneFileVideoQtOrRayTracingLibrary) {
    const RunResult r = runShell("ldd " + glBench());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const char* lib : {"libOpenImageIO", "libassimp", "libavcodec", "libavformat", "libQt6", "libembree",
                            "libOpenMesh", "libtinygltf"})
        EXPECT_FALSE(contains(r.output, lib)) << lib << " in:\n" << r.output;
    // libepoxy, libxxhash and glibc's: a handful, where lpv has 268.
    const auto linked = std::count(r.output.begin(), r.output.end(), '>');
    EXPECT_LE(linked, 8) << r.output;
    EXPECT_TRUE(contains(r.output, "libepoxy")) << r.output;
}

TEST(GlBench, PrintsTheTablesLpvBenchRenderPrintsForThePack) {
    const fs::path dir = freshBuildDir("cli", "GlBenchTables");
    const fs::path pack = dir / "cornell.lpvpack";
    const RunResult packed = runLpv("bench pack " + quoted(fs::path(cornellProject())) + " -o " + quoted(pack));
    ASSERT_EQ(packed.exitCode, 0) << packed.output;
    const std::string options = " --width 32 --height 18 --frames 1 --warmup 0 --rounds 1";
    const RunResult ours = runGlBench("render " + quoted(pack) + options + " --markdown " + quoted(dir / "gl.md"));
    ASSERT_EQ(ours.exitCode, 0) << ours.output;
    const RunResult lpv = runLpv("bench render " + quoted(pack) + options);
    ASSERT_EQ(lpv.exitCode, 0) << lpv.output;
    const std::set<std::string> passes = passNames(ours.output);
    EXPECT_TRUE(passes.contains("lpvPropagation") && passes.contains("shading")) << ours.output;
    EXPECT_EQ(passes, passNames(lpv.output)) << ours.output << "\n---\n" << lpv.output;
    EXPECT_TRUE(contains(ours.output, "GPU frame rate from the total's median")) << ours.output;
    EXPECT_TRUE(contains(readText(dir / "gl.md"), "lpvPropagation"));

    const RunResult version = runGlBench("--version");
    EXPECT_EQ(version.exitCode, 0) << version.output;
    EXPECT_TRUE(std::regex_search(version.output, std::regex("\nGPU: +[^\n]+\ndriver: +OpenGL 4\\.[^\n]+\nplatform: +EGL ")))
        << version.output;
}

TEST(GlBench, WritesAnImageWithoutAnImageLibraryAndRefusesAProject) {
    const fs::path dir = freshBuildDir("cli", "GlBenchImage");
    const fs::path pack = dir / "cornell.lpvpack";
    ASSERT_EQ(runLpv("bench pack " + quoted(fs::path(cornellProject())) + " -o " + quoted(pack)).exitCode, 0);
    const RunResult image =
        runGlBench("image " + quoted(pack) + " --width 32 --height 18 --frames 1 -o " + quoted(dir / "c.ppm"));
    ASSERT_EQ(image.exitCode, 0) << image.output;
    const std::string ppm = readText(dir / "c.ppm");
    const std::string header = "P6\n32 18\n255\n";
    ASSERT_EQ(ppm.size(), header.size() + 32 * 18 * 3);
    EXPECT_EQ(ppm.substr(0, header.size()), header);
    // The Cornell box is lit: some pixel is bright.
    EXPECT_TRUE(std::any_of(ppm.begin() + long(header.size()), ppm.end(),
                            [](char c) { return static_cast<unsigned char>(c) > 100; }));

    const RunResult project = runGlBench("render " + quoted(fs::path(cornellProject())));
    EXPECT_EQ(project.exitCode, 2) << project.output;
    EXPECT_TRUE(contains(project.output, "reads bench packs")) << project.output;
}
