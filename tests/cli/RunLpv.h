#pragma once
// Running the real `lpv` binary, as a user would, for the CLI's end-to-end tests.
#include "TestFiles.h"
#include "TestPaths.h"

#include <string>

namespace lpv::test {

inline RunResult runLpv(const std::string& args) {
    return runShell(std::string(kLpvExecutable) + " " + args);
}

inline std::string cornellProject() { return std::string(kSourceDir) + "/projects/cornell-box/cornell-box.lpvproj"; }

} // namespace lpv::test
