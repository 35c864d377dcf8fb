#pragma once
// Processes for the cluster test (issue #28): commands run to completion with
// their output captured, and daemons held by PID that are always stopped.
#include <chrono>
#include <expected>
#include <filesystem>
#include <string>
#include <sys/types.h>
#include <vector>

namespace lpv::test {

struct CommandResult {
    int exitCode = -1;  // -1: did not start, timed out or died of a signal
    std::string output; // stdout and stderr together
};

struct CommandOptions {
    std::vector<std::string> env;      // "KEY=VALUE" set on top of this process' environment
    std::filesystem::path cwd;         // empty: this process' working directory
    std::chrono::seconds timeout{120}; // then the command's process group is killed
};

// argv[0] is looked up on PATH. No shell: arguments arrive as they are.
CommandResult runCommand(const std::vector<std::string>& argv, const CommandOptions& options = {});

// A daemon started in the foreground, stdout and stderr into `log`. Move-only;
// stopped (SIGTERM, SIGKILL after the grace time, reaped) when destroyed. It
// also gets SIGTERM from the kernel if this process dies first
// (PR_SET_PDEATHSIG), and from a signal handler if this process is
// interrupted (SIGINT, SIGTERM, SIGHUP, SIGABRT), so no test leaves one running.
class Daemon {
  public:
    Daemon() = default;
    static std::expected<Daemon, std::string> spawn(const std::vector<std::string>& argv,
                                                    const std::vector<std::string>& env,
                                                    const std::filesystem::path& log);
    Daemon(Daemon&& other) noexcept;
    Daemon& operator=(Daemon&& other) noexcept;
    Daemon(const Daemon&) = delete;
    Daemon& operator=(const Daemon&) = delete;
    ~Daemon();

    pid_t pid() const { return pid_; }
    std::string name() const { return name_; }
    // False once it exited (it is reaped then, and `exitDescription` says how).
    bool running();
    std::string exitDescription() const { return exitDescription_; }
    // SIGTERM, then SIGKILL after `grace`; waits for it. Returns how it ended.
    std::string stop(std::chrono::milliseconds grace = std::chrono::seconds(10));

  private:
    pid_t pid_ = -1;
    std::string name_;
    std::string exitDescription_;
};

// Makes this process the reaper of its orphaned descendants (slurmd starts
// slurmstepd, which outlives it), so `killOrphans` can find them by PID.
void becomeSubreaper();
// Kills (SIGKILL) and reaps every child of this process that is not one of
// `keep`, repeatedly, as their own children are reparented here. Returns what
// it killed ("pid name"), empty when nothing was left.
std::vector<std::string> killOrphans(const std::vector<pid_t>& keep, std::chrono::milliseconds timeout);

// The first of `names` on PATH or in /usr/sbin, /sbin (daemons live there and
// a user's PATH often lacks them); empty when none.
std::filesystem::path findProgram(const std::string& name);

std::string readTextFile(const std::filesystem::path& file);
// The last `lines` lines of a file, for failure messages.
std::string tailOf(const std::filesystem::path& file, int lines = 30);

} // namespace lpv::test
