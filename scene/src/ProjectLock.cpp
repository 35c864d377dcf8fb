// Platform file (advisory locks, file identity): the per-project save lock
// of issue #42 (lpv/scene/ProjectLock.h).
#include "lpv/scene/ProjectLock.h"

#include "FileText.h"
#include "WindowsHeaders.h"

#include <system_error>
#include <thread>
#include <utility>

#ifndef _WIN32
#include <cerrno>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>
#endif

namespace lpv::scene {
namespace {

namespace fs = std::filesystem;
using detail::fromUtf8;
using detail::utf8;

// Often enough that a waiting save starts soon after the other one ends,
// seldom enough to cost nothing.
constexpr std::chrono::milliseconds kPollInterval{20};

std::string seconds(std::chrono::milliseconds wait) {
    const long long ms = wait.count();
    return ms % 1000 == 0 ? std::to_string(ms / 1000) + " s" : std::to_string(ms) + " ms";
}

std::unexpected<Error> busy(const fs::path& projectFile, const fs::path& lockFile,
                            std::chrono::milliseconds wait) {
    return makeError(ErrorCode::IoError, projectFile.string(), "",
                     "another process is saving this project (it holds " + lockFile.string() + "); waited " +
                         seconds(wait) + ", nothing was saved; try again when it has finished");
}

} // namespace

fs::path projectLockFile(const fs::path& projectFile) {
    return projectFile.parent_path() / fromUtf8("." + utf8(projectFile.filename()) + ".lock");
}

Error projectChangedError(const fs::path& projectFile, const std::string& operation) {
    return Error{ErrorCode::IoError, projectFile.string(), "",
                 "the project was written by another process while this " + operation +
                     " ran; nothing was saved, so that process's work stays (run the " + operation +
                     " again)"};
}

#ifdef _WIN32

ProjectFileIdentity projectFileIdentity(const fs::path& file) {
    ProjectFileIdentity id;
    HANDLE h = ::CreateFileW(file.c_str(), 0, FILE_SHARE_READ | FILE_SHARE_WRITE | FILE_SHARE_DELETE, nullptr,
                             OPEN_EXISTING, FILE_ATTRIBUTE_NORMAL, nullptr);
    if (h == INVALID_HANDLE_VALUE)
        return id;
    BY_HANDLE_FILE_INFORMATION info{};
    if (::GetFileInformationByHandle(h, &info)) {
        id.exists = true;
        id.device = info.dwVolumeSerialNumber;
        id.inode = (std::uint64_t{info.nFileIndexHigh} << 32) | info.nFileIndexLow;
        id.size = (std::uint64_t{info.nFileSizeHigh} << 32) | info.nFileSizeLow;
        id.modifiedNs =
            static_cast<std::int64_t>(((std::uint64_t{info.ftLastWriteTime.dwHighDateTime} << 32) |
                                       info.ftLastWriteTime.dwLowDateTime) *
                                      100);
        id.changedNs = static_cast<std::int64_t>(
            ((std::uint64_t{info.ftCreationTime.dwHighDateTime} << 32) | info.ftCreationTime.dwLowDateTime) *
            100);
    }
    ::CloseHandle(h);
    return id;
}

Expected<ProjectLock> ProjectLock::acquire(const fs::path& projectFile, std::chrono::milliseconds wait) {
    const fs::path lockFile = projectLockFile(projectFile);
    HANDLE h = ::CreateFileW(lockFile.c_str(), GENERIC_READ | GENERIC_WRITE,
                             FILE_SHARE_READ | FILE_SHARE_WRITE | FILE_SHARE_DELETE, nullptr, OPEN_ALWAYS,
                             FILE_ATTRIBUTE_HIDDEN, nullptr);
    if (h == INVALID_HANDLE_VALUE)
        return makeError(ErrorCode::IoError, projectFile.string(), "",
                         "cannot open the lock file " + lockFile.string() + ": " +
                             std::system_category().message(static_cast<int>(::GetLastError())));
    const auto deadline = std::chrono::steady_clock::now() + wait;
    for (;;) {
        OVERLAPPED whole{};
        if (::LockFileEx(h, LOCKFILE_EXCLUSIVE_LOCK | LOCKFILE_FAIL_IMMEDIATELY, 0, MAXDWORD, MAXDWORD,
                         &whole))
            break;
        if (std::chrono::steady_clock::now() >= deadline) {
            ::CloseHandle(h);
            return busy(projectFile, lockFile, wait);
        }
        std::this_thread::sleep_for(kPollInterval);
    }
    ProjectLock lock;
    lock.projectFile_ = projectFile;
    lock.handle_ = reinterpret_cast<std::intptr_t>(h);
    return lock;
}

void ProjectLock::release() {
    if (handle_ != -1)
        ::CloseHandle(reinterpret_cast<HANDLE>(handle_)); // releases the lock
    handle_ = -1;
}

#else

ProjectFileIdentity projectFileIdentity(const fs::path& file) {
    ProjectFileIdentity id;
    struct stat info {};
    if (::stat(file.c_str(), &info) != 0)
        return id;
    id.exists = true;
    id.device = static_cast<std::uint64_t>(info.st_dev);
    id.inode = static_cast<std::uint64_t>(info.st_ino);
    id.size = static_cast<std::uint64_t>(info.st_size);
#ifdef __APPLE__
    id.modifiedNs = std::int64_t{info.st_mtimespec.tv_sec} * 1000000000 + info.st_mtimespec.tv_nsec;
    id.changedNs = std::int64_t{info.st_ctimespec.tv_sec} * 1000000000 + info.st_ctimespec.tv_nsec;
#else
    id.modifiedNs = std::int64_t{info.st_mtim.tv_sec} * 1000000000 + info.st_mtim.tv_nsec;
    id.changedNs = std::int64_t{info.st_ctim.tv_sec} * 1000000000 + info.st_ctim.tv_nsec;
#endif
    return id;
}

// Opens (creating) the lock file; -1 with errno set when it cannot. A
// missing folder is made: the save would make it next anyway.
int openLockFile(const fs::path& lockFile) {
    int fd = ::open(lockFile.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0 && errno == ENOENT && !lockFile.parent_path().empty()) {
        std::error_code ec;
        fs::create_directories(lockFile.parent_path(), ec);
        fd = ::open(lockFile.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    }
    return fd;
}

// Whether `fd` is still the file at `lockFile`: the holder before us may
// have removed it (release does) after we opened it, and a lock on a
// removed file keeps no one else out.
bool stillNamed(int fd, const fs::path& lockFile) {
    struct stat held {
    }, named{};
    return ::fstat(fd, &held) == 0 && ::stat(lockFile.c_str(), &named) == 0 && held.st_dev == named.st_dev &&
           held.st_ino == named.st_ino;
}

Expected<ProjectLock> ProjectLock::acquire(const fs::path& projectFile, std::chrono::milliseconds wait) {
    const fs::path lockFile = projectLockFile(projectFile);
    const auto deadline = std::chrono::steady_clock::now() + wait;
    for (;;) {
        const int fd = openLockFile(lockFile);
        if (fd < 0)
            return makeError(ErrorCode::IoError, projectFile.string(), "",
                             "cannot open the lock file " + lockFile.string() + ": " +
                                 std::generic_category().message(errno));
        if (::flock(fd, LOCK_EX | LOCK_NB) == 0) {
            if (stillNamed(fd, lockFile)) {
                ProjectLock lock;
                lock.projectFile_ = projectFile;
                lock.handle_ = fd;
                return lock;
            }
            ::close(fd); // removed by the holder before us: lock the new one
            continue;
        }
        const int error = errno;
        ::close(fd);
        if (error != EWOULDBLOCK && error != EINTR)
            return makeError(ErrorCode::IoError, projectFile.string(), "",
                             "cannot lock " + lockFile.string() + ": " +
                                 std::generic_category().message(error));
        if (std::chrono::steady_clock::now() >= deadline)
            return busy(projectFile, lockFile, wait);
        std::this_thread::sleep_for(kPollInterval);
    }
}

// The lock file goes while we still hold it, so no project folder keeps
// it; a process that opened it meanwhile sees it is gone (stillNamed).
void ProjectLock::release() {
    if (handle_ == -1)
        return;
    std::error_code ec;
    fs::remove(projectLockFile(projectFile_), ec);
    ::close(static_cast<int>(handle_)); // releases the lock
    handle_ = -1;
}

#endif

ProjectLock::ProjectLock(ProjectLock&& other) noexcept
    : projectFile_(std::move(other.projectFile_)), handle_(std::exchange(other.handle_, -1)) {}

ProjectLock& ProjectLock::operator=(ProjectLock&& other) noexcept {
    if (this != &other) {
        release();
        projectFile_ = std::move(other.projectFile_);
        handle_ = std::exchange(other.handle_, -1);
    }
    return *this;
}

ProjectLock::~ProjectLock() {
    release();
}

} // namespace lpv::scene
