// Platform file: the headless context through EGL (Linux and other EGL
// systems). Windows and macOS build GlContextUnsupported.cpp instead; see
// docs/portability.md.
#include "lpv/renderer/GlContext.h"


#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <cstdlib>
#include <map>
#include <mutex>
#include <string_view>
#include <vector>

namespace lpv::renderer {

using scene::ErrorCode;
using scene::makeError;

struct HeadlessContext::State {
    EGLDisplay display = EGL_NO_DISPLAY;
    EGLContext context = EGL_NO_CONTEXT;
};

namespace {

// EGL hands every caller the same display for a platform, and eglTerminate
// ends it for all of them: the contexts on each display are counted, and the
// last one to close terminates it.
std::mutex displayMutex;
std::map<EGLDisplay, int> contextsOnDisplay;

void retainDisplay(EGLDisplay display) {
    const std::lock_guard lock(displayMutex);
    ++contextsOnDisplay[display];
}

void releaseDisplay(EGLDisplay display) {
    const std::lock_guard lock(displayMutex);
    auto it = contextsOnDisplay.find(display);
    if (it != contextsOnDisplay.end() && --it->second > 0)
        return;
    if (it != contextsOnDisplay.end())
        contextsOnDisplay.erase(it);
    eglTerminate(display);
}

// A display that could not make a context is terminated unless another context uses it.
void terminateIfUnused(EGLDisplay display) {
    const std::lock_guard lock(displayMutex);
    if (!contextsOnDisplay.contains(display))
        eglTerminate(display);
}

bool hasExtension(const char* list, std::string_view ext) {
    if (!list)
        return false;
    std::string_view all(list);
    for (std::size_t pos = 0; (pos = all.find(ext, pos)) != std::string_view::npos; pos += ext.size()) {
        const bool startOk = pos == 0 || all[pos - 1] == ' ';
        const bool endOk = pos + ext.size() == all.size() || all[pos + ext.size()] == ' ';
        if (startOk && endOk)
            return true;
    }
    return false;
}

// Tries to bring up a 4.5 core context on `display`; leaves it current on success.
EGLContext createCoreContext(EGLDisplay display) {
    EGLint major = 0, minor = 0;
    if (!eglInitialize(display, &major, &minor))
        return EGL_NO_CONTEXT;
    if (!eglBindAPI(EGL_OPENGL_API))
        return EGL_NO_CONTEXT;
    const EGLint configAttribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint count = 0;
    // Surfaceless contexts need no config on Mesa; NVIDIA wants one.
    eglChooseConfig(display, configAttribs, &config, 1, &count);
    const EGLint ctxAttribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                                 EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                 EGL_CONTEXT_OPENGL_DEBUG, glDebugOutputRequested() ? EGL_TRUE : EGL_FALSE, EGL_NONE};
    EGLContext ctx = eglCreateContext(display, count > 0 ? config : EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, ctxAttribs);
    if (ctx == EGL_NO_CONTEXT)
        return EGL_NO_CONTEXT;
    if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx)) {
        eglDestroyContext(display, ctx);
        return EGL_NO_CONTEXT;
    }
    return ctx;
}

std::vector<EGLDisplay> deviceDisplays() {
    std::vector<EGLDisplay> out;
    const char* clientExts = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!hasExtension(clientExts, "EGL_EXT_device_enumeration") || !hasExtension(clientExts, "EGL_EXT_platform_device"))
        return out;
    EGLDeviceEXT devices[16];
    EGLint n = 0;
    if (!eglQueryDevicesEXT(16, devices, &n))
        return out;
    // Hardware first (issue #45): where the NVIDIA driver and Mesa are both
    // installed, GLVND lists every vendor's devices, Mesa's software
    // rasteriser among them (EGL_MESA_device_software), in vendor order.
    const bool canQuery = hasExtension(clientExts, "EGL_EXT_device_query");
    std::vector<EGLDisplay> software;
    for (EGLint i = 0; i < n; ++i) {
        EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
        if (d == EGL_NO_DISPLAY)
            continue;
        const char* deviceExts = canQuery ? eglQueryDeviceStringEXT(devices[i], EGL_EXTENSIONS) : nullptr;
        (deviceExts && hasExtension(deviceExts, "EGL_MESA_device_software") ? software : out).push_back(d);
    }
    out.insert(out.end(), software.begin(), software.end());
    return out;
}

} // namespace

HeadlessContext::HeadlessContext() : state_(std::make_unique<State>()) {}
HeadlessContext::HeadlessContext(HeadlessContext&&) noexcept = default;
HeadlessContext& HeadlessContext::operator=(HeadlessContext&&) noexcept = default;

HeadlessContext::~HeadlessContext() {
    if (state_ && state_->context != EGL_NO_CONTEXT) {
        eglMakeCurrent(state_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(state_->display, state_->context);
        releaseDisplay(state_->display);
    }
}

bool HeadlessContext::makeCurrent() {
    return eglMakeCurrent(state_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, state_->context) == EGL_TRUE;
}

Expected<HeadlessContext> HeadlessContext::create() {
    const char* forced = std::getenv("LPV_EGL_PLATFORM");
    const std::string_view want = forced ? forced : "";
    const char* clientExts = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);

    struct Candidate {
        EGLDisplay display;
        const char* platform;
    };
    std::vector<Candidate> candidates;
    // A real GPU is found by enumerating EGL devices (NVIDIA's path). Mesa
    // lists a software device there too, so surfaceless comes second only as a fallback.
    if (want.empty() || want == "device")
        for (EGLDisplay d : deviceDisplays())
            candidates.push_back({d, "device"});
    if ((want.empty() || want == "surfaceless") && hasExtension(clientExts, "EGL_MESA_platform_surfaceless"))
        candidates.push_back(
            {eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr), "surfaceless"});
    if (want.empty() || want == "default")
        candidates.push_back({eglGetDisplay(EGL_DEFAULT_DISPLAY), "default"});

    for (const Candidate& c : candidates) {
        if (c.display == EGL_NO_DISPLAY)
            continue;
        EGLContext ctx = createCoreContext(c.display);
        if (ctx == EGL_NO_CONTEXT) {
            terminateIfUnused(c.display);
            continue;
        }
        retainDisplay(c.display);
        HeadlessContext out;
        out.state_->display = c.display;
        out.state_->context = ctx;
        out.info_ = queryCurrentGlInfo();
        out.info_.eglPlatform = c.platform;
        installDebugOutputIfRequested();
        return out;
    }
    return makeError(ErrorCode::IoError, "EGL", want.empty() ? "" : "LPV_EGL_PLATFORM=" + std::string(want),
                     "no EGL display could create an OpenGL 4.5 core context (is Mesa's libegl-mesa0 or the NVIDIA "
                     "driver installed?)");
}

} // namespace lpv::renderer

namespace lpv::renderer {

std::optional<GpuMemoryInfo> queryGpuMemory() {
    // Enum values from the extension specifications.
    constexpr GLenum kNvxTotalAvailableKiB = 0x9048, kNvxCurrentAvailableKiB = 0x9049;
    constexpr GLenum kAtiTextureFreeMemory = 0x87FC;
    if (epoxy_has_gl_extension("GL_NVX_gpu_memory_info")) {
        GLint total = 0, available = 0;
        glGetIntegerv(kNvxTotalAvailableKiB, &total);
        glGetIntegerv(kNvxCurrentAvailableKiB, &available);
        return GpuMemoryInfo{total / 1024.0, available / 1024.0};
    }
    if (epoxy_has_gl_extension("GL_ATI_meminfo")) {
        GLint free[4] = {};
        glGetIntegerv(kAtiTextureFreeMemory, free);
        return GpuMemoryInfo{0.0, free[0] / 1024.0};
    }
    return std::nullopt;
}

} // namespace lpv::renderer
