#include "SlurmCluster.h"

#include <algorithm>
#include <arpa/inet.h>
#include <array>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <netinet/in.h>
#include <pwd.h>
#include <sstream>
#include <sys/socket.h>
#include <thread>
#include <unistd.h>

namespace lpv::test {
namespace fs = std::filesystem;
using namespace std::chrono_literals;

namespace {

// Ports nobody listens on now, all different: bound together on every
// address, then released for the daemons (a race with another program is
// possible but would show as a daemon that failed to start, with its log).
std::expected<std::vector<int>, std::string> freePorts(int count) {
    std::vector<int> fds, ports;
    std::string error;
    for (int i = 0; i < count && error.empty(); ++i) {
        const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
        sockaddr_in addr{};
        addr.sin_family = AF_INET;
        addr.sin_addr.s_addr = htonl(INADDR_ANY);
        addr.sin_port = 0;
        socklen_t len = sizeof addr;
        if (fd < 0 || ::bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0 ||
            ::getsockname(fd, reinterpret_cast<sockaddr*>(&addr), &len) != 0)
            error = std::string("cannot find a free port: ") + std::strerror(errno);
        else
            ports.push_back(ntohs(addr.sin_port));
        if (fd >= 0)
            fds.push_back(fd);
    }
    for (int fd : fds)
        ::close(fd);
    if (!error.empty())
        return std::unexpected(error);
    return ports;
}

std::expected<void, std::string> writeMungeKey(const fs::path& file) {
    // 1024 random bits, as `mungekey --create` writes; munged wants the key
    // readable by its user only.
    std::array<char, 128> key{};
    std::ifstream random("/dev/urandom", std::ios::binary);
    if (!random.read(key.data(), key.size()))
        return std::unexpected("cannot read /dev/urandom");
    const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
    if (fd < 0)
        return std::unexpected("cannot create " + file.string() + ": " + std::strerror(errno));
    const bool ok = ::write(fd, key.data(), key.size()) == ssize_t(key.size());
    ::close(fd);
    if (!ok)
        return std::unexpected("cannot write " + file.string());
    return {};
}

std::string shortHostName() {
    std::array<char, 256> name{};
    if (::gethostname(name.data(), name.size() - 1) != 0)
        return "localhost";
    std::string s = name.data();
    return s.substr(0, s.find('.'));
}

std::string userName() {
    if (const passwd* pw = ::getpwuid(::geteuid()))
        return pw->pw_name;
    return std::to_string(::geteuid());
}

// "Key=Value Key=Value ..." of `scontrol -o show ...`; a value may hold
// spaces, so a token without '=' belongs to the value before it.
std::map<std::string, std::string> parseRecord(const std::string& line) {
    std::map<std::string, std::string> fields;
    std::istringstream in(line);
    std::string last;
    for (std::string token; in >> token;) {
        const auto eq = token.find('=');
        if (eq == std::string::npos || eq == 0) {
            if (!last.empty())
                fields[last] += " " + token;
            continue;
        }
        last = token.substr(0, eq);
        fields[last] = token.substr(eq + 1);
    }
    return fields;
}

} // namespace

namespace {

// Whether /proc/self/mounts lists a cgroup or cgroup2 file system under /sys/fs/cgroup.
bool cgroupFileSystemMounted() {
    std::ifstream mounts("/proc/self/mounts");
    for (std::string device, point, type, rest; mounts >> device >> point >> type && std::getline(mounts, rest);)
        if (point.starts_with("/sys/fs/cgroup") && (type == "cgroup" || type == "cgroup2"))
            return true;
    return false;
}

} // namespace

bool isTerminalJobState(const std::string& state) {
    for (const char* s : {"COMPLETED", "FAILED", "CANCELLED", "TIMEOUT", "NODE_FAIL", "PREEMPTED",
                          "BOOT_FAIL", "DEADLINE", "OUT_OF_MEMORY"})
        if (state == s)
            return true;
    return false;
}

std::expected<std::unique_ptr<SlurmCluster>, ClusterUnavailable> SlurmCluster::start() {
    std::vector<std::string> missing;
    for (const char* p : {"munged", "slurmctld", "slurmd", "sbatch", "scontrol", "scancel", "squeue"})
        if (findProgram(p).empty())
            missing.emplace_back(p);
    if (!missing.empty()) {
        std::string list;
        for (const auto& m : missing)
            list += (list.empty() ? "" : ", ") + m;
        return std::unexpected(ClusterUnavailable{
            true, "Slurm or munge is not installed (missing " + list +
                      "): apt-get install slurmctld slurmd slurm-client munge, or run ./scripts/setup.sh"});
    }
    if (::geteuid() != 0)
        return std::unexpected(ClusterUnavailable{
            true, "a private Slurm needs root here: slurmd starts each job as its submitting user, and "
                  "munged, slurmctld and slurmd run as SlurmUser=root (run the test as root, as CI does)"});

    // Debian 12's slurmd (22.05) loads its cgroup plugin whatever the
    // ProctrackType and TaskPlugin, and stops without a cgroup file system:
    // a chroot or a container that mounts none cannot run it.
    if (!cgroupFileSystemMounted())
        return std::unexpected(ClusterUnavailable{
            true, "no cgroup file system is mounted at /sys/fs/cgroup (a chroot or container without one): "
                  "Debian 12's slurmd cannot start without it"});

    std::unique_ptr<SlurmCluster> cluster(new SlurmCluster);
    // Under /tmp, not TMPDIR: munge's socket path must stay short (108 bytes).
    std::string pattern = "/tmp/lpv-slurm-XXXXXX";
    if (!::mkdtemp(pattern.data()))
        return std::unexpected(ClusterUnavailable{false, std::string("mkdtemp: ") + std::strerror(errno)});
    cluster->dir_ = pattern;
    fs::permissions(cluster->dir_, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                                       fs::perms::others_read | fs::perms::others_exec);
    cluster->node_ = shortHostName();
    cluster->cpus_ = std::max(1L, ::sysconf(_SC_NPROCESSORS_ONLN));
    cluster->scontrol_ = findProgram("scontrol");
    cluster->scancel_ = findProgram("scancel");
    // slurmd's job steps (slurmstepd) outlive it; as their reaper this
    // process can find and end them by PID.
    becomeSubreaper();
    if (auto started = cluster->startDaemons(); !started) {
        ClusterUnavailable why = started.error();
        why.message += "\n" + cluster->logs();
        cluster->keepFolder();
        cluster->stop();
        why.message += "\n(folder kept: " + cluster->dir_.string() + ")";
        return std::unexpected(why);
    }
    return cluster;
}

std::expected<void, ClusterUnavailable> SlurmCluster::startDaemons() {
    auto fail = [](std::string message) {
        return std::unexpected(ClusterUnavailable{false, std::move(message)});
    };
    for (const char* d : {"state", "spool", "log", "run"})
        fs::create_directories(dir_ / d);
    const fs::path key = dir_ / "munge.key";
    const fs::path socket = dir_ / "run" / "munge.socket";
    if (auto k = writeMungeKey(key); !k)
        return fail(k.error());

    // --force: munged refuses root and a world-writable /tmp above its
    // socket without it.
    auto munged = Daemon::spawn({findProgram("munged").string(), "--foreground", "--force",
                                 "--socket=" + socket.string(), "--key-file=" + key.string(),
                                 "--pid-file=" + (dir_ / "run" / "munged.pid").string(),
                                 "--log-file=" + (dir_ / "log" / "munged.log").string(),
                                 "--seed-file=" + (dir_ / "run" / "munged.seed").string(), "--num-threads=2"},
                                {}, dir_ / "log" / "munged.out");
    if (!munged)
        return fail(munged.error());
    munged_ = std::move(*munged);
    for (auto until = std::chrono::steady_clock::now() + 10s; !fs::exists(socket);) {
        if (!munged_.running())
            return fail("munged " + munged_.exitDescription());
        if (std::chrono::steady_clock::now() > until)
            return fail("munged did not create " + socket.string() + " within 10 s");
        std::this_thread::sleep_for(20ms);
    }

    auto ports = freePorts(2);
    if (!ports)
        return fail(ports.error());
    const std::string d = dir_.string();
    std::ofstream conf(dir_ / "slurm.conf");
    // MinJobAge keeps finished jobs for `scontrol show job`; KillWait makes a
    // cancelled job's SIGKILL follow its SIGTERM after 5 s, not 30;
    // batch_sched_delay=0 starts batch jobs on the next scheduler pass (about
    // a second) rather than up to 3 s later.
    conf << "# A private single-node cluster for the lpv cluster test (tests/cluster).\n"
         << "ClusterName=lpvtest\n"
         << "SlurmctldHost=" << node_ << "(127.0.0.1)\n"
         << "SlurmctldPort=" << (*ports)[0] << "\n"
         << "SlurmdPort=" << (*ports)[1] << "\n"
         << "SlurmUser=root\nSlurmdUser=root\n"
         << "AuthType=auth/munge\nCredType=cred/munge\n"
         << "AuthInfo=socket=" << socket.string() << "\n"
         << "StateSaveLocation=" << d << "/state\n"
         << "SlurmdSpoolDir=" << d << "/spool\n"
         << "SlurmctldPidFile=" << d << "/run/slurmctld.pid\n"
         << "SlurmdPidFile=" << d << "/run/slurmd.pid\n"
         << "SlurmctldLogFile=" << d << "/log/slurmctld.log\n"
         << "SlurmdLogFile=" << d << "/log/slurmd.log\n"
         << "PlugStackConfig=" << d << "/plugstack.conf\n"
         << "ProctrackType=proctrack/linuxproc\nTaskPlugin=task/none\n"
         << "JobAcctGatherType=jobacct_gather/none\nAccountingStorageType=accounting_storage/none\n"
         << "JobCompType=jobcomp/none\nMpiDefault=none\n"
         << "SchedulerType=sched/backfill\nSelectType=select/cons_tres\nSelectTypeParameters=CR_Core\n"
         << "ReturnToService=2\nMinJobAge=3600\nKillWait=5\nMailProg=/bin/true\n"
         << "SlurmdParameters=config_overrides\nSchedulerParameters=batch_sched_delay=0\n"
         << "NodeName=" << node_ << " NodeAddr=127.0.0.1 CPUs=" << cpus_ << " State=UNKNOWN\n"
         << "PartitionName=lpv Nodes=" << node_ << " Default=YES MaxTime=INFINITE State=UP\n";
    conf.close();
    std::ofstream(dir_ / "plugstack.conf") << "# no SPANK plugins\n";
    if (!conf)
        return fail("cannot write " + (dir_ / "slurm.conf").string());

    const std::string confPath = (dir_ / "slurm.conf").string();
    auto ctld = Daemon::spawn({findProgram("slurmctld").string(), "-D", "-f", confPath}, clientEnv(),
                              dir_ / "log" / "slurmctld.out");
    if (!ctld)
        return fail(ctld.error());
    slurmctld_ = std::move(*ctld);
    auto slurmd = Daemon::spawn({findProgram("slurmd").string(), "-D", "-N", node_, "-f", confPath},
                                clientEnv(), dir_ / "log" / "slurmd.out");
    if (!slurmd)
        return fail(slurmd.error());
    slurmd_ = std::move(*slurmd);

    // Submitting before the node registered works, but the jobs would wait;
    // waiting here keeps every test's timing about its own jobs.
    std::string last;
    for (auto until = std::chrono::steady_clock::now() + 30s;;) {
        for (Daemon* daemon : {&munged_, &slurmctld_, &slurmd_})
            if (!daemon->running())
                return fail(daemon->name() + " " + daemon->exitDescription());
        const CommandResult node = run({scontrol_.string(), "-o", "show", "node", node_});
        last = node.output;
        const auto fields = parseRecord(node.output);
        if (node.exitCode == 0 && fields.contains("State") && fields.at("State").starts_with("IDLE"))
            return {};
        if (std::chrono::steady_clock::now() > until)
            return fail("node " + node_ + " did not become idle within 30 s; scontrol show node: " + last);
        std::this_thread::sleep_for(200ms);
    }
}

SlurmCluster::~SlurmCluster() {
    stop();
}

CommandResult SlurmCluster::run(const std::vector<std::string>& argv, std::vector<std::string> env,
                                const fs::path& cwd) const {
    for (auto& e : clientEnv())
        env.push_back(e);
    return runCommand(argv, {.env = env, .cwd = cwd, .timeout = 60s});
}

std::vector<JobRecord> SlurmCluster::jobs(const std::vector<std::string>& ids) const {
    std::vector<JobRecord> records;
    for (const auto& id : ids) {
        const CommandResult r = run({scontrol_.string(), "-o", "show", "job", id});
        if (r.exitCode != 0)
            continue;
        std::istringstream lines(r.output);
        for (std::string line; std::getline(lines, line);) {
            auto fields = parseRecord(line);
            if (!fields.contains("JobId"))
                continue;
            JobRecord rec;
            rec.id = fields.contains("ArrayTaskId") && fields.contains("ArrayJobId")
                         ? fields["ArrayJobId"] + "_" + fields["ArrayTaskId"]
                         : fields["JobId"];
            rec.state = fields["JobState"];
            rec.exitCode = fields["ExitCode"];
            rec.fields = std::move(fields);
            records.push_back(std::move(rec));
        }
    }
    return records;
}

std::expected<std::vector<JobRecord>, std::string>
SlurmCluster::waitForJobs(const std::vector<std::string>& ids, std::chrono::seconds timeout) const {
    const auto until = std::chrono::steady_clock::now() + timeout;
    for (;;) {
        auto records = jobs(ids);
        const bool done = !records.empty() && std::ranges::all_of(records, [](const JobRecord& r) {
            return isTerminalJobState(r.state);
        });
        if (done)
            return records;
        if (std::chrono::steady_clock::now() > until) {
            std::string active;
            for (const auto& r : records)
                if (!isTerminalJobState(r.state))
                    active += " " + r.id + ":" + r.state + "(" +
                              (r.fields.contains("Reason") ? r.fields.at("Reason") : "") + ")";
            return std::unexpected("jobs still active after " + std::to_string(timeout.count()) +
                                   " s:" + (active.empty() ? std::string(" (no records)") : active));
        }
        std::this_thread::sleep_for(250ms);
    }
}

bool SlurmCluster::waitUntilRunning(const std::string& id, std::chrono::seconds timeout) const {
    for (const auto until = std::chrono::steady_clock::now() + timeout;
         std::chrono::steady_clock::now() < until;) {
        for (const auto& r : jobs({id}))
            if (r.id == id && r.state == "RUNNING")
                return true;
        std::this_thread::sleep_for(100ms);
    }
    return false;
}

std::string SlurmCluster::logs() const {
    std::string out;
    for (const char* f : {"munged.out", "slurmctld.log", "slurmd.log", "slurmctld.out", "slurmd.out"})
        if (fs::exists(dir_ / "log" / f))
            out += tailOf(dir_ / "log" / f, 25) + "\n";
    return out;
}

std::vector<std::string> SlurmCluster::stop() {
    if (stopped_)
        return {};
    stopped_ = true;
    // Cancel every job first: a job step outlives slurmd, and lpv shards
    // still running would outlive the test.
    if (slurmctld_.running()) {
        run({scancel_.string(), "--user=" + userName()});
        for (auto until = std::chrono::steady_clock::now() + 15s; std::chrono::steady_clock::now() < until;) {
            const CommandResult all = run({scontrol_.string(), "-o", "show", "job"});
            std::istringstream lines(all.output);
            bool active = false;
            for (std::string line; std::getline(lines, line);) {
                const auto f = parseRecord(line);
                if (f.contains("JobState") && !isTerminalJobState(f.at("JobState")))
                    active = true;
            }
            if (all.exitCode != 0 || !active)
                break;
            std::this_thread::sleep_for(200ms);
        }
    }
    slurmd_.stop();
    slurmctld_.stop();
    munged_.stop();
    std::vector<std::string> leftovers = killOrphans({}, 10s);
    if (!keep_ && !std::getenv("LPV_KEEP_SLURM_DIR") && !dir_.empty()) {
        std::error_code ec;
        fs::remove_all(dir_, ec);
    }
    return leftovers;
}

} // namespace lpv::test
