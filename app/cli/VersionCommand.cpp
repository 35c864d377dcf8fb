// `lpv --version`: the version report of lpv/app/VersionInfo.h with the
// OpenGL driver of a headless context. A machine without a usable driver
// still gets the rest (and exit code 0): that is when the report is needed most.
#include "Cli.h"

#include "lpv/app/VersionInfo.h"
#include "lpv/renderer/GlContext.h"

#include <iostream>

namespace lpv::cli {

int runVersion() {
    app::VersionReport report = app::collectVersionReport("lpv");
    auto context = renderer::HeadlessContext::create();
    report.openGl =
        context ? app::describeOpenGl(context->info()) : "unavailable: " + context.error().describe();
    if (context)
        report.gl = context->info();
    std::cout << app::formatVersionReport(report);
    return kOk;
}

} // namespace lpv::cli
