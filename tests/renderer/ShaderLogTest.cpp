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
