// lpv_app_common: where the programs find the built-in projects, and the
// version report's contents and layout.
#include "TestPaths.h"

#include "lpv/app/BuiltInProjects.h"
#include "lpv/app/VersionInfo.h"
#include "lpv/scene/ProcessId.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;

namespace {

// An installed tree: PREFIX/bin and PREFIX/share/lpvstudio/projects/cornell-box.
struct FakeInstall {
    fs::path prefix =
        fs::temp_directory_path() / ("lpv-app-common-" + std::to_string(lpv::scene::processId()));
    fs::path project = prefix / "share/lpvstudio/projects/cornell-box/cornell-box.lpvproj";

    FakeInstall() {
        fs::remove_all(prefix);
        fs::create_directories(prefix / "bin");
        fs::create_directories(project.parent_path());
        std::ofstream(project) << "{}";
    }
    ~FakeInstall() { fs::remove_all(prefix); }
};

} // namespace

TEST(BuiltInProjects, InstalledBesideTheExecutableComesFirst) {
    FakeInstall install;
    const fs::path found = lpv::app::findBuiltInProject("cornell-box", install.prefix / "bin");
    EXPECT_EQ(found, install.project.lexically_normal());
}

TEST(BuiltInProjects, FromTheBuildFolderFallsBackToTheSourceTree) {
    FakeInstall install;
    fs::remove_all(install.prefix / "share");
    const fs::path found = lpv::app::findBuiltInProject("cornell-box", install.prefix / "bin");
    ASSERT_FALSE(found.empty());
    EXPECT_TRUE(
        fs::equivalent(found, fs::path(lpv::test::kSourceDir) / "projects/cornell-box/cornell-box.lpvproj"))
        << found;
}

TEST(BuiltInProjects, CandidatesAreInstalledThenSourceAndUnknownNamesAreNotFound) {
    const auto candidates = lpv::app::builtInProjectCandidates("cornell-box", "/opt/lpv/bin");
    ASSERT_EQ(candidates.size(), 2u);
    EXPECT_EQ(candidates[0], fs::path("/opt/lpv/share/lpvstudio/projects/cornell-box/cornell-box.lpvproj"));
    EXPECT_TRUE(lpv::app::findBuiltInProject("no-such-project", "/opt/lpv/bin").empty());
}

TEST(VersionReport, NamesVersionRevisionAndEveryLayersLibraries) {
    const lpv::app::VersionReport report = lpv::app::collectVersionReport("lpv");
    EXPECT_EQ(report.build.version, LPV_TEST_PROJECT_VERSION);
    EXPECT_FALSE(report.build.revision.empty());
    EXPECT_FALSE(report.build.compiler.empty());
    std::vector<std::string> names;
    for (const auto& lib : report.libraries) {
        names.push_back(lib.name);
        EXPECT_FALSE(lib.version.empty()) << lib.name;
        EXPECT_NE(lib.version, "unknown") << lib.name;
    }
    // One of each layer: scene, importers, renderer.
    for (const char* name : {"glm", "nlohmann_json", "Assimp", "OpenImageIO", "tinygltf", "libepoxy"})
        EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name;
}

TEST(VersionReport, FormatsOneFieldPerLineAndAlignsLibraries) {
    lpv::app::VersionReport report{
        "lpv", {"1.2.3", "abc1234-dirty", "Release", "GNU 12.2.0", "Linux x86_64"}, "", {}, {}};
    report.openGl = lpv::app::describeOpenGl(
        {"Mesa", "llvmpipe (LLVM 15.0.6, 256 bits)", "4.5 (Core Profile)", "surfaceless"});
    report.libraries = {{"glm", "0.9.9.8", "header-only"}, {"OpenImageIO", "2.4.7", ""}};
    EXPECT_EQ(
        lpv::app::formatVersionReport(report),
        "lpv 1.2.3\n"
        "revision:  abc1234-dirty\n"
        "build:     Release, GNU 12.2.0, Linux x86_64\n"
        "OpenGL:    llvmpipe (LLVM 15.0.6, 256 bits), OpenGL 4.5 (Core Profile) (Mesa, EGL surfaceless)\n"
        "libraries:\n"
        "  glm          0.9.9.8 (header-only)\n"
        "  OpenImageIO  2.4.7\n");
}

TEST(VersionReport, NamesTheGpuDriverAndPlatformOfAContext) {
    lpv::app::VersionReport report{"lpv", {"1.2.3", "abc1234", "Release", "GNU 12.2.0", "Linux x86_64"}, "", {}, {}};
    report.gl = lpv::renderer::GlInfo{"NVIDIA Corporation", "NVIDIA H200/PCIe/SSE2", "4.6.0 NVIDIA 550.54.15", "device"};
    report.openGl = lpv::app::describeOpenGl(*report.gl);
    const std::string text = lpv::app::formatVersionReport(report);
    EXPECT_NE(text.find("\nGPU:       NVIDIA H200/PCIe/SSE2 (NVIDIA Corporation)\n"), std::string::npos) << text;
    EXPECT_NE(text.find("\ndriver:    OpenGL 4.6.0 NVIDIA 550.54.15\n"), std::string::npos) << text;
    EXPECT_NE(text.find("\nplatform:  EGL device\n"), std::string::npos) << text;
    report.gl->eglPlatform.clear(); // a context that did not come from our EGL code (Qt's GLX)
    EXPECT_NE(lpv::app::formatVersionReport(report).find("\nplatform:  not EGL\n"), std::string::npos);
}

TEST(VersionReport, DescribesAContextWithMissingStrings) {
    EXPECT_EQ(lpv::app::describeOpenGl({}), "unknown renderer, OpenGL unknown (unknown vendor)");
}
