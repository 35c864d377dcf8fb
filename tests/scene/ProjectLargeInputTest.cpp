// Issue #29, hostile input: project files that are valid or nearly so but
// huge in one direction. Each must load (or fail with its error) in time
// linear in its size. The time bounds are hundreds of times what the linear
// code takes; the quadratic code they replaced took minutes.
#include "CpuTime.h"
#include "ProjectTestSupport.h"

#include "lpv/scene/Project.h"
#include "lpv/scene/WorldMatrices.h"

#include <gtest/gtest.h>

#include <cstring>
#include <iomanip>
#include <sstream>

using namespace lpv::scene;
using namespace lpv::test;
namespace fs = std::filesystem;

namespace {

// CPU seconds (CpuTime.h): linear work on these sizes takes well under one.
constexpr double kBoundSeconds = 5.0;

// Object i is object i-1's child, one unit further along x, and shows the quad.
Project parentChain(std::size_t n) {
    Project p;
    p.name = "chain";
    Material m;
    m.name = "m";
    p.scene.materials = {m};
    p.scene.meshes = {unitQuadMesh()};
    p.scene.objects.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        Object& o = p.scene.objects[i];
        o.name = "o" + std::to_string(i);
        o.mesh = 0;
        o.parent = int(i) - 1;
        o.transform.translation = {1, 0, 0};
    }
    return p;
}

std::string emptyProjectText(const std::string& parameters) {
    return R"({"format": "lpvstudio-project", "version": 2, "name": "p",
  "sky": {"color": [0.5, 0.7, 1.0], "intensity": 1.0},
  "materials": [], "meshes": [], "objects": [], "lights": [], "cameras": [], "cameraPaths": [],
  "parameters": {)" +
           parameters + "}}\n";
}

std::string jsonText(const ParameterValue& v) {
    if (const bool* b = std::get_if<bool>(&v))
        return *b ? "true" : "false";
    if (const int* i = std::get_if<int>(&v))
        return std::to_string(*i);
    if (const double* d = std::get_if<double>(&v)) {
        std::ostringstream out;
        out << std::setprecision(17) << *d;
        return out.str();
    }
    return "\"" + std::get<std::string>(v) + "\"";
}

class ProjectLargeInput : public TempDirTest {
protected:
    ProjectLargeInput() : TempDirTest("lpv-large-") {}
};

} // namespace

// World matrices used to walk each object's chain to the root: a chain of
// 100,000 objects took 178 s to load and show (`lpv info`). Now one pass.
TEST_F(ProjectLargeInput, ParentChainOf100000ObjectsLoadsWithItsWorldBoundsInLinearTime) {
    constexpr std::size_t kCount = 100000;
    const fs::path file = dir_ / "chain.lpvproj";
    ASSERT_TRUE(saveProject(parentChain(kCount), file));
    const auto loaded = loadProject(file);
    ASSERT_TRUE(loaded) << loaded.error().message;
    ASSERT_EQ(loaded->scene.objects.size(), kCount);
    EXPECT_EQ(loaded->scene.objects.back().parent, int(kCount) - 2);

    const double start = processCpuSeconds();
    const Bounds bounds = loaded->scene.worldBounds();
    const std::vector<glm::mat4> world = worldMatrices(loaded->scene);
    EXPECT_LT(processCpuSeconds() - start, kBoundSeconds);
    // Object i sits at x = i + 1, its quad reaching to i + 2 (exact in float).
    EXPECT_EQ(bounds.min, glm::vec3(1, 0, 0));
    EXPECT_EQ(bounds.max, glm::vec3(float(kCount) + 1.0f, 1, 0));
    ASSERT_EQ(world.size(), kCount);
    EXPECT_EQ(world.back()[3], glm::vec4(float(kCount), 0, 0, 1));
    EXPECT_EQ(world.back(), loaded->scene.worldMatrix(int(kCount) - 1));
}

// The one-pass matrices are the per-object ones bit for bit, whatever the
// order of parents and children in the list and however the transforms round.
TEST(WorldMatrices, EqualWorldMatrixBitForBitInAnyParentOrder) {
    Scene s;
    s.objects.resize(40);
    for (std::size_t i = 0; i < s.objects.size(); ++i) {
        Object& o = s.objects[i];
        // Parents before and after their children, several roots, chains of several levels.
        o.parent = i % 7 == 0 ? -1 : int(((i * 2654435761u) >> 7) % i);
        const float f = float(i) * 0.37f;
        o.transform.translation = {f, -0.3f * f, 1.0f / (f + 1.0f)};
        o.transform.rotation = glm::normalize(glm::quat(0.9f, 0.1f * f, -0.2f, 0.05f * f));
        o.transform.scale = {1.1f, 0.7f + 0.01f * f, 1.3f};
    }
    // Forward references: object 3's parent comes later in the list.
    s.objects[3].parent = 30;
    s.objects[30].parent = 35;
    s.objects[35].parent = -1;
    const std::vector<glm::mat4> world = worldMatrices(s);
    ASSERT_EQ(world.size(), s.objects.size());
    for (std::size_t i = 0; i < s.objects.size(); ++i) {
        const glm::mat4 one = s.worldMatrix(int(i));
        EXPECT_EQ(std::memcmp(&world[i], &one, sizeof one), 0) << "object " << i;
    }
    const glm::mat4 three =
        s.objects[35].transform.matrix() * s.objects[30].transform.matrix() * s.objects[3].transform.matrix();
    EXPECT_EQ(world[3], three);
}

// A scene the loader would refuse still cannot hang either function.
TEST(WorldMatrices, CyclicChainEndsWhereItCloses) {
    Scene s;
    s.objects.resize(3);
    s.objects[0].parent = 2;
    s.objects[1].parent = 0;
    s.objects[2].parent = 1;
    for (Object& o : s.objects)
        o.transform.translation = {1, 0, 0};
    const std::vector<glm::mat4> world = worldMatrices(s);
    ASSERT_EQ(world.size(), 3u);
    for (const glm::mat4& m : world)
        EXPECT_TRUE(std::isfinite(m[3].x));
    EXPECT_EQ(world[1][3], glm::vec4(1, 0, 0, 1)); // 0 -> 2 -> 1 -> (0): cut before 0 comes round again
    EXPECT_EQ(world[0][3], glm::vec4(3, 0, 0, 1));
    EXPECT_TRUE(std::isfinite(s.worldMatrix(0)[3].x));
}

// The cycle check is linear too, and a loop of 100,000 objects is named by
// its ends and length (it was listed in full: a 700 KB message).
TEST_F(ProjectLargeInput, ParentCycleOf100000ObjectsIsInvalidValueNamedByItsEnds) {
    constexpr std::size_t kCount = 100000;
    const fs::path file = dir_ / "cycle.lpvproj";
    ASSERT_TRUE(saveProject(parentChain(kCount), file));
    std::string text = readFile(file);
    const std::string first = "\"parent\": -1";
    const std::size_t at = text.find(first);
    ASSERT_NE(at, std::string::npos);
    text.replace(at, first.size(), "\"parent\": " + std::to_string(kCount - 1));
    writeFile(file, text);

    const double start = processCpuSeconds();
    const auto loaded = loadProject(file);
    EXPECT_LT(processCpuSeconds() - start, kBoundSeconds);
    ASSERT_FALSE(loaded);
    EXPECT_EQ(loaded.error().code, ErrorCode::InvalidValue);
    EXPECT_EQ(loaded.error().location, "objects[0].parent");
    EXPECT_EQ(
        loaded.error().message,
        "object \"o0\" is its own ancestor (parent chain 0 -> 99999 -> 99998 -> 99997 -> 99996 -> 99995 -> "
        "99994 -> 99993 -> ... -> 2 -> 1 -> 0: a loop of 100000 objects)");
}

// nlohmann's ordered map finds each key by a linear search, so parsing an
// object of N keys compared N^2/2 strings: 100,000 unknown parameter keys
// took 6.9 s before the loader named the first. 200,000 here (the quadratic
// parser: about 30 s).
TEST_F(ProjectLargeInput, TwoHundredThousandUnknownParameterKeysFailFastNamingTheFirst) {
    std::string parameters;
    for (int i = 0; i < 200000; ++i)
        parameters += (i ? ", \"junk.key" : "\"junk.key") + std::to_string(i) + "\": 1";
    const fs::path file = dir_ / "keys.lpvproj";
    writeFile(file, emptyProjectText(parameters));

    const double start = processCpuSeconds();
    const auto loaded = loadProject(file);
    EXPECT_LT(processCpuSeconds() - start, kBoundSeconds);
    ASSERT_FALSE(loaded);
    EXPECT_EQ(loaded.error().code, ErrorCode::UnknownParameter);
    EXPECT_EQ(loaded.error().location, "parameters.junk.key0");
    EXPECT_EQ(loaded.error().message, "unknown parameter 'junk.key0' (see `lpv params`)");
}

// Fields the format does not know are ignored, however many: 200,000 of them
// in one material load as fast.
TEST_F(ProjectLargeInput, TwoHundredThousandUnknownFieldsInAMaterialAreIgnoredFast) {
    Project p;
    p.name = "p";
    Material m;
    m.name = "m";
    p.scene.materials = {m};
    const fs::path file = dir_ / "fields.lpvproj";
    ASSERT_TRUE(saveProject(p, file));
    std::string junk;
    for (int i = 0; i < 200000; ++i)
        junk += "\"junk" + std::to_string(i) + "\": [1, 2], ";
    std::string text = readFile(file);
    const std::size_t at = text.find("\"name\": \"m\"");
    ASSERT_NE(at, std::string::npos);
    text.insert(at, junk);
    writeFile(file, text);

    const double start = processCpuSeconds();
    const auto loaded = loadProject(file);
    EXPECT_LT(processCpuSeconds() - start, kBoundSeconds);
    ASSERT_TRUE(loaded) << loaded.error().message;
    EXPECT_EQ(loaded->scene.materials, p.scene.materials);
}

// A key written twice keeps its last value, in a small object (linear
// search) and in a large one (hash index) alike, as nlohmann's parser did.
TEST_F(ProjectLargeInput, RepeatedKeyKeepsItsLastValueInSmallAndLargeObjects) {
    std::string few = "\"lpv.intensity\": 1.5, \"lpv.intensity\": 2.5";
    // More keys than the builder searches one by one, each at its default.
    std::string many = "\"lpv.intensity\": 1.5, ";
    std::size_t n = 0;
    for (const ParameterInfo& info : ParameterRegistry::instance().all()) {
        if (info.key == "lpv.intensity" || n == 30)
            continue;
        many += "\"" + info.key + "\": " + jsonText(info.defaultValue) + ", ";
        ++n;
    }
    ASSERT_EQ(n, 30u) << "the registry has fewer than 31 parameters";
    many += "\"lpv.intensity\": 2.5";
    for (const std::string& parameters : {few, many}) {
        const fs::path file = dir_ / "repeated.lpvproj";
        writeFile(file, emptyProjectText(parameters));
        const auto loaded = loadProject(file);
        ASSERT_TRUE(loaded) << loaded.error().message;
        EXPECT_EQ(loaded->parameters.getFloat("lpv.intensity"), 2.5f);
    }
}
