// Platform file: systems without EGL (Windows, macOS). The editor renders
// there through Qt's context (QOpenGLWidget); a headless context for the CLI
// and the GL tests would be WGL or CGL behind this same interface, and is not
// written yet (docs/portability.md). Until then creating one is an error, as
// a missing driver is on Linux, so `lpv --version` still works.
#include "lpv/renderer/GlContext.h"

namespace lpv::renderer {

struct HeadlessContext::State {};

HeadlessContext::HeadlessContext() : state_(std::make_unique<State>()) {}
HeadlessContext::HeadlessContext(HeadlessContext&&) noexcept = default;
HeadlessContext& HeadlessContext::operator=(HeadlessContext&&) noexcept = default;
HeadlessContext::~HeadlessContext() = default;

bool HeadlessContext::makeCurrent() {
    return false;
}

Expected<HeadlessContext> HeadlessContext::create() {
    return scene::makeError(scene::ErrorCode::IoError, "OpenGL", "",
                            "no headless OpenGL context on this platform yet (EGL only); use the editor");
}

} // namespace lpv::renderer
