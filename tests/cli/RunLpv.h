#pragma once
// Running the real `lpv` binary, as a user would, for the CLI's end-to-end tests.
#include "TestFiles.h"
#include "TestPaths.h"

#include <filesystem>
#include <string>

namespace lpv::test {

inline RunResult runLpv(const std::string& args) {
    return runShell(std::string(kLpvExecutable) + " " + args);
}

// An empty folder under the build tree (build/tests/SUITE/NAME), where a
// test's files stay for a look after it fails.
inline std::filesystem::path freshBuildDir(const std::string& suite, const std::string& name) {
    const std::filesystem::path dir = std::filesystem::path(kBinaryDir) / "tests" / suite / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

inline std::string cornellProject() { return std::string(kSourceDir) + "/projects/cornell-box/cornell-box.lpvproj"; }

} // namespace lpv::test
