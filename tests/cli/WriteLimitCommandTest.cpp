// Issue #42: no write that a read refuses. An import of more materials than
// a project holds is refused before Assimp parses the library (1,000,000 of
// them reached 5.4 GiB; 60,000 imported in a minute and wrote a project
// that would not load).
#include "RunLpv.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

using namespace lpv::test;
namespace fs = std::filesystem;

namespace {

// An OBJ of one triangle whose library defines `materials` materials.
fs::path writeObjWithMaterials(const fs::path& dir, int materials) {
    std::ofstream mtl(dir / "many.mtl");
    for (int i = 0; i < materials; ++i)
        mtl << "newmtl m" << i << "\nKd 0.5 0.5 0.5\n";
    std::ofstream(dir / "many.obj") << "mtllib many.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl m0\nf 1 2 3\n";
    return dir / "many.obj";
}

} // namespace

TEST(WriteLimitCommand, AnImportOfMoreMaterialsThanAProjectHoldsIsRefused) {
    const fs::path dir = freshBuildDir("cli-write-limits", "materials");
    // With the default material Assimp adds, one more than a project holds.
    const fs::path obj = writeObjWithMaterials(dir, 16384);
    const RunResult r = runLpv("import " + quoted(obj) + " --no-sun -o " + quoted(dir / "out" / "p.lpvproj"));
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find(obj.string() + ": materials: material library '"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("many.mtl' brings the materials to 16385, more than a project can hold (16384); "
                            "refused before parsing it"),
              std::string::npos)
        << r.output;
    EXPECT_FALSE(fs::exists(dir / "out" / "p.lpvproj"));
}

TEST(WriteLimitCommand, AnImportOfAsManyMaterialsAsAProjectHoldsImportsAndLoads) {
    const fs::path dir = freshBuildDir("cli-write-limits", "materials-at-limit");
    const fs::path obj = writeObjWithMaterials(dir, 16383);
    const fs::path project = dir / "p.lpvproj";
    const RunResult r = runLpv("import " + quoted(obj) + " --no-sun -o " + quoted(project));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const RunResult info = runLpv("info " + quoted(project));
    EXPECT_EQ(info.exitCode, 0) << info.output;
}
