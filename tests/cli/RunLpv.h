#pragma once
#include "TestPaths.h"

#include <array>
#include <cstdio>
#include <string>
#include <sys/wait.h>

namespace lpv::test {

struct RunResult {
    int exitCode = -1;
    std::string output; // stdout and stderr together
};

// Runs the real `lpv` binary, as a user would.
inline RunResult runLpv(const std::string& args) {
    const std::string cmd = std::string(kLpvExecutable) + " " + args + " 2>&1";
    RunResult r;
    FILE* pipe = popen(cmd.c_str(), "r");
    if (!pipe)
        return r;
    std::array<char, 4096> buf{};
    while (std::size_t n = std::fread(buf.data(), 1, buf.size(), pipe))
        r.output.append(buf.data(), n);
    const int status = pclose(pipe);
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

inline std::string cornellProject() { return std::string(kSourceDir) + "/projects/cornell-box/cornell-box.lpvproj"; }

} // namespace lpv::test
