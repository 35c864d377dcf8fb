#pragma once
// A headless OpenGL 4.5 core context through EGL: the NVIDIA EGL device where
// present, Mesa surfaceless (llvmpipe) on CPU machines. The same renderer runs
// in it as in the editor's QOpenGLWidget.
#include "lpv/scene/Error.h"

#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace lpv::renderer {

using scene::Expected;

struct GlInfo {
    std::string vendor;
    std::string renderer;
    std::string version;
    std::string eglPlatform; // "device", "surfaceless" or "default"
};

class HeadlessContext {
public:
    // Env LPV_EGL_PLATFORM=device|surfaceless|default forces one platform.
    static Expected<HeadlessContext> create();

    HeadlessContext(HeadlessContext&&) noexcept;
    HeadlessContext& operator=(HeadlessContext&&) noexcept;
    ~HeadlessContext();

    bool makeCurrent();
    const GlInfo& info() const { return info_; }

private:
    HeadlessContext();
    struct State;
    std::unique_ptr<State> state_;
    GlInfo info_;
};

// Vendor/renderer/version strings of the current context.
GlInfo queryCurrentGlInfo();

// GPU memory as the driver reports it (GL_NVX_gpu_memory_info on NVIDIA,
// GL_ATI_meminfo on AMD); nothing where the driver does not say (Mesa
// llvmpipe), so callers never show a guessed figure.
struct GpuMemoryInfo {
    double totalMiB = 0.0; // 0 when only the free amount is known (ATI)
    double freeMiB = 0.0;
};
std::optional<GpuMemoryInfo> queryGpuMemory();

// Routes GL debug messages (errors and performance warnings) to stderr, or
// to the sink set with setGlDebugSink. On in debug builds, or when
// LPV_GL_DEBUG=1; needs a debug context to see everything.
void installDebugOutputIfRequested();
// Whether GL debug output is on in this process (debug build or LPV_GL_DEBUG=1).
bool glDebugOutputRequested();

// Where GL debug messages go instead of stderr (the editor's log); empty
// restores stderr. Called on the thread whose context reports the message
// (a render thread), under a lock that setGlDebugSink also takes: a sink
// must be quick and must not call setGlDebugSink itself.
using GlDebugSink = std::function<void(bool error, const std::string& message)>;
void setGlDebugSink(GlDebugSink sink);

} // namespace lpv::renderer
