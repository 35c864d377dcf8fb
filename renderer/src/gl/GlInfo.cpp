// The platform-independent part of lpv/renderer/GlContext.h: what the current
// context is, and GL debug output. Works on any context (headless or Qt's).
#include "lpv/renderer/GlContext.h"

#include <epoxy/gl.h>

#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <string_view>

namespace lpv::renderer {

namespace {

std::mutex& sinkMutex() {
    static std::mutex m;
    return m;
}

GlDebugSink& sink() {
    static GlDebugSink s;
    return s;
}

void GLAPIENTRY printDebugMessage(GLenum, GLenum type, GLuint, GLenum severity, GLsizei,
                                  const GLchar* message, const void*) {
    if (severity == GL_DEBUG_SEVERITY_NOTIFICATION)
        return;
    const bool error = type == GL_DEBUG_TYPE_ERROR;
    {
        std::lock_guard lock(sinkMutex());
        if (sink()) {
            sink()(error, message);
            return;
        }
    }
    std::fprintf(stderr, "GL %s: %s\n", error ? "error" : "warning", message);
}

} // namespace

void setGlDebugSink(GlDebugSink newSink) {
    std::lock_guard lock(sinkMutex());
    sink() = std::move(newSink);
}

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
