#include "lpv/app/VersionInfo.h"

#include "BuildRevision.h"
#include "lpv/importers/DependencyVersions.h"
#include "lpv/renderer/DependencyVersions.h"

#include <algorithm>

namespace lpv::app {

BuildInfo buildInfo() {
    return {LPV_VERSION, buildRevision(), LPV_BUILD_TYPE, LPV_COMPILER, LPV_SYSTEM};
}

VersionReport collectVersionReport(std::string program) {
    VersionReport report{std::move(program), buildInfo(), "", {}, {}};
    for (auto list :
         {scene::dependencyVersions(), importers::dependencyVersions(), renderer::dependencyVersions()})
        report.libraries.insert(report.libraries.end(), list.begin(), list.end());
    return report;
}

std::string describeOpenGl(const renderer::GlInfo& info) {
    std::string out = (info.renderer.empty() ? "unknown renderer" : info.renderer) + ", OpenGL " +
                      (info.version.empty() ? "unknown" : info.version) + " (" +
                      (info.vendor.empty() ? "unknown vendor" : info.vendor);
    if (!info.eglPlatform.empty())
        out += ", EGL " + info.eglPlatform;
    return out + ")";
}

std::string formatVersionReport(const VersionReport& report) {
    const BuildInfo& b = report.build;
    std::string out = report.program + " " + b.version + "\n";
    out += "revision:  " + b.revision + "\n";
    out += "build:     " + b.buildType + ", " + b.compiler + ", " + b.system + "\n";
    out += "OpenGL:    " + report.openGl + "\n";
    if (report.gl) {
        const renderer::GlInfo& gl = *report.gl;
        out += "GPU:       " + (gl.renderer.empty() ? "unknown" : gl.renderer) + " (" +
               (gl.vendor.empty() ? "unknown vendor" : gl.vendor) + ")\n";
        out += "driver:    OpenGL " + (gl.version.empty() ? "unknown" : gl.version) + "\n";
        out += "platform:  " + (gl.eglPlatform.empty() ? std::string("not EGL") : "EGL " + gl.eglPlatform) + "\n";
    }
    out += "libraries:\n";
    std::size_t width = 0;
    for (const auto& lib : report.libraries)
        width = std::max(width, lib.name.size());
    for (const auto& lib : report.libraries) {
        out += "  " + lib.name + std::string(width - lib.name.size() + 2, ' ') + lib.version;
        if (!lib.note.empty())
            out += " (" + lib.note + ")";
        out += "\n";
    }
    return out;
}

} // namespace lpv::app
