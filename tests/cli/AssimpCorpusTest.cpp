// Assimp's own test models (Debian's assimp-testmodels, issue #42) through
// `lpv import`, each in its own process with a time limit: every OBJ, glTF
// (.gltf, .glb), 3DS and FBX either imports (exit 0, and `lpv info` then
// loads the project) or is refused with a message (exit 1 and an "lpv: ..."
// line). A signal (an abort, a segmentation fault), another exit code or a
// hang fails the test, naming the file. Skipped when the package is absent.
//
// Files run two at a time (LPV_CORPUS_JOBS overrides): CI machines have two
// cores, and one import is mostly a single thread. Each step may take
// LPV_CORPUS_TIMEOUT seconds (30 by default; the models are small and take
// about half a second each).
#include "ChildProcess.h"
#include "TestPaths.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

using namespace lpv::test;
namespace fs = std::filesystem;

namespace {

fs::path modelsDir() {
    return fs::path(LPV_TEST_ASSIMP_MODELS_DIR);
}

int envInt(const char* name, int fallback) {
    const char* v = std::getenv(name);
    const int n = v ? std::atoi(v) : 0;
    return n > 0 ? n : fallback;
}

std::string lowerExtension(const fs::path& p) {
    std::string e = p.extension().string();
    std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return e;
}

std::vector<fs::path> modelsWith(const std::set<std::string>& extensions) {
    std::vector<fs::path> files;
    std::error_code ec;
    for (fs::recursive_directory_iterator it(modelsDir(), ec), end; !ec && it != end; it.increment(ec))
        if (it->is_regular_file(ec) && extensions.count(lowerExtension(it->path())))
            files.push_back(it->path());
    std::sort(files.begin(), files.end());
    return files;
}

// The last lines of a program's output, for a failure message.
std::string tail(const std::string& output, std::size_t lines = 6) {
    std::size_t at = output.size();
    for (std::size_t n = 0; n <= lines && at != std::string::npos && at > 0; ++n)
        at = output.rfind('\n', at - 1);
    return at == std::string::npos ? output : output.substr(at + 1);
}

// A refusal names what was wrong on a line of its own: "lpv: <message>".
bool hasErrorLine(const std::string& output) {
    std::istringstream in(output);
    for (std::string line; std::getline(in, line);)
        if (line.rfind("lpv: ", 0) == 0 && line.find_first_not_of(" \t\r", 5) != std::string::npos)
            return true;
    return false;
}

enum class Outcome { Imported, Refused, Failed };

struct FileResult {
    fs::path model;
    Outcome outcome = Outcome::Failed;
    std::string why; // for a failure: the symptom and the output's end
    double seconds = 0.0;
};

FileResult importOne(const fs::path& model, const fs::path& work, std::chrono::seconds limit) {
    FileResult r{model, Outcome::Failed, {}, 0.0};
    fs::create_directories(work);
    const fs::path project = work / "model.lpvproj";
    const ChildResult imported = runChild({kLpvExecutable, "import", model.string(), "-o", project.string()},
                                          limit, work / "import.log");
    r.seconds = imported.seconds;
    if (imported.exited() && imported.exitCode == 1 && hasErrorLine(imported.output)) {
        r.outcome = Outcome::Refused;
        return r;
    }
    if (!imported.exited() || imported.exitCode != 0) {
        r.why = "lpv import: " + imported.describe() +
                (imported.exited() && imported.exitCode == 1 ? ", without an 'lpv: ...' error line" : "") +
                "\n" + tail(imported.output);
        return r;
    }
    const ChildResult info = runChild({kLpvExecutable, "info", project.string()}, limit, work / "info.log");
    r.seconds += info.seconds;
    if (!info.exited() || info.exitCode != 0) {
        r.why = "imported, but lpv info of the project: " + info.describe() + "\n" + tail(info.output);
        return r;
    }
    r.outcome = Outcome::Imported;
    return r;
}

void importAll(const std::string& format, const std::set<std::string>& extensions) {
    if (!fs::is_directory(modelsDir()))
        GTEST_SKIP() << "Assimp's test models are not installed (" << modelsDir().string()
                     << "; Debian: apt-get install assimp-testmodels)";
    const std::vector<fs::path> models = modelsWith(extensions);
    ASSERT_FALSE(models.empty()) << "no " << format << " files under " << modelsDir().string();

    const fs::path work =
        fs::temp_directory_path() / ("lpv-corpus-" + format + "-" + std::to_string(::getpid()));
    fs::remove_all(work);
    const std::chrono::seconds limit(envInt("LPV_CORPUS_TIMEOUT", 30));
    const int jobs = envInt("LPV_CORPUS_JOBS", 2);

    std::vector<FileResult> results(models.size());
    std::atomic<std::size_t> next{0};
    const auto start = std::chrono::steady_clock::now();
    std::vector<std::thread> workers;
    for (int j = 0; j < jobs; ++j)
        workers.emplace_back([&] {
            for (std::size_t i; (i = next++) < models.size();)
                results[i] = importOne(models[i], work / std::to_string(i), limit);
        });
    for (std::thread& w : workers)
        w.join();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    std::size_t imported = 0, refused = 0, failed = 0;
    for (const FileResult& r : results) {
        imported += r.outcome == Outcome::Imported;
        refused += r.outcome == Outcome::Refused;
        if (r.outcome == Outcome::Failed) {
            ++failed;
            ADD_FAILURE() << fs::relative(r.model, modelsDir()).string() << ": " << r.why;
        }
    }
    std::printf("[corpus] %s: %zu files, %zu imported, %zu refused with a message, %zu crashed or hung; "
                "%.1f s with %d jobs\n",
                format.c_str(), models.size(), imported, refused, failed, seconds, jobs);
    if (failed == 0)
        fs::remove_all(work);
    else
        std::printf("[corpus] outputs of every file kept in %s\n", work.string().c_str());
}

} // namespace

TEST(AssimpCorpus, EveryObjImportsOrIsRefused) {
    importAll("obj", {".obj"});
}

TEST(AssimpCorpus, EveryGltfImportsOrIsRefused) {
    importAll("gltf", {".gltf", ".glb"});
}

TEST(AssimpCorpus, Every3dsImportsOrIsRefused) {
    importAll("3ds", {".3ds"});
}

TEST(AssimpCorpus, EveryFbxImportsOrIsRefused) {
    importAll("fbx", {".fbx"});
}

// The corpus tests' verdicts rest on these: an abort is told from an exit
// code, and a hang is cut at its limit.
TEST(ChildProcess, TellsASignalAnExitCodeAndAHangApart) {
    const fs::path work = fs::temp_directory_path() / ("lpv-child-" + std::to_string(::getpid()));
    fs::create_directories(work);
    const ChildResult aborted = runChild({"/bin/sh", "-c", "echo dying; kill -ABRT $$"},
                                         std::chrono::seconds(10), work / "abort.log");
    EXPECT_EQ(aborted.signal, SIGABRT) << aborted.describe();
    EXPECT_EQ(aborted.output, "dying\n");
    const ChildResult failed =
        runChild({"/bin/sh", "-c", "exit 134"}, std::chrono::seconds(10), work / "exit.log");
    EXPECT_TRUE(failed.exited());
    EXPECT_EQ(failed.exitCode, 134);
    const ChildResult hung = runChild({"/bin/sleep", "30"}, std::chrono::seconds(1), work / "hang.log");
    EXPECT_TRUE(hung.timedOut);
    EXPECT_LT(hung.seconds, 5.0);
    fs::remove_all(work);
}
