// The install list proven complete (issue #29): every system header and
// library this build read belongs to a Debian package that scripts/setup.sh
// installs or pulls in. The check itself is tests/install/check-install-list.sh
// (run it by hand to see which package is missing); these tests run it on this
// build, and once with a needed package left out to show that it can fail.
#include "TestFiles.h"
#include "TestPaths.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <sys/wait.h>

using namespace lpv::test;

namespace {

std::string checkCommand(const std::string& extra) {
    return "'" + std::string(lpv::test::kSourceDir) + "/tests/install/check-install-list.sh' '" +
           lpv::test::kBinaryDir + "' " + extra;
}

bool haveDebianTools() {
    return std::system("command -v dpkg-query >/dev/null && command -v apt-cache >/dev/null") == 0;
}

} // namespace

TEST(InstallList, EverySystemFileTheBuildReadComesFromAListedPackage) {
    if (!haveDebianTools())
        GTEST_SKIP() << "not a Debian system (no dpkg-query/apt-cache): the install list is Debian's";
    const RunResult r = runShell(checkCommand(""));
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("system files checked"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("MISSING PACKAGE"), std::string::npos) << r.output;
}

// zlib1g-dev was the package missing on a fresh Debian 12 (Assimp's CMake
// config links libz.so, libassimp-dev does not depend on zlib1g-dev): without
// it in the list the check must fail and name it.
TEST(InstallList, FailsNamingAPackageLeftOutOfTheList) {
    if (!haveDebianTools())
        GTEST_SKIP() << "not a Debian system (no dpkg-query/apt-cache): the install list is Debian's";
    const RunResult r = runShell(checkCommand("--without zlib1g-dev"));
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("MISSING PACKAGE zlib1g-dev:"), std::string::npos) << r.output;
    // It names one of the package's files the build read: the library Assimp
    // links, or zlib's headers (the image-budget test reads them too).
    const bool namesAZlibFile = r.output.find("libz.so") != std::string::npos ||
                                r.output.find("/usr/include/zconf.h") != std::string::npos ||
                                r.output.find("/usr/include/zlib.h") != std::string::npos;
    EXPECT_TRUE(namesAZlibFile) << r.output;
}

namespace {

std::string setupCommand(const std::string& osRelease) {
    return "LPV_OS_RELEASE='" + osRelease + "' '" + std::string(lpv::test::kSourceDir) +
           "/scripts/setup.sh' --print-packages";
}

std::string writeOsRelease(const std::string& name, const std::string& text) {
    const std::string path = std::string(lpv::test::kBinaryDir) + "/os-release-" + name;
    FILE* f = std::fopen(path.c_str(), "w");
    if (f) {
        std::fputs(text.c_str(), f);
        std::fclose(f);
    }
    return path;
}

bool listed(const std::string& list, const std::string& package) {
    return ("\n" + list).find("\n" + package + "\n") != std::string::npos;
}

} // namespace

// Debian 12 ships Qt's OpenGL headers as libqt6opengl6-dev; on Debian 13 they
// are in qt6-base-dev, which only provides that name (issue #49). setup.sh
// lists the real package of the release /etc/os-release names.
TEST(InstallList, SetupChoosesPackageNamesByRelease) {
    const RunResult bookworm =
        runShell(setupCommand(writeOsRelease("bookworm", "ID=debian\nVERSION_ID=\"12\"\nVERSION_CODENAME=bookworm\n")));
    ASSERT_EQ(bookworm.exitCode, 0) << bookworm.output;
    EXPECT_TRUE(listed(bookworm.output, "libqt6opengl6-dev")) << bookworm.output;
    EXPECT_TRUE(listed(bookworm.output, "qt6-base-dev")) << bookworm.output;

    const RunResult trixie =
        runShell(setupCommand(writeOsRelease("trixie", "ID=debian\nVERSION_ID=\"13\"\nVERSION_CODENAME=trixie\n")));
    ASSERT_EQ(trixie.exitCode, 0) << trixie.output;
    EXPECT_FALSE(listed(trixie.output, "libqt6opengl6-dev")) << trixie.output;
    EXPECT_TRUE(listed(trixie.output, "qt6-base-dev")) << trixie.output;

    // Another system gets a warning that says what is assumed, and still a list.
    const RunResult other = runShell(setupCommand(writeOsRelease("other", "ID=arch\n")));
    ASSERT_EQ(other.exitCode, 0) << other.output;
    EXPECT_NE(other.output.find("knows Debian 12 (bookworm) and 13 (trixie)"), std::string::npos) << other.output;
    EXPECT_TRUE(listed(other.output, "qt6-base-dev")) << other.output;
}

// Every name setup.sh lists for this machine's release is a package installed
// under that name: a name another package only provides would never count as
// installed, and setup.sh would run apt-get on every build.
TEST(InstallList, EveryPackageListedForThisReleaseIsInstalledUnderItsName) {
    if (!haveDebianTools())
        GTEST_SKIP() << "not a Debian system (no dpkg-query/apt-cache): the install list is Debian's";
    const RunResult list = runShell("'" + std::string(lpv::test::kSourceDir) + "/scripts/setup.sh' --print-packages");
    ASSERT_EQ(list.exitCode, 0) << list.output;
    std::size_t checked = 0;
    std::size_t start = 0;
    while (start < list.output.size()) {
        const std::size_t end = list.output.find('\n', start);
        const std::string package = list.output.substr(start, end - start);
        start = end == std::string::npos ? list.output.size() : end + 1;
        if (package.empty() || package.starts_with("=="))
            continue;
        const RunResult status = runShell("dpkg-query -W -f='${Status}' " + package);
        EXPECT_NE(status.output.find("install ok installed"), std::string::npos)
            << package << " is listed by scripts/setup.sh but not installed under that name: " << status.output;
        ++checked;
    }
    EXPECT_GT(checked, 30u);
}
