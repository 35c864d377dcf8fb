// The installed tree (issue #12). `cmake --install` into a staging prefix
// lays out what a user gets; then the INSTALLED programs run on the INSTALLED
// sample project, found relative to the executables (the staging prefix is
// not the configured one). A missing or wrong install rule fails here.
//
// One CTest test for the whole binary (the install happens once, in
// SetUpTestSuite); the staging tree is left in build/tests/install-staging
// for a look after a failure and replaced by the next run.
#include "TestFiles.h"
#include "TestPaths.h"

#include "lpv/importers/ImageIO.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>

namespace fs = std::filesystem;

using namespace lpv::test;

namespace {

const std::string kAppId = "org.lpvstudio.lpvstudio";

class Installed : public ::testing::Test {
  protected:
    static inline fs::path prefix = fs::path(lpv::test::kBinaryDir) / "tests/install-staging";
    static inline RunResult install;

    static void SetUpTestSuite() {
        fs::remove_all(prefix);
        install = runShell(std::string(LPV_TEST_CMAKE_COMMAND) + " --install " + quoted(lpv::test::kBinaryDir) +
                      " --prefix " + quoted(prefix));
    }

    void SetUp() override { ASSERT_EQ(install.exitCode, 0) << "cmake --install failed:\n" << install.output; }

    static fs::path project() { return prefix / "share/lpvstudio/projects/cornell-box/cornell-box.lpvproj"; }
    static fs::path output(const std::string& name) {
        fs::create_directories(prefix.parent_path() / "install-output");
        return prefix.parent_path() / "install-output" / name;
    }
};

} // namespace

TEST_F(Installed, LaysOutProgramsAndTheSampleProject) {
    EXPECT_TRUE(fs::is_regular_file(prefix / "bin/lpv"));
    // The installed project is the committed one, every file of it.
    const fs::path source = fs::path(lpv::test::kSourceDir) / "projects/cornell-box";
    int files = 0;
    for (const auto& entry : fs::recursive_directory_iterator(source)) {
        if (!entry.is_regular_file())
            continue;
        const fs::path installed = project().parent_path() / fs::relative(entry.path(), source);
        ASSERT_TRUE(fs::is_regular_file(installed)) << installed;
        EXPECT_EQ(readText(installed), readText(entry.path())) << installed;
        ++files;
    }
    EXPECT_GE(files, 2) << "the project file and its mesh assets";
}

// Issue #28: the cluster job files come with the package, the scripts runnable.
TEST_F(Installed, LaysOutTheClusterJobFiles) {
    const fs::path source = fs::path(lpv::test::kSourceDir) / "packaging/cluster";
    const fs::path installed = prefix / "share/lpvstudio/cluster";
    int files = 0;
    for (const auto& entry : fs::directory_iterator(source)) {
        const fs::path copy = installed / entry.path().filename();
        ASSERT_TRUE(fs::is_regular_file(copy)) << copy;
        EXPECT_EQ(readText(copy), readText(entry.path())) << copy;
        const std::string ext = entry.path().extension().string();
        if (ext == ".sh" || ext == ".sbatch") {
            EXPECT_NE(fs::status(copy).permissions() & fs::perms::owner_exec, fs::perms::none) << copy;
        }
        ++files;
    }
    EXPECT_GE(files, 10) << "submit wrappers, batch scripts and manifests";
}

TEST_F(Installed, LpvReportsItsVersion) {
    const RunResult r = runShell(quoted(prefix / "bin/lpv") + " --version");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(r.output.rfind(std::string("lpv ") + LPV_TEST_PROJECT_VERSION + "\n", 0), 0u) << r.output;
    EXPECT_NE(r.output.find("\nrevision:  "), std::string::npos) << r.output;
}

TEST_F(Installed, LpvRendersTheInstalledCornellBox) {
    const fs::path png = output("cornell-box.png");
    fs::remove(png);
    const RunResult r = runShell(quoted(prefix / "bin/lpv") + " render " + quoted(project()) + " -o " +
                            quoted(png) + " --width 96 --height 96");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    ASSERT_TRUE(fs::is_regular_file(png)) << r.output;
    EXPECT_GT(fs::file_size(png), 0u);
    auto image = lpv::importers::readImage8(png);
    ASSERT_TRUE(image) << image.error().describe();
    EXPECT_EQ(image->width, 96);
    EXPECT_EQ(image->height, 96);
    long lit = 0;
    for (std::size_t i = 0; i + 2 < image->pixels.size(); i += std::size_t(image->channels))
        lit += image->pixels[i] + image->pixels[i + 1] + image->pixels[i + 2] > 60 ? 1 : 0;
    EXPECT_GT(lit, 96 * 96 / 4) << "the render is (nearly) black";
}

#if LPV_TEST_WITH_EDITOR
TEST_F(Installed, LaysOutTheDesktopIntegration) {
    const fs::path share = prefix / "share";
    EXPECT_TRUE(fs::is_regular_file(prefix / "bin/lpvstudio"));
    EXPECT_TRUE(fs::is_regular_file(share / "icons/hicolor/scalable/apps" / (kAppId + ".svg")));
    for (int size : {16, 22, 24, 32, 48, 64, 128, 256}) {
        const std::string dir = std::to_string(size) + "x" + std::to_string(size);
        auto icon = lpv::importers::readImage8(share / "icons/hicolor" / dir / "apps" / (kAppId + ".png"));
        ASSERT_TRUE(icon) << icon.error().describe();
        EXPECT_EQ(icon->width, size) << dir;
        EXPECT_EQ(icon->height, size) << dir;
    }

    // Double-clicking a project: the entry launches the installed editor with
    // the file, for the MIME type the MIME package declares.
    const std::string desktop = readText(share / "applications" / (kAppId + ".desktop"));
    EXPECT_NE(desktop.find("\nExec=lpvstudio %f\n"), std::string::npos) << desktop;
    EXPECT_NE(desktop.find("\nMimeType=application/x-lpvproj;\n"), std::string::npos) << desktop;
    EXPECT_NE(desktop.find("\nIcon=" + kAppId + "\n"), std::string::npos) << desktop;
    const std::string mime = readText(share / "mime/packages" / (kAppId + ".xml"));
    EXPECT_NE(mime.find("<mime-type type=\"application/x-lpvproj\">"), std::string::npos) << mime;
    EXPECT_NE(mime.find("<glob pattern=\"*.lpvproj\"/>"), std::string::npos) << mime;

    const std::string metainfo = readText(share / "metainfo" / (kAppId + ".metainfo.xml"));
    EXPECT_NE(metainfo.find("<id>" + kAppId + "</id>"), std::string::npos);
    EXPECT_NE(metainfo.find("<launchable type=\"desktop-id\">" + kAppId + ".desktop</launchable>"),
              std::string::npos);
    EXPECT_NE(metainfo.find(std::string("<release version=\"") + LPV_TEST_PROJECT_VERSION + "\""),
              std::string::npos)
        << "packaging/linux/" << kAppId << ".metainfo.xml needs a release entry for "
        << LPV_TEST_PROJECT_VERSION;
}

TEST_F(Installed, MimeDatabaseMapsProjectFilesToTheType) {
    if (std::string(LPV_TEST_UPDATE_MIME_DATABASE).empty())
        GTEST_SKIP() << "update-mime-database not found (package shared-mime-info)";
    // update-mime-database compiles the package into the lookup files desktops read.
    const fs::path mime = output("mime");
    fs::remove_all(mime);
    fs::copy(prefix / "share/mime", mime, fs::copy_options::recursive);
    const RunResult r = runShell(std::string(LPV_TEST_UPDATE_MIME_DATABASE) + " " + quoted(mime));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(readText(mime / "globs2").find("application/x-lpvproj:*.lpvproj"), std::string::npos)
        << readText(mime / "globs2");
}

TEST_F(Installed, EditorStartsOnTheInstalledProjectAndRendersIt) {
    const RunResult version =
        runShell("QT_QPA_PLATFORM=offscreen " + quoted(prefix / "bin/lpvstudio") + " --version");
    EXPECT_EQ(version.exitCode, 0) << version.output;
    EXPECT_NE(version.output.find(std::string("LPV Studio ") + LPV_TEST_PROJECT_VERSION), std::string::npos)
        << version.output;

    // Qt's offscreen platform has no OpenGL: a real window needs an X server (Xvfb).
    const RunResult r =
        runShell(std::string(LPV_TEST_XVFB_RUN) + " -a -s '-screen 0 1280x1024x24' env QT_QPA_PLATFORM=xcb " +
            quoted(prefix / "bin/lpvstudio") + " --quit-after 3000");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("showed " + project().string()), std::string::npos)
        << "the installed editor must open the installed project, not the source tree's:\n"
        << r.output;
    EXPECT_NE(r.output.find("rendered without error"), std::string::npos) << r.output;
}
#endif
