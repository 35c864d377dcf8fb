// Platform file (process liveness): stale temporary files, orphan texture
// copies, and rolling back a save of several steps (issue #29).
#include "lpv/scene/SaveCleanup.h"

#include "FileText.h"
#include "WindowsHeaders.h"
#include "lpv/scene/ProcessId.h"
#include "lpv/scene/ProjectTextures.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <climits>
#include <system_error>

#ifndef _WIN32
#include <cerrno>
#include <csignal>
#include <sys/stat.h>
#include <unistd.h>
#endif

#ifdef __linux__
#include <fstream>
#include <sstream>
#endif

namespace lpv::scene {
namespace {

namespace fs = std::filesystem;
using detail::fromUtf8;
using detail::utf8;

bool allDigits(std::string_view s) {
    return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

std::string lowerAscii(std::string s) {
    for (char& c : s)
        if (c >= 'A' && c <= 'Z')
            c = static_cast<char>(c - 'A' + 'a');
    return s;
}

// A regular file itself, not what a symbolic link of that name points to.
bool isRegularFile(const fs::path& path) {
    std::error_code ec;
    return fs::symlink_status(path, ec).type() == fs::file_type::regular;
}

// The file names in `folder` (none when it cannot be read).
std::vector<std::string> namesIn(const fs::path& folder) {
    std::vector<std::string> names;
    std::error_code ec;
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec))
        names.push_back(utf8(it->path().filename()));
    return names;
}

// False only when the system says no process has this id: a pid that cannot
// exist (a name that was never ours) counts as gone, one we may not signal
// as running.
bool processRunning(long long pid) {
    if (pid <= 0 || pid > INT_MAX)
        return false;
#ifdef _WIN32
    HANDLE process = ::OpenProcess(PROCESS_QUERY_LIMITED_INFORMATION, FALSE, static_cast<DWORD>(pid));
    if (!process)
        return ::GetLastError() != ERROR_INVALID_PARAMETER; // access denied: it runs
    DWORD code = 0;
    const bool exited = ::GetExitCodeProcess(process, &code) && code != STILL_ACTIVE;
    ::CloseHandle(process);
    return !exited;
#else
    return ::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH;
#endif
}

// Linux: whether the process with this pid started after `modified` (seconds
// since the epoch), i.e. it cannot have written a file last changed then.
// False wherever that cannot be told.
bool startedAfter([[maybe_unused]] long long pid, [[maybe_unused]] long long modified) {
#ifdef __linux__
    std::ifstream statFile("/proc/" + std::to_string(pid) + "/stat");
    std::string stat;
    std::getline(statFile, stat); // one line
    // "pid (comm) state ppid ...": comm may hold spaces and ')'; field 22 is the start time in ticks since
    // boot.
    const std::size_t close = stat.rfind(')');
    if (close == std::string::npos)
        return false;
    std::istringstream fields(stat.substr(close + 1));
    std::string field;
    int number = 2;
    while (number < 22 && fields >> field)
        ++number;
    unsigned long long ticks = 0;
    if (number != 22)
        return false;
    if (!allDigits(field) ||
        std::from_chars(field.data(), field.data() + field.size(), ticks).ec != std::errc())
        return false;
    std::ifstream systemStat("/proc/stat");
    long long bootTime = -1;
    for (std::string line; std::getline(systemStat, line);)
        if (line.rfind("btime ", 0) == 0)
            bootTime = std::atoll(line.c_str() + 6);
    const long ticksPerSecond = ::sysconf(_SC_CLK_TCK);
    if (bootTime <= 0 || ticksPerSecond <= 0)
        return false;
    const long long started =
        bootTime + static_cast<long long>(ticks / static_cast<unsigned long long>(ticksPerSecond));
    // Two seconds of slack: the boot time and the file time are rounded to seconds.
    return modified + 2 < started;
#else
    return false;
#endif
}

// Seconds since the epoch of the file's last change; nullopt when unknown.
std::optional<long long> modifiedSeconds([[maybe_unused]] const fs::path& file) {
#ifdef _WIN32
    return std::nullopt;
#else
    struct stat info {};
    if (::stat(file.c_str(), &info) != 0)
        return std::nullopt;
    return static_cast<long long>(info.st_mtime);
#endif
}

bool isStale(const fs::path& file, long long pid) {
    if (pid == processId())
        return false;
    if (!processRunning(pid))
        return true;
    const auto modified = modifiedSeconds(file);
    return modified && startedAfter(pid, *modified);
}

} // namespace

fs::path assetsFolderOf(const fs::path& projectFile) {
    return projectFile.parent_path() / fromUtf8(utf8(projectFile.stem()) + ".assets");
}

std::optional<TemporaryName> parseTemporaryName(std::string_view fileName) {
    const std::size_t at = fileName.rfind(".tmp-");
    if (at == std::string_view::npos || at == 0)
        return std::nullopt;
    const std::string_view rest = fileName.substr(at + 5);
    const std::size_t dash = rest.find('-');
    if (dash == std::string_view::npos)
        return std::nullopt;
    const std::string_view pid = rest.substr(0, dash);
    const std::string_view counter = rest.substr(dash + 1);
    if (!allDigits(pid) || !allDigits(counter) || pid.size() > 18)
        return std::nullopt;
    TemporaryName name{std::string(fileName.substr(0, at)), 0};
    std::from_chars(pid.data(), pid.data() + pid.size(), name.pid);
    return name;
}

std::size_t removeStaleTemporaries(const fs::path& folder,
                                   const std::function<bool(std::string_view)>& ours) {
    std::size_t removed = 0;
    for (const std::string& name : namesIn(folder)) {
        const auto temporary = parseTemporaryName(name);
        if (!temporary || !ours(temporary->base))
            continue;
        const fs::path file = folder / fromUtf8(name);
        if (!isRegularFile(file) || !isStale(file, temporary->pid))
            continue;
        std::error_code ec;
        if (fs::remove(file, ec))
            ++removed;
    }
    return removed;
}

std::size_t removeStaleTemporaries(const fs::path& file) {
    const std::string target = utf8(file.filename());
    if (target.empty())
        return 0;
    const fs::path folder = file.parent_path().empty() ? fs::path(".") : file.parent_path();
    return removeStaleTemporaries(folder, [&](std::string_view base) { return base == target; });
}

bool isTextureCopyName(std::string_view fileName) {
    if (fileName.size() < 18 || fileName[16] != '-')
        return false;
    for (std::size_t i = 0; i < 16; ++i) {
        const char c = fileName[i];
        if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f')))
            return false;
    }
    return !parseTemporaryName(fileName);
}

std::size_t removeOrphanTextures(const Scene& scene, const fs::path& projectFile) {
    const fs::path folder = assetsFolderOf(projectFile) / "textures";
    std::error_code ec;
    if (!fs::is_directory(folder, ec))
        return 0;
    std::set<std::string> named;
    for (const Material& m : scene.materials)
        for (const std::string* slot : textureSlots(m))
            if (!slot->empty()) {
                // Either separator: a slot written on Windows may hold backslashes.
                const std::size_t cut = slot->find_last_of("/\\");
                named.insert(lowerAscii(cut == std::string::npos ? *slot : slot->substr(cut + 1)));
            }
    std::size_t removed = 0;
    for (const std::string& name : namesIn(folder)) {
        const fs::path file = folder / fromUtf8(name);
        if (!isTextureCopyName(name) || named.contains(lowerAscii(name)) || !isRegularFile(file))
            continue;
        if (fs::remove(file, ec))
            ++removed;
    }
    return removed;
}

void SaveRollback::noteMissingFolders(fs::path folder) {
    std::error_code ec;
    while (!folder.empty() && fs::symlink_status(folder, ec).type() == fs::file_type::not_found) {
        if (std::find(newFolders_.begin(), newFolders_.end(), folder) == newFolders_.end())
            newFolders_.push_back(folder);
        const fs::path parent = folder.parent_path();
        if (parent == folder)
            break;
        folder = parent;
    }
}

void SaveRollback::willWrite(const fs::path& file) {
    std::error_code ec;
    if (fs::symlink_status(file, ec).type() == fs::file_type::not_found)
        newFiles_.push_back(file);
    noteMissingFolders(file.parent_path());
}

void SaveRollback::watchTextureCopies(const fs::path& folder) {
    const std::vector<std::string> names = namesIn(folder);
    watched_.emplace_back(folder, std::set<std::string>(names.begin(), names.end()));
    noteMissingFolders(folder);
}

void SaveRollback::undo() {
    std::error_code ec;
    for (const fs::path& file : newFiles_)
        if (isRegularFile(file))
            fs::remove(file, ec);
    for (const auto& [folder, before] : watched_)
        for (const std::string& name : namesIn(folder)) {
            const fs::path file = folder / fromUtf8(name);
            if (isTextureCopyName(name) && !before.contains(name) && isRegularFile(file))
                fs::remove(file, ec);
        }
    // Deepest first; fs::remove leaves a folder that is not empty.
    std::vector<fs::path> folders = newFolders_;
    std::sort(folders.begin(), folders.end(), [](const fs::path& a, const fs::path& b) {
        return std::distance(a.begin(), a.end()) > std::distance(b.begin(), b.end());
    });
    for (const fs::path& folder : folders)
        if (fs::symlink_status(folder, ec).type() == fs::file_type::directory)
            fs::remove(folder, ec);
    newFiles_.clear();
    newFolders_.clear();
    watched_.clear();
}

} // namespace lpv::scene
