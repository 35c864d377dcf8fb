// `lpv --version`: the version from CMake, the git revision of the build, the
// OpenGL driver (or why there is none, still with exit code 0) and the versions
// of the main libraries.
#include "RunLpv.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <regex>

using namespace lpv::test;

namespace {

// The value of the report line "KEY: value", or nullopt.
std::optional<std::string> field(const std::string& output, const std::string& key) {
    const std::regex line("(^|\n)" + key + ": *([^\n]*)");
    std::smatch m;
    if (!std::regex_search(output, m, line))
        return std::nullopt;
    return m[2].str();
}

} // namespace

TEST(CliVersion, PrintsVersionRevisionOpenGlAndLibraries) {
    const RunResult r = runLpv("--version");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(r.output.rfind(std::string("lpv ") + LPV_TEST_PROJECT_VERSION + "\n", 0), 0u) << r.output;

    const auto revision = field(r.output, "revision");
    ASSERT_TRUE(revision) << r.output;
    EXPECT_FALSE(revision->empty());
    // Tests run from a git checkout, where the build must have read the
    // revision: an abbreviated hash, after a tag if there is one, maybe "-dirty".
    if (std::filesystem::exists(std::filesystem::path(kSourceDir) / ".git")) {
        EXPECT_TRUE(std::regex_match(*revision, std::regex("(.+-g)?[0-9a-f]{7,40}(-dirty)?"))) << *revision;
    }

    const auto build = field(r.output, "build");
    ASSERT_TRUE(build) << r.output;
    EXPECT_NE(build->find(LPV_TEST_BUILD_TYPE), std::string::npos) << *build;

    // The tests' machines have a driver (llvmpipe at least): the line names it and its GL version.
    const auto gl = field(r.output, "OpenGL");
    ASSERT_TRUE(gl) << r.output;
    EXPECT_EQ(gl->find("unavailable"), std::string::npos) << *gl;
    EXPECT_NE(gl->find("OpenGL 4."), std::string::npos) << *gl;
    // Issue #45: the GPU (GL_RENDERER), the driver (GL_VERSION) and the EGL platform, a line each.
    const auto gpu = field(r.output, "GPU"), driver = field(r.output, "driver"), platform = field(r.output, "platform");
    ASSERT_TRUE(gpu && driver && platform) << r.output;
    EXPECT_NE(gl->find(gpu->substr(0, gpu->find(" ("))), std::string::npos) << *gpu << " | " << *gl;
    EXPECT_EQ(driver->rfind("OpenGL 4.", 0), 0u) << *driver;
    EXPECT_TRUE(std::regex_match(*platform, std::regex("EGL (device|surfaceless|default)"))) << *platform;

    for (const char* lib :
         {"Assimp", "OpenImageIO", "glm", "nlohmann_json", "tinygltf", "OpenMesh", "libepoxy"})
        EXPECT_TRUE(std::regex_search(r.output, std::regex(std::string("\n  ") + lib + " +[0-9]+\\.[0-9]+")))
            << lib << " missing or without a version:\n"
            << r.output;
}

TEST(CliVersion, WithoutOpenGlSaysWhyAndStillSucceeds) {
    // No EGL platform of that name: context creation fails as on a machine without a driver.
    ::setenv("LPV_EGL_PLATFORM", "none", 1);
    const RunResult r = runLpv("--version");
    ::unsetenv("LPV_EGL_PLATFORM");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    const auto gl = field(r.output, "OpenGL");
    ASSERT_TRUE(gl) << r.output;
    EXPECT_EQ(gl->rfind("unavailable: ", 0), 0u) << *gl;
    EXPECT_NE(gl->find("LPV_EGL_PLATFORM=none"), std::string::npos) << "the error names the cause: " << *gl;
    EXPECT_TRUE(field(r.output, "revision")) << "the rest is still printed";
    EXPECT_FALSE(field(r.output, "GPU")) << "no context, no GPU line: " << r.output;
    EXPECT_NE(r.output.find("\n  Assimp "), std::string::npos) << r.output;
}
