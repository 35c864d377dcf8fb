#include "Subprocess.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <mutex>
#include <poll.h>
#include <sstream>
#include <sys/prctl.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <utility>

extern char** environ;

namespace lpv::test {
namespace fs = std::filesystem;
using namespace std::chrono_literals;

namespace {

// The daemons alive now, for the signal and exit handlers: they may run at
// any time, so a fixed array of atomics rather than a container.
std::array<std::atomic<pid_t>, 16> g_daemons{};

void terminateDaemons() {
    for (auto& slot : g_daemons)
        if (const pid_t pid = slot.load(); pid > 0)
            ::kill(pid, SIGTERM);
}

bool isDaemon(pid_t pid) {
    for (auto& slot : g_daemons)
        if (slot.load() == pid)
            return true;
    return false;
}

// What a signal handler may do: raw system calls on fixed buffers, no
// allocation, no stdio.
struct ProcStat {
    pid_t ppid = 0, pgrp = 0, sid = 0;
};

bool readProcStat(pid_t pid, ProcStat& out) {
    char path[32] = "/proc/";
    char digits[16];
    int n = 0;
    for (pid_t v = pid; v > 0 && n < 15; v /= 10)
        digits[n++] = char('0' + v % 10);
    int at = 6;
    while (n > 0)
        path[at++] = digits[--n];
    for (const char* tail = "/stat"; *tail;)
        path[at++] = *tail++;
    path[at] = 0;
    const int fd = ::open(path, O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        return false;
    char buf[512];
    const ssize_t len = ::read(fd, buf, sizeof buf - 1);
    ::close(fd);
    if (len <= 0)
        return false;
    // "pid (comm) S ppid pgrp session ..."; comm may hold ')' and spaces.
    ssize_t i = len - 1;
    while (i > 0 && buf[i] != ')')
        --i;
    i += 4; // ") S "
    pid_t fields[3] = {0, 0, 0};
    for (int f = 0; f < 3 && i < len; ++f, ++i)
        for (; i < len && buf[i] >= '0' && buf[i] <= '9'; ++i)
            fields[f] = fields[f] * 10 + (buf[i] - '0');
    out = {fields[0], fields[1], fields[2]};
    return out.ppid > 0;
}

template <class F> void forEachProcess(F&& visit) {
    const int fd = ::open("/proc", O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0)
        return;
    struct Dirent64 {
        std::uint64_t ino;
        std::int64_t off;
        unsigned short reclen;
        unsigned char type;
        char name[1];
    };
    alignas(8) char buf[8192];
    for (long n; (n = ::syscall(SYS_getdents64, fd, buf, sizeof buf)) > 0;) {
        for (long off = 0; off < n;) {
            const auto* d = reinterpret_cast<const Dirent64*>(buf + off);
            off += d->reclen;
            pid_t pid = 0;
            const char* c = d->name;
            for (; *c >= '0' && *c <= '9'; ++c)
                pid = pid * 10 + (*c - '0');
            if (*c == 0 && pid > 0)
                visit(pid);
        }
    }
    ::close(fd);
}

// On SIGTERM or SIGINT the test ends without its teardown: the jobs' steps
// (slurmstepd in a session of its own, reparented to this process, the
// subreaper) and their sessions (the job script, lpv) are killed here, as
// is any command the test ran, since slurmd leaves steps running when it stops.
void killJobSteps() {
    const pid_t self = ::getpid();
    const pid_t ownSession = ::getsid(0);
    pid_t sessions[64];
    int sessionCount = 0;
    forEachProcess([&](pid_t pid) {
        ProcStat st;
        if (isDaemon(pid) || !readProcStat(pid, st) || st.ppid != self)
            return;
        if (st.sid != ownSession && sessionCount < 64)
            sessions[sessionCount++] = st.sid;
        ::kill(st.pgrp == pid && st.sid == ownSession ? -pid : pid, SIGKILL);
    });
    if (sessionCount == 0)
        return;
    forEachProcess([&](pid_t pid) {
        ProcStat st;
        if (pid == self || !readProcStat(pid, st))
            return;
        for (int i = 0; i < sessionCount; ++i)
            if (st.sid == sessions[i])
                ::kill(pid, SIGKILL);
    });
}

void onFatalSignal(int sig) {
    killJobSteps();
    terminateDaemons();
    struct sigaction dfl {};
    dfl.sa_handler = SIG_DFL;
    ::sigaction(sig, &dfl, nullptr);
    ::raise(sig);
}

void installHandlersOnce() {
    static std::once_flag once;
    std::call_once(once, [] {
        struct sigaction sa {};
        sa.sa_handler = onFatalSignal;
        sigemptyset(&sa.sa_mask);
        for (int sig : {SIGINT, SIGTERM, SIGHUP, SIGABRT})
            ::sigaction(sig, &sa, nullptr);
        std::atexit(terminateDaemons);
    });
}

void registerDaemon(pid_t pid) {
    for (auto& slot : g_daemons) {
        pid_t empty = 0;
        if (slot.compare_exchange_strong(empty, pid))
            return;
    }
}

void unregisterDaemon(pid_t pid) {
    for (auto& slot : g_daemons) {
        pid_t expected = pid;
        slot.compare_exchange_strong(expected, 0);
    }
}

// execve wants char* arrays; they must be ready before fork (the child may
// only make async-signal-safe calls).
struct CArgs {
    std::vector<std::string> storage;
    std::vector<char*> ptrs;
    explicit CArgs(std::vector<std::string> s) : storage(std::move(s)) {
        for (auto& a : storage)
            ptrs.push_back(a.data());
        ptrs.push_back(nullptr);
    }
    char** get() { return ptrs.data(); }
};

std::vector<std::string> mergedEnvironment(const std::vector<std::string>& overrides) {
    std::vector<std::string> env;
    auto keyOf = [](const std::string& kv) { return kv.substr(0, kv.find('=')); };
    for (char** e = environ; e && *e; ++e) {
        const std::string kv = *e;
        const bool overridden =
            std::ranges::any_of(overrides, [&](const std::string& o) { return keyOf(o) == keyOf(kv); });
        if (!overridden)
            env.push_back(kv);
    }
    env.insert(env.end(), overrides.begin(), overrides.end());
    return env;
}

std::string describeStatus(int status) {
    if (WIFEXITED(status))
        return "exited with code " + std::to_string(WEXITSTATUS(status));
    if (WIFSIGNALED(status))
        return std::string("killed by signal ") + ::strsignal(WTERMSIG(status));
    return "ended (status " + std::to_string(status) + ")";
}

} // namespace

CommandResult runCommand(const std::vector<std::string>& argv, const CommandOptions& options) {
    CommandResult result;
    if (argv.empty())
        return result;
    CArgs args(argv);
    CArgs env(mergedEnvironment(options.env));
    const std::string cwd = options.cwd.string();
    int out[2];
    if (::pipe2(out, O_CLOEXEC) != 0)
        return result;
    const pid_t pid = ::fork();
    if (pid < 0) {
        ::close(out[0]);
        ::close(out[1]);
        return result;
    }
    if (pid == 0) {
        // Its own process group, so a timeout takes everything it started.
        ::setpgid(0, 0);
        const int devnull = ::open("/dev/null", O_RDONLY);
        ::dup2(devnull, 0);
        ::dup2(out[1], 1);
        ::dup2(out[1], 2);
        if (!cwd.empty() && ::chdir(cwd.c_str()) != 0)
            ::_exit(126);
        ::execvpe(args.get()[0], args.get(), env.get());
        ::_exit(127);
    }
    ::close(out[1]);
    const auto deadline = std::chrono::steady_clock::now() + options.timeout;
    bool timedOut = false;
    std::array<char, 4096> buf{};
    for (;;) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
            deadline - std::chrono::steady_clock::now());
        if (left <= 0ms) {
            timedOut = true;
            ::kill(-pid, SIGKILL);
            break;
        }
        pollfd p{out[0], POLLIN, 0};
        const int ready = ::poll(&p, 1, int(std::min<long long>(left.count(), 1000)));
        if (ready < 0 && errno != EINTR)
            break;
        if (ready <= 0)
            continue;
        const ssize_t n = ::read(out[0], buf.data(), buf.size());
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            break;
        result.output.append(buf.data(), std::size_t(n));
    }
    ::close(out[0]);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (timedOut)
        result.output += "\n[timed out after " + std::to_string(options.timeout.count()) + " s; killed]";
    else if (WIFEXITED(status))
        result.exitCode = WEXITSTATUS(status);
    else
        result.output += "\n[" + describeStatus(status) + "]";
    return result;
}

std::expected<Daemon, std::string> Daemon::spawn(const std::vector<std::string>& argv,
                                                 const std::vector<std::string>& envOverrides,
                                                 const fs::path& log) {
    installHandlersOnce();
    CArgs args(argv);
    CArgs env(mergedEnvironment(envOverrides));
    const int logFd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
    if (logFd < 0)
        return std::unexpected("cannot open " + log.string() + ": " + std::strerror(errno));
    // The child writes errno here when exec fails; a successful exec closes it
    // (O_CLOEXEC) and the parent reads end of file.
    int status[2];
    if (::pipe2(status, O_CLOEXEC) != 0) {
        ::close(logFd);
        return std::unexpected(std::string("pipe: ") + std::strerror(errno));
    }
    const pid_t parent = ::getpid();
    const pid_t pid = ::fork();
    if (pid < 0) {
        ::close(logFd);
        ::close(status[0]);
        ::close(status[1]);
        return std::unexpected(std::string("fork: ") + std::strerror(errno));
    }
    if (pid == 0) {
        // Dies with the test process, whatever kills it.
        ::prctl(PR_SET_PDEATHSIG, SIGTERM);
        if (::getppid() != parent)
            ::_exit(1);
        // Its own process group: a Ctrl+C reaches the test, which stops the
        // daemons in order, not the daemons first.
        ::setpgid(0, 0);
        const int devnull = ::open("/dev/null", O_RDONLY);
        ::dup2(devnull, 0);
        ::dup2(logFd, 1);
        ::dup2(logFd, 2);
        ::execve(args.get()[0], args.get(), env.get());
        const int err = errno;
        [[maybe_unused]] const ssize_t w = ::write(status[1], &err, sizeof err);
        ::_exit(127);
    }
    registerDaemon(pid);
    ::close(logFd);
    ::close(status[1]);
    int err = 0;
    ssize_t n;
    while ((n = ::read(status[0], &err, sizeof err)) < 0 && errno == EINTR) {
    }
    ::close(status[0]);
    Daemon d;
    d.pid_ = pid;
    d.name_ = fs::path(argv[0]).filename().string();
    if (n > 0) {
        d.stop(0ms);
        return std::unexpected("cannot run " + argv[0] + ": " + std::strerror(err));
    }
    return d;
}

Daemon::Daemon(Daemon&& other) noexcept
    : pid_(std::exchange(other.pid_, -1)), name_(std::move(other.name_)),
      exitDescription_(std::move(other.exitDescription_)) {}

Daemon& Daemon::operator=(Daemon&& other) noexcept {
    if (this != &other) {
        stop();
        pid_ = std::exchange(other.pid_, -1);
        name_ = std::move(other.name_);
        exitDescription_ = std::move(other.exitDescription_);
    }
    return *this;
}

Daemon::~Daemon() {
    stop();
}

bool Daemon::running() {
    if (pid_ <= 0)
        return false;
    int status = 0;
    const pid_t r = ::waitpid(pid_, &status, WNOHANG);
    if (r == 0)
        return true;
    exitDescription_ = r == pid_ ? describeStatus(status) : "gone";
    unregisterDaemon(pid_);
    pid_ = -1;
    return false;
}

std::string Daemon::stop(std::chrono::milliseconds grace) {
    if (!running())
        return exitDescription_;
    ::kill(pid_, SIGTERM);
    const auto deadline = std::chrono::steady_clock::now() + grace;
    while (std::chrono::steady_clock::now() < deadline) {
        if (!running())
            return exitDescription_;
        std::this_thread::sleep_for(20ms);
    }
    ::kill(pid_, SIGKILL);
    int status = 0;
    while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
    exitDescription_ =
        describeStatus(status) + " (did not stop on SIGTERM within " + std::to_string(grace.count()) + " ms)";
    unregisterDaemon(pid_);
    pid_ = -1;
    return exitDescription_;
}

void becomeSubreaper() {
    ::prctl(PR_SET_CHILD_SUBREAPER, 1);
}

std::vector<std::string> killOrphans(const std::vector<pid_t>& keep, std::chrono::milliseconds timeout) {
    std::vector<std::string> killed;
    const pid_t self = ::getpid();
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    for (;;) {
        bool any = false;
        std::error_code ec;
        for (const auto& entry : fs::directory_iterator("/proc", ec)) {
            const std::string name = entry.path().filename().string();
            if (name.empty() || !std::ranges::all_of(name, [](char c) { return c >= '0' && c <= '9'; }))
                continue;
            const pid_t pid = std::stoi(name);
            if (std::ranges::find(keep, pid) != keep.end())
                continue;
            // /proc/PID/stat: "pid (comm) state ppid ..."; comm may hold spaces.
            const std::string stat = readTextFile(entry.path() / "stat");
            const auto close = stat.rfind(')');
            if (close == std::string::npos)
                continue;
            std::istringstream rest(stat.substr(close + 1));
            char state = 0;
            pid_t ppid = 0;
            rest >> state >> ppid;
            if (ppid != self)
                continue;
            any = true;
            if (state != 'Z') {
                const auto open = stat.find('(');
                killed.push_back(name + " " + stat.substr(open + 1, close - open - 1));
                ::kill(pid, SIGKILL);
            }
            ::waitpid(pid, nullptr, 0);
        }
        if (!any || std::chrono::steady_clock::now() > deadline)
            return killed;
    }
}

fs::path findProgram(const std::string& name) {
    std::vector<std::string> dirs;
    if (const char* path = std::getenv("PATH")) {
        std::istringstream in(path);
        for (std::string d; std::getline(in, d, ':');)
            dirs.push_back(d);
    }
    for (const char* d : {"/usr/local/sbin", "/usr/sbin", "/sbin"})
        dirs.emplace_back(d);
    for (const auto& d : dirs) {
        const fs::path p = fs::path(d) / name;
        if (!d.empty() && ::access(p.c_str(), X_OK) == 0)
            return p;
    }
    return {};
}

std::string readTextFile(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::string tailOf(const fs::path& file, int lines) {
    std::vector<std::string> all;
    std::istringstream in(readTextFile(file));
    for (std::string line; std::getline(in, line);)
        all.push_back(line);
    std::string out = "--- " + file.string() + " (end) ---\n";
    for (std::size_t i = all.size() > std::size_t(lines) ? all.size() - std::size_t(lines) : 0;
         i < all.size(); ++i)
        out += all[i] + "\n";
    return out;
}

} // namespace lpv::test
