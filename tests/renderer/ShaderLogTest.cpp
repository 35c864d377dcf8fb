#include "lpv/renderer/ShaderLibrary.h"

#include <gtest/gtest.h>

using lpv::renderer::formatShaderLog;

TEST(ShaderLog, TranslatesMesaFormat) {
    EXPECT_EQ(formatShaderLog("0:12(5): error: `x' undeclared\n", "shaders/a.frag"),
              "shaders/a.frag:12: error: `x' undeclared\n");
}

TEST(ShaderLog, TranslatesNvidiaFormat) {
    EXPECT_EQ(formatShaderLog("0(7) : error C1008: undefined variable \"x\"\n", "shaders/b.vert"),
              "shaders/b.vert:7: error C1008: undefined variable \"x\"\n");
}

TEST(ShaderLog, KeepsUnrecognisedLinesWithFileName) {
    EXPECT_EQ(formatShaderLog("something odd", "s.comp"), "s.comp: something odd\n");
}

TEST(ShaderLog, NamesTheIncludedFileBySourceStringNumber) {
    EXPECT_EQ(formatShaderLog("1:3(2): error: bad\n0:9(1): error: worse\n",
                              std::vector<std::string>{"shaders/a.frag", "shaders/common.glsl"}),
              "shaders/common.glsl:3: error: bad\nshaders/a.frag:9: error: worse\n");
}

TEST(ShaderInclude, UnknownIncludeIsAnErrorNamingTheLine) {
    std::vector<std::string> names{"shaders/a.frag"};
    auto r = lpv::renderer::expandIncludes("#version 450 core\n#include \"nope.glsl\"\n", names);
    ASSERT_FALSE(r.has_value());
    EXPECT_NE(r.error().describe().find("shaders/a.frag:2"), std::string::npos) << r.error().describe();
    EXPECT_NE(r.error().describe().find("nope.glsl"), std::string::npos);
}

TEST(ShaderInclude, SourceWithoutIncludesIsUnchanged) {
    std::vector<std::string> names{"shaders/a.frag"};
    auto r = lpv::renderer::expandIncludes("#version 450 core\nvoid main() {}\n", names);
    ASSERT_TRUE(r.has_value());
    EXPECT_EQ(*r, "#version 450 core\nvoid main() {}\n");
    EXPECT_EQ(names.size(), 1u);
}
