#pragma once
// A private single-node Slurm on localhost for the cluster test (issue #28):
// munged, slurmctld and slurmd started in the foreground from a temporary
// folder (own munge key and socket, own ports chosen free at start, own
// state, spool, pid and log files), so the job files of packaging/cluster/
// meet a real scheduler. Nothing of the host's munge or Slurm set-up is read
// or touched. The destructor cancels every job, stops the daemons by PID and
// kills what their jobs left behind.
#include "Subprocess.h"

#include <chrono>
#include <expected>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace lpv::test {

// How a start that did not work ended: `skip` where this machine cannot run
// Slurm at all (programs missing, not root), an error message otherwise.
struct ClusterUnavailable {
    bool skip = false;
    std::string message;
};

// One record of `scontrol show job`: a job or one task of an array.
struct JobRecord {
    std::string id;       // "12", or "12_3" for task 3 of array job 12
    std::string state;    // COMPLETED, FAILED, CANCELLED, PENDING, RUNNING, ...
    std::string exitCode; // "0:0" (code:signal)
    std::map<std::string, std::string> fields;
};

class SlurmCluster {
  public:
    static std::expected<std::unique_ptr<SlurmCluster>, ClusterUnavailable> start();
    ~SlurmCluster();
    SlurmCluster(const SlurmCluster&) = delete;
    SlurmCluster& operator=(const SlurmCluster&) = delete;

    const std::filesystem::path& dir() const { return dir_; }
    const std::string& nodeName() const { return node_; }
    int cpus() const { return cpus_; }
    // SLURM_CONF=..., for every client command (sbatch, squeue, scontrol, ...).
    std::vector<std::string> clientEnv() const { return {"SLURM_CONF=" + (dir_ / "slurm.conf").string()}; }

    // A Slurm client (or a script that calls them) with clientEnv() added to `env`.
    CommandResult run(const std::vector<std::string>& argv, std::vector<std::string> env = {},
                      const std::filesystem::path& cwd = {}) const;

    // Every record of these jobs (array tasks separately).
    std::vector<JobRecord> jobs(const std::vector<std::string>& ids) const;
    // Waits until no record of these jobs is pending, running or being
    // requeued; returns their records, or an error naming those still active.
    std::expected<std::vector<JobRecord>, std::string> waitForJobs(const std::vector<std::string>& ids,
                                                                   std::chrono::seconds timeout) const;
    // Waits until `id` (e.g. "12_2") is RUNNING.
    bool waitUntilRunning(const std::string& id, std::chrono::seconds timeout) const;

    // The daemons' logs' ends, for failure messages.
    std::string logs() const;
    // Keep the temporary folder after the cluster stops (a test failed).
    void keepFolder() { keep_ = true; }
    // Stops everything now (the destructor does the same); returns what it
    // had to kill beyond the daemons, one line each.
    std::vector<std::string> stop();

  private:
    SlurmCluster() = default;
    std::expected<void, ClusterUnavailable> startDaemons();

    std::filesystem::path dir_;
    std::string node_;
    int cpus_ = 1;
    std::filesystem::path scontrol_, scancel_;
    Daemon munged_, slurmctld_, slurmd_;
    bool keep_ = false;
    bool stopped_ = false;
};

bool isTerminalJobState(const std::string& state);

} // namespace lpv::test
