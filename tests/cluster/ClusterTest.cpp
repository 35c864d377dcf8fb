// Issue #28 items 3-5: the Slurm job files of packaging/cluster/ run on a real
// (private, single-node) Slurm, and sharded references and sweeps merged
// from its jobs equal what one process makes. docs/cluster.md.
#include "SlurmCluster.h"
#include "TestPaths.h"

#include "lpv/importers/ImageIO.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <iostream>
#include <limits>
#include <optional>
#include <sstream>
#include <thread>

using namespace lpv::test;
namespace fs = std::filesystem;
using namespace std::chrono_literals;

namespace {

const fs::path kJobFiles = fs::path(kSourceDir) / "packaging" / "cluster";
const fs::path kFakeLpv = fs::path(kSourceDir) / "tests" / "cluster" / "fake-lpv.sh";

struct Submitted {
    std::string arrayJob, mergeJob, shardDir;
};

// ARRAY_JOB=..., MERGE_JOB=..., SHARD_DIR=... as submit-*.sh print them.
std::optional<Submitted> parseSubmitted(const std::string& output) {
    Submitted s;
    std::istringstream lines(output);
    for (std::string line; std::getline(lines, line);) {
        if (line.starts_with("ARRAY_JOB="))
            s.arrayJob = line.substr(10);
        else if (line.starts_with("MERGE_JOB="))
            s.mergeJob = line.substr(10);
        else if (line.starts_with("SHARD_DIR="))
            s.shardDir = line.substr(10);
    }
    if (s.arrayJob.empty() || s.mergeJob.empty())
        return std::nullopt;
    return s;
}

std::string describe(const std::vector<JobRecord>& records) {
    std::string out;
    for (const auto& r : records)
        out += r.id + "=" + r.state + "(" + r.exitCode + ") ";
    return out;
}

const JobRecord* find(const std::vector<JobRecord>& records, const std::string& id) {
    auto it = std::ranges::find(records, id, &JobRecord::id);
    return it == records.end() ? nullptr : &*it;
}

// "key=value key=value" lines of fake-lpv.sh's outputs.
double fieldOf(const std::string& text, const std::string& key, std::size_t from = 0) {
    const auto at = text.find(key + "=", from);
    if (at == std::string::npos)
        return std::numeric_limits<double>::quiet_NaN(); // fails every comparison
    return std::stod(text.substr(at + key.size() + 1));
}

std::vector<std::string> filesUnder(const fs::path& dir) {
    std::vector<std::string> names;
    std::error_code ec;
    for (const auto& e : fs::recursive_directory_iterator(dir, ec))
        names.push_back(fs::relative(e.path(), dir).string());
    std::ranges::sort(names);
    return names;
}

std::string joined(const std::vector<std::string>& v) {
    std::string out;
    for (const auto& s : v)
        out += (out.empty() ? "" : ", ") + s;
    return out;
}

CommandResult runLpv(std::vector<std::string> args, std::chrono::seconds timeout = 300s) {
    args.insert(args.begin(), kLpvExecutable);
    CommandOptions options;
    options.timeout = timeout;
    return runCommand(args, options);
}

// Bit for bit on every channel of every pixel; the header (which records the
// seconds each run took) is not compared.
void expectSamePixels(const fs::path& expected, const fs::path& actual) {
    auto a = lpv::importers::readImageChannels(expected);
    auto b = lpv::importers::readImageChannels(actual);
    ASSERT_TRUE(a) << expected;
    ASSERT_TRUE(b) << actual;
    ASSERT_EQ(a->width, b->width);
    ASSERT_EQ(a->height, b->height);
    ASSERT_EQ(a->names, b->names);
    ASSERT_EQ(a->pixels.size(), b->pixels.size());
    std::size_t differing = 0, first = 0;
    for (std::size_t i = 0; i < a->pixels.size(); ++i)
        if (std::memcmp(&a->pixels[i], &b->pixels[i], sizeof(float)) != 0 && differing++ == 0)
            first = i;
    if (differing > 0) {
        const std::size_t channels = a->names.size();
        const std::size_t pixel = first / channels;
        ADD_FAILURE() << differing << " of " << a->pixels.size() << " values differ between " << expected
                      << " and " << actual << "; the first at pixel (" << pixel % std::size_t(a->width)
                      << ", " << pixel / std::size_t(a->width) << ") channel " << a->names[first % channels]
                      << ": " << a->pixels[first] << " vs " << b->pixels[first];
    }
}

std::vector<std::vector<std::string>> readCsv(const fs::path& file) {
    std::vector<std::vector<std::string>> rows;
    std::istringstream lines(readTextFile(file));
    for (std::string line; std::getline(lines, line);) {
        std::vector<std::string> cells;
        std::string cell;
        std::istringstream in(line);
        while (std::getline(in, cell, ','))
            cells.push_back(cell);
        if (!line.empty() && line.back() == ',')
            cells.emplace_back();
        rows.push_back(std::move(cells));
    }
    return rows;
}

} // namespace

class Cluster : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        auto started = SlurmCluster::start();
        if (started)
            cluster_ = std::move(*started);
        else
            unavailable_ = started.error();
    }

    static void TearDownTestSuite() {
        if (!cluster_)
            return;
        const fs::path dir = cluster_->dir();
        const std::vector<std::string> leftovers = cluster_->stop();
        if (!leftovers.empty())
            std::cerr << "killed what the jobs left running: " << joined(leftovers) << "\n";
        if (failed_)
            std::cerr << "the cluster's folder is kept for a look: " << dir << "\n";
        cluster_.reset();
    }

    void SetUp() override {
        if (!cluster_) {
            if (unavailable_.skip)
                GTEST_SKIP() << unavailable_.message;
            FAIL() << "Slurm did not start: " << unavailable_.message;
        }
        work_ = cluster_->dir() / "work" / ::testing::UnitTest::GetInstance()->current_test_info()->name();
        fs::create_directories(work_);
    }

    void TearDown() override {
        if (!HasFailure() || !cluster_)
            return;
        failed_ = true;
        cluster_->keepFolder();
        std::cerr << cluster_->logs();
        for (const auto& f : filesUnder(work_))
            if (f.ends_with(".out"))
                std::cerr << tailOf(work_ / f, 20) << "\n";
    }

    // Every job's output under work_: slurm-<name>-<job>_<task>.out.
    std::vector<std::string> jobEnv(const fs::path& lpvBinary) const {
        return {"LPV=" + lpvBinary.string(),
                "LPV_SBATCH_ARGS=--output=" + (work_ / "slurm-%x-%A_%a.out").string()};
    }

    Submitted submit(const std::string& script, const std::vector<std::string>& args,
                     std::vector<std::string> env) {
        std::vector<std::string> argv{(kJobFiles / script).string()};
        argv.insert(argv.end(), args.begin(), args.end());
        const CommandResult r = cluster_->run(argv, std::move(env), work_);
        EXPECT_EQ(r.exitCode, 0) << script << ": " << r.output;
        auto s = parseSubmitted(r.output);
        EXPECT_TRUE(s) << script << " printed no job ids: " << r.output;
        return s.value_or(Submitted{});
    }

    std::vector<JobRecord> waitFor(const std::vector<std::string>& ids, std::chrono::seconds timeout = 90s) {
        auto records = cluster_->waitForJobs(ids, timeout);
        EXPECT_TRUE(records) << records.error();
        return records.value_or(std::vector<JobRecord>{});
    }

    static void expectAllCompleted(const std::vector<JobRecord>& records, std::size_t count) {
        EXPECT_EQ(records.size(), count) << describe(records);
        for (const auto& r : records)
            EXPECT_TRUE(r.state == "COMPLETED" && r.exitCode == "0:0") << describe(records);
    }

    fs::path newCornellBox() {
        const fs::path project = work_ / "cornell-box.lpvproj";
        const CommandResult r = runLpv({"new", project.string(), "--template", "cornell-box"});
        EXPECT_EQ(r.exitCode, 0) << r.output;
        return project;
    }

    static inline std::unique_ptr<SlurmCluster> cluster_;
    static inline ClusterUnavailable unavailable_;
    static inline bool failed_ = false;
    fs::path work_;
};

// The harness itself: an array job and a job that depends on it run, in order.
TEST_F(Cluster, RunsAnArrayThenTheJobThatDependsOnIt) {
    const fs::path script = work_ / "task.sh";
    std::ofstream(script)
        << "#!/bin/sh\n"
        << "echo \"task=$SLURM_ARRAY_TASK_ID count=$SLURM_ARRAY_TASK_COUNT start=$(date +%s.%N)\" > "
        << work_.string() << "/task-$SLURM_ARRAY_TASK_ID\n"
        << "sleep 0.3\n"
        << "echo \"end=$(date +%s.%N)\" >> " << work_.string() << "/task-$SLURM_ARRAY_TASK_ID\n";
    const std::string output = "--output=" + (work_ / "slurm-%A_%a.out").string();
    const CommandResult array = cluster_->run(
        {"sbatch", "--parsable", "--export=ALL", "--array=0-3", output, script.string()}, {}, work_);
    ASSERT_EQ(array.exitCode, 0) << array.output;
    const std::string arrayId = array.output.substr(0, array.output.find_first_of(";\n"));
    const CommandResult after =
        cluster_->run({"sbatch", "--parsable", "--dependency=afterok:" + arrayId, output, "--wrap",
                       "date +%s.%N > " + (work_ / "after").string()},
                      {}, work_);
    ASSERT_EQ(after.exitCode, 0) << after.output;
    const std::string afterId = after.output.substr(0, after.output.find_first_of(";\n"));

    const auto records = waitFor({arrayId, afterId});
    expectAllCompleted(records, 5);
    const double afterStart = std::stod(readTextFile(work_ / "after"));
    for (int i = 0; i < 4; ++i) {
        const std::string task = readTextFile(work_ / ("task-" + std::to_string(i)));
        EXPECT_NE(task.find("task=" + std::to_string(i) + " count=4"), std::string::npos) << task;
        EXPECT_LE(fieldOf(task, "end"), afterStart)
            << "the dependent job started before task " << i << " ended";
    }
}

// submit-reference.sh and submit-sweep.sh: every shard runs once with its
// index and the count, each writes only its final name, then the merge runs
// after all of them. A stand-in for lpv keeps this independent of lpv.
TEST_F(Cluster, JobFilesRunEveryShardThenTheMerge) {
    const std::vector<std::string> env = jobEnv(kFakeLpv);
    const fs::path project = work_ / "p.lpvproj";
    std::ofstream(project) << "{}\n";
    const Submitted ref = submit("submit-reference.sh",
                                 {project.string(), (work_ / "ref.exr").string(), "4", "--width", "64"}, env);
    const Submitted sweep = submit(
        "submit-sweep.sh",
        {project.string(), (work_ / "sweep").string(), "3", "--sweep", "lpv.propagationSteps=0,4,8"}, env);
    const auto records = waitFor({ref.arrayJob, ref.mergeJob, sweep.arrayJob, sweep.mergeJob});
    expectAllCompleted(records, 4 + 1 + 3 + 1);

    EXPECT_EQ(ref.shardDir, (work_ / "ref.shards").string());
    EXPECT_EQ(filesUnder(work_ / "ref.shards"),
              (std::vector<std::string>{"shard-0-of-4.exr", "shard-1-of-4.exr", "shard-2-of-4.exr",
                                        "shard-3-of-4.exr"}))
        << "no temporary file is left";
    const std::string merged = readTextFile(work_ / "ref.exr");
    const double mergeStart = fieldOf(merged, "merge-start");
    for (int i = 0; i < 4; ++i) {
        const auto at = merged.find("shard=" + std::to_string(i) + "/4 ");
        ASSERT_NE(at, std::string::npos) << merged;
        EXPECT_LE(fieldOf(merged, "end", at), mergeStart)
            << "the merge started before shard " << i << " ended";
    }

    EXPECT_EQ(filesUnder(work_ / "sweep.shards"),
              (std::vector<std::string>{"shard-0-of-3", "shard-0-of-3/shard.txt", "shard-1-of-3",
                                        "shard-1-of-3/shard.txt", "shard-2-of-3", "shard-2-of-3/shard.txt"}));
    const std::string sweepMerged = readTextFile(work_ / "sweep" / "sweep.csv");
    for (int i = 0; i < 3; ++i)
        EXPECT_NE(sweepMerged.find("shard=" + std::to_string(i) + "/3 "), std::string::npos) << sweepMerged;
}

// A shard that fails: its partial output is removed, the merge never runs
// (afterok, cancelled as its dependency can never be met), no output appears.
TEST_F(Cluster, AFailedShardCancelsTheMergeAndLeavesNoFile) {
    std::vector<std::string> env = jobEnv(kFakeLpv);
    env.push_back("LPV_FAKE_FAIL_SHARD=2");
    const fs::path project = work_ / "p.lpvproj";
    std::ofstream(project) << "{}\n";
    const Submitted ref =
        submit("submit-reference.sh", {project.string(), (work_ / "ref.exr").string(), "4"}, env);
    const auto records = waitFor({ref.arrayJob, ref.mergeJob});
    const JobRecord* failed = find(records, ref.arrayJob + "_2");
    ASSERT_TRUE(failed) << describe(records);
    EXPECT_EQ(failed->state, "FAILED") << describe(records);
    const JobRecord* merge = find(records, ref.mergeJob);
    ASSERT_TRUE(merge) << describe(records);
    EXPECT_EQ(merge->state, "CANCELLED") << describe(records);
    EXPECT_FALSE(fs::exists(work_ / "ref.exr"));
    EXPECT_EQ(filesUnder(work_ / "ref.shards"),
              (std::vector<std::string>{"shard-0-of-4.exr", "shard-1-of-4.exr", "shard-3-of-4.exr"}))
        << "the failed shard's partial output is gone";
}

namespace {

// Whether a process of this machine has each of these argument runs, in
// order, on its command line (the lpv of one shard of one test's project).
bool processWithArguments(const std::vector<std::vector<std::string>>& runs) {
    std::error_code ec;
    for (const auto& e : fs::directory_iterator("/proc", ec)) {
        const std::string raw = readTextFile(e.path() / "cmdline");
        std::vector<std::string> argv;
        for (std::size_t at = 0; at < raw.size();) {
            const auto end = raw.find('\0', at);
            argv.push_back(raw.substr(at, end - at));
            at = end == std::string::npos ? raw.size() : end + 1;
        }
        if (std::ranges::all_of(runs,
                                [&](const auto& run) { return !std::ranges::search(argv, run).empty(); }))
            return true;
    }
    return false;
}

std::vector<std::string> concat(std::vector<std::string> a, const std::vector<std::string>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

} // namespace

// Item 4: a 4-shard reference of the Cornell box through the job files, merged
// by the merge job, equals one process' reference bit for bit.
TEST_F(Cluster, AFourShardReferenceIsBitIdenticalToOneProcess) {
    const fs::path project = newCornellBox();
    const std::vector<std::string> options{"--width", "64", "--height", "36", "--spp", "16"};
    const Submitted s = submit("submit-reference.sh",
                               concat({project.string(), (work_ / "sharded.exr").string(), "4"}, options),
                               jobEnv(kLpvExecutable));
    // One process renders the same while the jobs run.
    const CommandResult one =
        runLpv(concat({"reference", project.string(), "-o", (work_ / "single.exr").string()}, options));
    ASSERT_EQ(one.exitCode, 0) << one.output;
    expectAllCompleted(waitFor({s.arrayJob, s.mergeJob}), 4 + 1);
    ASSERT_TRUE(fs::exists(work_ / "sharded.exr"));
    expectSamePixels(work_ / "single.exr", work_ / "sharded.exr");
}

// Item 4: a 3-shard sweep through the job files, merged by the merge job, has
// the one-process sweep's files, the same error columns exactly, and timings.
TEST_F(Cluster, AThreeShardSweepMergesIntoTheOneProcessSweep) {
    const fs::path project = newCornellBox();
    const fs::path reference = work_ / "ref.exr";
    const CommandResult traced = runLpv({"reference", project.string(), "-o", reference.string(), "--width",
                                         "64", "--height", "36", "--spp", "16"});
    ASSERT_EQ(traced.exitCode, 0) << traced.output;
    const std::vector<std::string> options{"--sweep",     "lpv.propagationSteps=0,4,8",
                                           "--reference", reference.string(),
                                           "--width",     "64",
                                           "--height",    "36",
                                           "--frames",    "2",
                                           "--warmup",    "1"};
    const Submitted s =
        submit("submit-sweep.sh", concat({project.string(), (work_ / "sharded").string(), "3"}, options),
               jobEnv(kLpvExecutable));
    const CommandResult one =
        runLpv(concat(concat({"bench", project.string()}, options), {"--out", (work_ / "single").string()}));
    ASSERT_EQ(one.exitCode, 0) << one.output;
    expectAllCompleted(waitFor({s.arrayJob, s.mergeJob}), 3 + 1);

    EXPECT_EQ(filesUnder(work_ / "sharded"), filesUnder(work_ / "single"))
        << "sweep.csv, sweep.json, sweep.md and the plots, as one process writes them";
    const auto single = readCsv(work_ / "single" / "sweep.csv");
    const auto sharded = readCsv(work_ / "sharded" / "sweep.csv");
    ASSERT_EQ(single.size(), 4u) << "header and three settings";
    ASSERT_EQ(sharded.size(), single.size());
    const std::vector<std::string>& header = single[0];
    ASSERT_EQ(sharded[0], header);
    for (std::size_t row = 1; row < single.size(); ++row) {
        ASSERT_EQ(sharded[row].size(), header.size()) << "row " << row;
        for (std::size_t col = 0; col < header.size(); ++col) {
            const std::string& want = single[row][col];
            const std::string& got = sharded[row][col];
            if (header[col] == "rounds" || header[col] == "same_cost_as")
                continue; // each shard times its own settings in rounds: how many and which tie differ
            if (header[col].ends_with("_ms")) {
                // Timings differ run to run; the same passes ran and each took time.
                EXPECT_EQ(got.empty(), want.empty()) << header[col] << ", row " << row;
                if (!got.empty()) {
                    EXPECT_GT(std::stod(got), 0.0) << header[col] << ", row " << row;
                }
            } else {
                EXPECT_EQ(got, want) << header[col] << ", row " << row;
            }
        }
    }
}

// Item 5: a shard killed mid-run (SIGKILL to its script and lpv, as when a
// node dies: no trap runs) leaves nothing `lpv merge` accepts, the merge job
// never runs, and the shard run again writes the same pixels.
TEST_F(Cluster, AKilledShardLeavesNothingTheMergeAcceptsAndItsRerunMatches) {
    const fs::path project = newCornellBox();
    // Enough samples that a shard runs for seconds, so the kill lands mid-run.
    const std::vector<std::string> options{"--width", "160", "--height", "90", "--spp", "1024"};
    const fs::path merged = work_ / "merged.exr";
    const std::vector<std::string> env = jobEnv(kLpvExecutable);
    const Submitted s =
        submit("submit-reference.sh", concat({project.string(), merged.string(), "4"}, options), env);
    const fs::path shards = s.shardDir;

    ASSERT_TRUE(cluster_->waitUntilRunning(s.arrayJob + "_2", 60s)) << describe(cluster_->jobs({s.arrayJob}));
    bool started = false;
    for (auto until = std::chrono::steady_clock::now() + 30s;
         !started && std::chrono::steady_clock::now() < until;)
        if (!(started = processWithArguments({{"reference", project.string()}, {"--shard", "2/4"}})))
            std::this_thread::sleep_for(20ms);
    ASSERT_TRUE(started) << "lpv of shard 2 never ran";
    std::this_thread::sleep_for(300ms);
    const CommandResult kill = cluster_->run({"scancel", "--full", "--signal=KILL", s.arrayJob + "_2"});
    ASSERT_EQ(kill.exitCode, 0) << kill.output;

    const auto records = waitFor({s.arrayJob, s.mergeJob}, 120s);
    const JobRecord* killed = find(records, s.arrayJob + "_2");
    ASSERT_TRUE(killed) << describe(records);
    EXPECT_NE(killed->state, "COMPLETED") << "killed after it finished: the test needs a longer shard";
    const JobRecord* merge = find(records, s.mergeJob);
    ASSERT_TRUE(merge) << describe(records);
    EXPECT_EQ(merge->state, "CANCELLED") << describe(records);
    EXPECT_FALSE(fs::exists(merged));
    ASSERT_FALSE(fs::exists(shards / "shard-2-of-4.exr"));

    // Neither the three good shards alone nor with anything the kill left is a set.
    const std::vector<std::string> good{(shards / "shard-0-of-4.exr").string(),
                                        (shards / "shard-1-of-4.exr").string(),
                                        (shards / "shard-3-of-4.exr").string()};
    const fs::path probe = work_ / "probe.exr";
    const CommandResult incomplete = runLpv(concat({"merge", probe.string()}, good));
    EXPECT_NE(incomplete.exitCode, 0) << incomplete.output;
    EXPECT_NE(incomplete.output.find("2/4"), std::string::npos)
        << "names the missing shard: " << incomplete.output;
    for (const std::string& left : filesUnder(shards)) {
        if (std::ranges::find(good, (shards / left).string()) != good.end())
            continue;
        const CommandResult withLeftover =
            runLpv(concat({"merge", probe.string(), (shards / left).string()}, good));
        EXPECT_NE(withLeftover.exitCode, 0) << left << " completed the set: " << withLeftover.output;
    }
    EXPECT_FALSE(fs::exists(probe));

    // Shard 2 again, as docs/cluster.md says to, then the merge after it.
    const CommandResult again = cluster_->run(
        concat({"sbatch", "--parsable", "--array=2", "--export=ALL,LPV_SHARD_COUNT=4",
                "--output=" + (work_ / "slurm-%x-%A_%a.out").string(),
                (kJobFiles / "slurm-reference.sbatch").string(), project.string(), shards.string()},
               options),
        {"LPV=" + std::string(kLpvExecutable)}, work_);
    ASSERT_EQ(again.exitCode, 0) << again.output;
    const std::string againId = again.output.substr(0, again.output.find_first_of(";\n"));
    const CommandResult mergeAgain = cluster_->run({"sbatch", "--parsable", "--dependency=afterok:" + againId,
                                                    "--output=" + (work_ / "slurm-%x-%A.out").string(),
                                                    (kJobFiles / "slurm-reference-merge.sbatch").string(),
                                                    merged.string(), shards.string(), "4"},
                                                   {"LPV=" + std::string(kLpvExecutable)}, work_);
    ASSERT_EQ(mergeAgain.exitCode, 0) << mergeAgain.output;
    const std::string mergeAgainId = mergeAgain.output.substr(0, mergeAgain.output.find_first_of(";\n"));
    // Meanwhile one process renders shard 2 and the whole image.
    const CommandResult localShard = runLpv(concat(
        {"reference", project.string(), "-o", (work_ / "shard-2.exr").string(), "--shard", "2/4"}, options));
    ASSERT_EQ(localShard.exitCode, 0) << localShard.output;
    const CommandResult single =
        runLpv(concat({"reference", project.string(), "-o", (work_ / "single.exr").string()}, options));
    ASSERT_EQ(single.exitCode, 0) << single.output;
    expectAllCompleted(waitFor({againId, mergeAgainId}), 2);
    expectSamePixels(work_ / "shard-2.exr", shards / "shard-2-of-4.exr");
    expectSamePixels(work_ / "single.exr", merged);
}

// The report in pieces through submit-report.sh: coordinator, 2 shards,
// coordinator, 2 shards, coordinator as a chain of afterok jobs, with the
// errors one process measures.
TEST_F(Cluster, AShardedReportRunsAsAChainOfJobsAndMatchesOneProcess) {
    const std::vector<std::string> options{
        "--quick", "--scene", "cornell-box", "--question", "steps", "--width",  "48", "--height",
        "32",      "--spp",   "16",          "--frames",   "1",     "--warmup", "0",  "--radiosity-seconds",
        "5"};
    const CommandResult submitted = cluster_->run(
        concat({(kJobFiles / "submit-report.sh").string(), (work_ / "sharded").string(), "2"}, options),
        jobEnv(kLpvExecutable), work_);
    ASSERT_EQ(submitted.exitCode, 0) << submitted.output;
    const auto jobsAt = submitted.output.find("JOBS=\"");
    ASSERT_NE(jobsAt, std::string::npos) << submitted.output;
    std::vector<std::string> jobs;
    std::istringstream ids(
        submitted.output.substr(jobsAt + 6, submitted.output.find('"', jobsAt + 6) - jobsAt - 6));
    for (std::string id; ids >> id;)
        jobs.push_back(id);
    ASSERT_EQ(jobs.size(), 5u) << submitted.output;
    const CommandResult one =
        runLpv(concat({"bench", "report", "--out", (work_ / "whole").string()}, options));
    ASSERT_EQ(one.exitCode, 0) << one.output;
    expectAllCompleted(waitFor(jobs, 120s), 1 + 2 + 1 + 2 + 1);

    auto runsOf = [](const fs::path& file) {
        const auto j = nlohmann::json::parse(readTextFile(file), nullptr, false);
        return j.is_discarded() ? nlohmann::json() : j["scenes"][0]["runs"];
    };
    const auto whole = runsOf(work_ / "whole" / "report.json");
    const auto sharded = runsOf(work_ / "sharded" / "report.json");
    ASSERT_EQ(whole.size(), 3u) << "propagationSteps, three values in --quick";
    ASSERT_EQ(sharded.size(), whole.size());
    for (std::size_t i = 0; i < whole.size(); ++i) {
        EXPECT_EQ(sharded[i]["setting"], whole[i]["setting"]);
        for (const char* error : {"indirectMare", "indirectMeanRatio", "imageMare"})
            EXPECT_EQ(sharded[i][error], whole[i][error]) << whole[i]["setting"] << " " << error;
        EXPECT_GT(sharded[i]["totalMs"].get<double>(), 0.0);
    }
    EXPECT_TRUE(fs::exists(work_ / "sharded" / "report.md"));
}
