#pragma once
// Files and processes as the tests of the programs and their libraries use
// them (tests/cli, tests/bench, tests/install): a fresh
// scratch folder, a file's text, a shell command's output and exit status.
// One copy here instead of one per test file.
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace lpv::test {

struct RunResult {
    int exitCode = -1;
    std::string output; // stdout and stderr together
};

// Runs `command` in a shell, stdout and stderr together.
inline RunResult runShell(const std::string& command) {
    RunResult r;
    FILE* pipe = popen((command + " 2>&1").c_str(), "r");
    if (!pipe)
        return r;
    std::array<char, 4096> buf{};
    while (std::size_t n = std::fread(buf.data(), 1, buf.size(), pipe))
        r.output.append(buf.data(), n);
    const int status = pclose(pipe);
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

// A path quoted for the shell.
inline std::string quoted(const std::filesystem::path& p) {
    return "'" + p.string() + "'";
}

inline bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

inline std::string readText(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// An empty folder of the system's temporary ones, lpv-PREFIX[-NAME]-PID:
// named for the test and this process, so that parallel runs never share one.
inline std::filesystem::path freshTempDir(const std::string& prefix, const std::string& name = "") {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() /
        ("lpv-" + prefix + (name.empty() ? "" : "-" + name) + "-" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

} // namespace lpv::test
