#pragma once
// The private scratch folder of one fuzzer process: the targets that load
// from a path (projects, glTF, OBJ) write each input there and load it, so
// relative references resolve against real neighbouring files.
//
// The folder is `<parent>/lpv-fuzz-<target>-<pid>`, with <parent> from
// LPV_FUZZ_TMP (environment), else /dev/shm (tmpfs: millions of small writes
// never reach a disk), else the system temporary folder. It is removed at
// exit; after a crash scripts/fuzz.sh removes it, or the next fuzzer that
// starts (removeStaleWorkFolders).
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

namespace lpv::fuzz {

namespace detail {

inline std::vector<std::filesystem::path>& workFolders() {
    static std::vector<std::filesystem::path> folders;
    return folders;
}

inline void removeWorkFolders() {
    for (const std::filesystem::path& folder : workFolders()) {
        std::error_code ignored;
        std::filesystem::remove_all(folder, ignored);
    }
}

} // namespace detail

[[noreturn]] inline void setUpFailed(std::string_view target, const std::string& what) {
    std::fprintf(stderr, "fuzz_%.*s: %s\n", int(target.size()), target.data(), what.c_str());
    std::exit(1);
}

inline std::filesystem::path tempParent() {
    if (const char* env = std::getenv("LPV_FUZZ_TMP"); env && *env)
        return env;
    std::error_code ec;
    if (std::filesystem::is_directory("/dev/shm", ec))
        return "/dev/shm";
    return std::filesystem::temp_directory_path();
}

// Removes the work folders of processes that are gone: a crash skips the
// removal at exit, and a replayed crash or a -fork child would otherwise
// leave one per run.
inline void removeStaleWorkFolders(const std::filesystem::path& parent) {
    std::error_code ec;
    for (const std::filesystem::directory_entry& entry : std::filesystem::directory_iterator(parent, ec)) {
        const std::string name = entry.path().filename().string();
        const std::size_t dash = name.rfind('-');
        if (!name.starts_with("lpv-fuzz-") || dash == std::string::npos || dash + 1 == name.size())
            continue;
        const std::string pid = name.substr(dash + 1);
        if (pid.find_first_not_of("0123456789") != std::string::npos || pid.size() > 9)
            continue;
        if (kill(pid_t(std::stol(pid)), 0) != 0 && errno == ESRCH) {
            std::error_code ignored;
            std::filesystem::remove_all(entry.path(), ignored);
        }
    }
}

// Creates (empty) and registers for removal at exit. Exits on failure.
inline std::filesystem::path makeWorkFolder(std::string_view target) {
    removeStaleWorkFolders(tempParent());
    const std::filesystem::path folder =
        tempParent() / ("lpv-fuzz-" + std::string(target) + "-" + std::to_string(getpid()));
    std::error_code ec;
    std::filesystem::remove_all(folder, ec);
    std::filesystem::create_directories(folder, ec);
    if (ec)
        setUpFailed(target, "cannot create " + folder.string() + ": " + ec.message());
    if (detail::workFolders().empty())
        std::atexit(detail::removeWorkFolders);
    detail::workFolders().push_back(folder);
    return folder;
}

// Copies a file or folder (recursively) into the work folder. Exits on failure.
inline void copyInto(std::string_view target, const std::filesystem::path& from,
                     const std::filesystem::path& to) {
    std::error_code ec;
    std::filesystem::create_directories(to.parent_path(), ec);
    if (!ec)
        std::filesystem::copy(
            from, to,
            std::filesystem::copy_options::recursive | std::filesystem::copy_options::overwrite_existing, ec);
    if (ec)
        setUpFailed(target, "cannot copy " + from.string() + " to " + to.string() + ": " + ec.message());
}

// Writes the bytes (truncating); a failure aborts, since every later
// execution would silently load a stale file.
inline void writeInput(const std::filesystem::path& file, std::string_view bytes) {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) {
        std::fprintf(stderr, "fuzz: cannot write %s\n", file.string().c_str());
        std::abort();
    }
}

// The work folder of the project targets: a copy of the committed
// projects/cornell-box/cornell-box.assets, so a project written next to it
// as cornell-box.lpvproj finds real .lpvmesh files (checksums, vertex and
// triangle counts) where the Cornell box project names them.
inline std::filesystem::path makeCornellBoxFolder(std::string_view target,
                                                  const std::filesystem::path& projectDir) {
    const std::filesystem::path folder = makeWorkFolder(target);
    copyInto(target, projectDir / "cornell-box.assets", folder / "cornell-box.assets");
    return folder;
}

} // namespace lpv::fuzz
