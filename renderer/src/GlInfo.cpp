// The platform-independent part of lpv/renderer/GlContext.h: what the current
// context is, and GL debug output. Works on any context (headless or Qt's).
#include "GlDebug.h"
#include "lpv/renderer/GlContext.h"

#include <epoxy/gl.h>

#include <cstdio>
#include <cstdlib>
#include <string_view>

namespace lpv::renderer {

namespace {

void GLAPIENTRY printDebugMessage(GLenum, GLenum type, GLuint, GLenum severity, GLsizei,
                                  const GLchar* message, const void*) {
    if (severity == GL_DEBUG_SEVERITY_NOTIFICATION)
        return;
    std::fprintf(stderr, "GL %s: %s\n", type == GL_DEBUG_TYPE_ERROR ? "error" : "warning", message);
}

} // namespace

bool glDebugOutputRequested() {
#ifndef NDEBUG
    return true;
#else
    const char* env = std::getenv("LPV_GL_DEBUG");
    return env && std::string_view(env) == "1";
#endif
}

void installDebugOutputIfRequested() {
    if (!glDebugOutputRequested())
        return;
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(printDebugMessage, nullptr);
}

GlInfo queryCurrentGlInfo() {
    auto str = [](GLenum e) {
        const GLubyte* s = glGetString(e);
        return s ? std::string(reinterpret_cast<const char*>(s)) : std::string();
    };
    return GlInfo{str(GL_VENDOR), str(GL_RENDERER), str(GL_VERSION), ""};
}

} // namespace lpv::renderer
