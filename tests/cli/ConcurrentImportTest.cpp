// Issue #42: two `lpv import` runs to the same -o at once. Before the
// project lock, 6 of 20 rounds left a project that did not load (one save's
// clean-up deleted the mesh assets the other's project file named) and 8
// more lost one import's content while both exited 0.
#include "RunLpv.h"

#include "lpv/scene/Project.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

using namespace lpv::test;
namespace fs = std::filesystem;

namespace {

// One triangle in an object named `name`, at height `z`.
fs::path writeTriangle(const fs::path& dir, const std::string& name, int z) {
    const fs::path file = dir / (name + ".obj");
    std::ofstream(file) << "o " << name << "\nv 0 0 " << z << "\nv 1 0 " << z << "\nv 0 1 " << z
                        << "\nf 1 2 3\n";
    return file;
}

bool hasObject(const lpv::scene::Project& p, const std::string& name) {
    for (const auto& o : p.scene.objects)
        if (o.name == name)
            return true;
    return false;
}

const std::string kLost = "was written by another process while this import ran; nothing was saved";

} // namespace

// Started together: they either take turns (both succeed, the second adds
// to the first's project) or one finds the project changed and says it
// lost; never a project that does not load, never a silent loss.
TEST(ConcurrentImport, TwoImportsToOneProjectEndWithOneCompleteProject) {
    const fs::path dir = freshBuildDir("cli-concurrent", "two-imports");
    const fs::path a = writeTriangle(dir, "alpha", 0);
    const fs::path b = writeTriangle(dir, "beta", 5);
    for (int round = 0; round < 5; ++round) {
        const fs::path out = dir / ("round" + std::to_string(round));
        fs::create_directories(out);
        const fs::path project = out / "p.lpvproj";
        auto start = [&](const fs::path& obj, const std::string& tag) {
            return "(" + std::string(kLpvExecutable) + " import " + quoted(obj) + " --no-sun -o " +
                   quoted(project) + " >" + quoted(out / (tag + ".log")) + " 2>&1; echo $? >" +
                   quoted(out / (tag + ".rc")) + ") & ";
        };
        ASSERT_EQ(std::system((start(a, "a") + start(b, "b") + "wait").c_str()), 0); // std::system runs sh
        const int rcA = std::stoi(readText(out / "a.rc"));
        const int rcB = std::stoi(readText(out / "b.rc"));
        const std::string logA = readText(out / "a.log"), logB = readText(out / "b.log");
        const auto loaded = lpv::scene::loadProject(project);
        ASSERT_TRUE(loaded) << "round " << round << ": " << loaded.error().describe() << "\n" << logA << logB;
        if (rcA == 0 && rcB == 0) {
            EXPECT_TRUE(hasObject(*loaded, "alpha") && hasObject(*loaded, "beta"))
                << "round " << round << ": both succeeded but one import's content is missing";
            continue;
        }
        ASSERT_TRUE((rcA == 0 && rcB == 1) || (rcA == 1 && rcB == 0)) << logA << logB;
        const std::string& loserLog = rcA == 1 ? logA : logB;
        EXPECT_NE(loserLog.find(kLost), std::string::npos) << loserLog;
        EXPECT_TRUE(hasObject(*loaded, rcA == 0 ? "alpha" : "beta")) << "round " << round;
        EXPECT_FALSE(hasObject(*loaded, rcA == 0 ? "beta" : "alpha")) << "round " << round;
        EXPECT_FALSE(fs::exists(out / ".p.lpvproj.lock"));
    }
}
