#pragma once
// Runs a program in its own process with a time limit and tells how it
// ended: an exit code, a signal, or killed at the limit. RunLpv.h's popen
// cannot do this: the shell between hides a signal behind an exit code and
// a hang would hang the test. Safe to call from several threads at once
// (posix_spawn, one pid waited for per call).
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

extern char** environ;

namespace lpv::test {

struct ChildResult {
    bool started = false;
    bool timedOut = false;
    int exitCode = -1; // when it exited
    int signal = 0;    // when a signal ended it (not our kill at the limit)
    double seconds = 0.0;
    std::string output; // stdout and stderr together

    bool exited() const { return started && !timedOut && signal == 0; }
    std::string describe() const {
        if (!started)
            return "could not be started";
        if (timedOut)
            return "did not end within its time limit (killed)";
        if (signal != 0)
            return std::string("killed by signal ") + std::to_string(signal) + " (" + strsignal(signal) + ")";
        return "exit code " + std::to_string(exitCode);
    }
};

// Runs `argv` (argv[0] a path) with stdout and stderr into `outputFile`,
// which is read back into the result and left in place.
inline ChildResult runChild(const std::vector<std::string>& argv, std::chrono::seconds limit,
                            const std::filesystem::path& outputFile) {
    ChildResult r;
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, outputFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, 1, 2);
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    std::vector<char*> args;
    for (const std::string& a : argv)
        args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);

    const auto start = std::chrono::steady_clock::now();
    pid_t pid = 0;
    r.started = posix_spawn(&pid, args[0], &actions, nullptr, args.data(), environ) == 0;
    posix_spawn_file_actions_destroy(&actions);
    if (!r.started)
        return r;

    int status = 0;
    // Polled, not blocked on: the limit must hold for a child that never ends.
    for (auto wait = std::chrono::milliseconds(2);;
         wait = std::min(wait * 2, std::chrono::milliseconds(50))) {
        const pid_t done = waitpid(pid, &status, WNOHANG);
        if (done == pid)
            break;
        if (done < 0)
            return r; // cannot happen for our own child; reported as not started
        if (std::chrono::steady_clock::now() - start > limit) {
            kill(pid, SIGKILL);
            waitpid(pid, &status, 0);
            r.timedOut = true;
            break;
        }
        std::this_thread::sleep_for(wait);
    }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!r.timedOut) {
        if (WIFEXITED(status))
            r.exitCode = WEXITSTATUS(status);
        else if (WIFSIGNALED(status))
            r.signal = WTERMSIG(status);
    }
    std::ifstream in(outputFile, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    r.output = text.str();
    return r;
}

} // namespace lpv::test
