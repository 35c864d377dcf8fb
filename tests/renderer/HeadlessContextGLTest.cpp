// HeadlessContext owns its EGL display only in part: EGL hands every caller
// the same display for a platform, and eglTerminate ends it for all of them.
#include "lpv/renderer/GlContext.h"

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <optional>

using lpv::renderer::HeadlessContext;

namespace {

// A GL call that needs a live context: clear a texture and read it back.
float clearAndReadBack(float value) {
    GLuint texture = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &texture);
    glTextureStorage2D(texture, 1, GL_RGBA32F, 1, 1);
    const float colour[4] = {value, value, value, 1.0f};
    glClearTexImage(texture, 0, GL_RGBA, GL_FLOAT, colour);
    float out[4] = {};
    glGetTextureImage(texture, 0, GL_RGBA, GL_FLOAT, sizeof(out), out);
    glDeleteTextures(1, &texture);
    return out[0];
}

} // namespace

// Two contexts in one process (the editor's offscreen jobs, a CLI command that
// renders twice): closing the first must leave the second usable.
TEST(HeadlessContextGLTest, ClosingOneContextLeavesAnotherOnTheSameDisplayUsable) {
    auto first = HeadlessContext::create();
    ASSERT_TRUE(first.has_value()) << first.error().describe();
    std::optional<HeadlessContext> firstContext(std::move(*first));
    auto second = HeadlessContext::create();
    ASSERT_TRUE(second.has_value()) << second.error().describe();
    EXPECT_EQ(clearAndReadBack(0.25f), 0.25f);

    firstContext.reset();
    ASSERT_TRUE(second->makeCurrent()) << "the display was terminated under the second context";
    EXPECT_EQ(clearAndReadBack(0.75f), 0.75f);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));

    // And a context made after both others is fine too.
    auto third = HeadlessContext::create();
    ASSERT_TRUE(third.has_value()) << third.error().describe();
    EXPECT_EQ(clearAndReadBack(0.5f), 0.5f);
}
