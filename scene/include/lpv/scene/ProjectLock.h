#pragma once
// Saves that know about each other (issue #42, docs/project-format.md,
// "Concurrent saves"). Every save of a project holds an advisory lock on a
// lock file beside it, `.<Name>.lpvproj.lock`, across writing the assets,
// renaming the project file and the clean-up, so one save's clean-up never
// deletes what another save's project file names. A load-modify-save (an
// import, a path import) also records the project file's identity when it
// starts and refuses to save over a file another process wrote meanwhile.
#include "lpv/scene/Error.h"

#include <chrono>
#include <cstdint>
#include <filesystem>

namespace lpv::scene {

// How long a save waits for another process's save before it gives up.
// Saves take seconds at most; a minute-long import holds the lock only for
// its save, not while it reads its input.
inline constexpr std::chrono::milliseconds kProjectLockWait{10000};

// `<folder>/.<Name>.lpvproj.lock` for `<folder>/<Name>.lpvproj`. It exists
// only while a save holds it (POSIX): the holder removes it before letting
// go, and whoever locked a file that is no longer at that name tries again,
// so the removal never lets two writers in at once. On Windows it stays.
std::filesystem::path projectLockFile(const std::filesystem::path& projectFile);

// Which file a path names right now: absent, or its device, inode, size and
// change times. A save renames a new file into place, so any save by anyone
// changes it.
struct ProjectFileIdentity {
    bool exists = false;
    std::uint64_t device = 0;
    std::uint64_t inode = 0;
    std::uint64_t size = 0;
    std::int64_t modifiedNs = 0;
    std::int64_t changedNs = 0;

    bool operator==(const ProjectFileIdentity&) const = default;
};
ProjectFileIdentity projectFileIdentity(const std::filesystem::path& file);

// An exclusive advisory lock on a project (flock on Linux and macOS,
// LockFileEx on Windows), released when the object goes. Move-only. Locks
// are per open file, so a process that holds one and asks again for the
// same project waits for itself: pass the held lock on (SaveOptions).
class ProjectLock {
  public:
    // Waits up to `wait` for the lock. The error names the lock file and
    // says that another process is saving the project.
    static Expected<ProjectLock> acquire(const std::filesystem::path& projectFile,
                                         std::chrono::milliseconds wait = kProjectLockWait);

    ProjectLock(ProjectLock&& other) noexcept;
    ProjectLock& operator=(ProjectLock&& other) noexcept;
    ProjectLock(const ProjectLock&) = delete;
    ProjectLock& operator=(const ProjectLock&) = delete;
    ~ProjectLock();

    // The project file this lock guards (as given to acquire).
    const std::filesystem::path& projectFile() const { return projectFile_; }

  private:
    ProjectLock() = default;
    void release();

    std::filesystem::path projectFile_;
    std::intptr_t handle_ = -1; // a file descriptor, or a Windows HANDLE
};

// The error a save returns when the project file is no longer the one
// `since` describes; `operation` names what ran ("import", "path import").
Error projectChangedError(const std::filesystem::path& projectFile, const std::string& operation);

} // namespace lpv::scene
