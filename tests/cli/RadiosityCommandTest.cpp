// `lpv radiosity` as a user runs it, on a temporary copy of the Cornell box
// with coarse patches: solve, save, resume, image.
#include "RunLpv.h"

#include <gtest/gtest.h>

#include <filesystem>

using namespace lpv::test;
namespace fs = std::filesystem;

namespace {

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

} // namespace

TEST(RadiosityCommand, SolvesSavesAndResumesTheCornellBox) {
    const fs::path dir = fs::path(kBinaryDir) / "tests" / "cli-radiosity";
    fs::remove_all(dir);
    fs::create_directories(dir);
    const fs::path solved = dir / "solved.lpvproj";
    const std::string coarse = " --set radiosity.maxPatchArea=0.5 --set radiosity.hemicubeResolution=32";

    auto first = runLpv("radiosity " + cornellProject() + coarse + " --residual 0.3 -o " + solved.string() +
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
    EXPECT_TRUE(contains(r.output, "--residual must be in (0, 1]")) << r.output;
    auto v = runLpv("radiosity " + cornellProject() + " --view sideways");
    EXPECT_EQ(v.exitCode, 2) << v.output;
}
