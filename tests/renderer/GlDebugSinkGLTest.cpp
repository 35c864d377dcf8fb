// GL debug messages go to a sink when one is set (the editor's Log dock,
// issue #26 item 5), and to stderr again when it is removed.
#include "lpv/renderer/GlContext.h"

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

using namespace lpv::renderer;

TEST(GlDebugSink, AMessageOfTheContextReachesTheSinkThenStderrAgain) {
    ::setenv("LPV_GL_DEBUG", "1", 1); // release builds turn debug output on only when asked
    auto context = HeadlessContext::create();
    ::unsetenv("LPV_GL_DEBUG");
    ASSERT_TRUE(context) << context.error().describe();
    std::vector<std::pair<bool, std::string>> got;
    setGlDebugSink([&](bool error, const std::string& message) { got.emplace_back(error, message); });
    glDebugMessageInsert(GL_DEBUG_SOURCE_APPLICATION, GL_DEBUG_TYPE_ERROR, 7, GL_DEBUG_SEVERITY_HIGH, -1,
                         "lpv sink test: an error");
    glDebugMessageInsert(GL_DEBUG_SOURCE_APPLICATION, GL_DEBUG_TYPE_PERFORMANCE, 8, GL_DEBUG_SEVERITY_MEDIUM, -1,
                         "lpv sink test: a warning");
    glDebugMessageInsert(GL_DEBUG_SOURCE_APPLICATION, GL_DEBUG_TYPE_OTHER, 9, GL_DEBUG_SEVERITY_NOTIFICATION, -1,
                         "lpv sink test: a notification");
    glFinish();
    ASSERT_EQ(got.size(), 2u) << "errors and warnings, not notifications";
    EXPECT_TRUE(got[0].first);
    EXPECT_EQ(got[0].second, "lpv sink test: an error");
    EXPECT_FALSE(got[1].first);
    EXPECT_EQ(got[1].second, "lpv sink test: a warning");

    setGlDebugSink({});
    glDebugMessageInsert(GL_DEBUG_SOURCE_APPLICATION, GL_DEBUG_TYPE_ERROR, 10, GL_DEBUG_SEVERITY_HIGH, -1,
                         "lpv sink test: to stderr");
    glFinish();
    EXPECT_EQ(got.size(), 2u) << "a removed sink hears nothing";
}
