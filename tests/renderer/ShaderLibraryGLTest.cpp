#include "GlFixture.h"

#include "lpv/renderer/ShaderLibrary.h"

using namespace lpv::renderer;

class ShaderLibrary : public GlTest {};

TEST_F(ShaderLibrary, EveryEmbeddedStageCompiles) {
    const auto names = embeddedShaderNames();
    ASSERT_FALSE(names.empty());
    for (const std::string& name : names) {
        if (name.ends_with(".glsl"))
            continue; // include snippets are compiled as part of their users
        auto program = buildEmbeddedProgram({name});
        // A lone stage links only for compute; what we check is that it compiles.
        if (!program) {
            EXPECT_EQ(program.error().location, "link") << program.error().describe();
        }
    }
}

TEST_F(ShaderLibrary, CompileErrorNamesFileAndLine) {
    const std::string src = "#version 450 core\nout vec4 c;\nvoid main() {\n  c = vec4(undefinedThing);\n}\n";
    auto program = buildProgram({{GL_FRAGMENT_SHADER, "shaders/broken.frag", src}});
    ASSERT_FALSE(program.has_value());
    EXPECT_EQ(program.error().file, "shaders/broken.frag");
    EXPECT_NE(program.error().message.find("shaders/broken.frag:4:"), std::string::npos) << program.error().message;
}

TEST_F(ShaderLibrary, MissingEmbeddedShaderIsAnError) {
    auto program = buildEmbeddedProgram({"nope.frag"});
    ASSERT_FALSE(program.has_value());
    EXPECT_EQ(program.error().code, lpv::scene::ErrorCode::MissingAsset);
}

TEST_F(ShaderLibrary, DefinesAreInsertedAndErrorsKeepTheFilesLineNumbers) {
    // shadow.geom sizes its invocations from SHADOW_LAYERS; a bad value must
    // fail to compile and the message must still name shadow.geom.
    auto good = buildEmbeddedProgram({"shadow.vert", "shadow.geom", "shadow.frag"}, {"SHADOW_LAYERS 3"});
    EXPECT_TRUE(good.has_value()) << good.error().describe();
    auto bad = buildEmbeddedProgram({"shadow.vert", "shadow.geom", "shadow.frag"}, {"SHADOW_LAYERS banana"});
    ASSERT_FALSE(bad.has_value());
    EXPECT_NE(bad.error().describe().find("shaders/shadow.geom"), std::string::npos) << bad.error().describe();
}
