// "A parameter that is not in the registry does not exist" (DESIGN.md): every
// key the code reads by name (params.get*("group.name")) is declared, and
// reading an undeclared key fails loudly in every build type.
#include "TestPaths.h"
#include "lpv/scene/ParameterRegistry.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>

namespace {

namespace fs = std::filesystem;
using lpv::scene::ParameterRegistry;
using lpv::scene::ParameterSet;

// Keys in calls such as getInt("lpv.gridSize") or .get("shadow.bias") across the product's sources.
std::map<std::string, std::string> keysReadByCode() {
    static const std::regex call(R"re(\bget(Bool|Int|Float|Enum)?\(\s*"([a-zA-Z]+\.[a-zA-Z0-9]+)"\s*\))re");
    std::map<std::string, std::string> keys; // key -> a file that reads it
    for (const char* dir : {"scene", "renderer", "importers", "radiosity", "reference", "bench", "video", "app"}) {
        const fs::path root = fs::path(lpv::test::kSourceDir) / dir;
        if (!fs::exists(root))
            continue;
        for (const auto& entry : fs::recursive_directory_iterator(root)) {
            const std::string ext = entry.path().extension().string();
            if (!entry.is_regular_file() || (ext != ".cpp" && ext != ".h"))
                continue;
            std::ifstream in(entry.path());
            std::stringstream text;
            text << in.rdbuf();
            const std::string source = text.str();
            for (std::sregex_iterator it(source.begin(), source.end(), call), end; it != end; ++it)
                keys.emplace((*it)[2].str(), fs::relative(entry.path(), lpv::test::kSourceDir).string());
        }
    }
    return keys;
}

TEST(ParameterKeysInCode, EveryKeyTheCodeReadsIsDeclared) {
    const auto keys = keysReadByCode();
    // The scan finds the renderer's reads; an empty result would mean it looked in the wrong place.
    ASSERT_GT(keys.size(), 40u);
    ASSERT_TRUE(keys.count("lpv.propagationSteps"));
    for (const auto& [key, file] : keys)
        EXPECT_NE(ParameterRegistry::instance().find(key), nullptr)
            << file << " reads '" << key << "', which ParameterDeclarations.cpp does not declare";
}

TEST(ParameterKeysInCode, ReadingAnUndeclaredKeyThrowsInEveryBuildType) {
    const ParameterSet params;
    EXPECT_THROW((void)params.getInt("lpv.gridSzie"), std::logic_error);
    EXPECT_THROW((void)params.get("no.such"), std::logic_error);
    try {
        (void)params.getFloat("lpv.cellSise");
    } catch (const std::logic_error& e) {
        EXPECT_NE(std::string(e.what()).find("lpv.cellSise"), std::string::npos) << e.what();
    }
    EXPECT_EQ(params.getInt("lpv.gridSize"), 32);
}

TEST(ParameterKeysInCode, EveryPassHasOneNameAndEveryFlagANamedPass) {
    std::set<std::string> names;
    for (lpv::scene::Pass p : lpv::scene::allPasses()) {
        const std::string name = lpv::scene::passName(p);
        EXPECT_FALSE(name.empty());
        EXPECT_TRUE(names.insert(name).second) << name << " names two passes";
    }
    for (const auto& info : ParameterRegistry::instance().all())
        for (std::uint32_t bit = 0; bit < 32; ++bit) {
            if (std::uint32_t(info.invalidates) & (1u << bit)) {
                EXPECT_FALSE(lpv::scene::passName(lpv::scene::Pass(1u << bit)).empty())
                    << info.key << " invalidates an unnamed pass bit " << bit;
            }
        }
}

} // namespace
