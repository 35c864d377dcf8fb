#pragma once
// What `lpv --version` and the editor's About box report: the version, the
// git revision the build came from, the build itself, the OpenGL driver and
// the versions of the libraries in use. Qt-free; the editor adds Qt's lines.
#include "lpv/renderer/GlContext.h"
#include "lpv/scene/DependencyVersions.h"

#include <optional>
#include <string>
#include <vector>

namespace lpv::app {

struct BuildInfo {
    std::string version;   // CMake's project version, "0.1.0"
    std::string revision;  // `git describe --always --dirty` at build time, or "unknown"
    std::string buildType; // "RelWithDebInfo"
    std::string compiler;  // "GNU 12.2.0"
    std::string system;    // the build's target system, "Linux x86_64"
};

BuildInfo buildInfo();

struct VersionReport {
    std::string program; // "lpv", "LPV Studio"
    BuildInfo build;
    std::string openGl; // describeOpenGl(...), or "unavailable: <why>"
    std::vector<scene::DependencyVersion> libraries;
    // The context behind `openGl`, when there is one: its GPU (GL_RENDERER),
    // driver (GL_VERSION) and EGL platform get a line each (issue #45), so a
    // report from a GPU machine says which card and driver its figures are from.
    std::optional<renderer::GlInfo> gl;
};

// Everything but OpenGL, which needs a context: the CLI makes a headless one,
// the editor asks its viewport's. Libraries come in layer order (scene,
// importers, renderer).
VersionReport collectVersionReport(std::string program);

// "llvmpipe (LLVM 15.0.6, 256 bits), OpenGL 4.5 (Core Profile) Mesa 22.3.6 (Mesa, EGL surfaceless)"
std::string describeOpenGl(const renderer::GlInfo& info);

// The plain-text block `lpv --version` prints: "PROGRAM VERSION" on the first
// line, then "revision:", "build:", "OpenGL:", with a context "GPU:",
// "driver:" and "platform:" (EGL device, surfaceless or default; "not EGL"
// for a context that came from elsewhere), and one line per library.
std::string formatVersionReport(const VersionReport& report);

} // namespace lpv::app
