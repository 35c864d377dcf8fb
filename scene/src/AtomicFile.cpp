// Atomic replacement of one file: the bytes go to a temporary file in the
// target's folder (same file system, so the rename cannot turn into a copy),
// which is flushed to the disk and then renamed over the target. Readers see
// the old file or the new one, never a mixture, even if we crash midway.
#include "FileText.h"
#include "lpv/scene/Project.h"
#include "lpv/scene/ProcessId.h"

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <system_error>

#ifdef _WIN32
#include <fcntl.h>
#include <io.h>
#else
#include <fcntl.h>
#include <unistd.h>
#endif

namespace lpv::scene {
namespace {

namespace fs = std::filesystem;

std::atomic<unsigned> tempCounter{0};

// "x": fail rather than reuse a file that already has the temporary's name.
std::FILE* createExclusive(const fs::path& path) {
#ifdef _WIN32
    return _wfopen(path.c_str(), L"wbx");
#else
    return std::fopen(path.c_str(), "wbx");
#endif
}

// Pushes the file's data to the disk, so the rename never exposes a file
// whose contents are still only in the OS cache.
bool syncToDisk(std::FILE* f) {
#ifdef _WIN32
    return _commit(_fileno(f)) == 0;
#else
    return ::fsync(::fileno(f)) == 0;
#endif
}

// Makes the rename itself durable (POSIX; on Windows the rename is already
// journaled). Best effort: the new file is in place either way.
void syncFolder([[maybe_unused]] const fs::path& folder) {
#ifndef _WIN32
    const int fd = ::open(folder.empty() ? "." : folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd >= 0) {
        ::fsync(fd);
        ::close(fd);
    }
#endif
}

// errno after a failed call; EIO in the rare case the C library left it unset.
int lastError() { return errno != 0 ? errno : EIO; }

std::string describeErrno(const std::string& what, const fs::path& path, int error) {
    return what + " " + path.string() + ": " + std::generic_category().message(error);
}

// Writes `bytes` to a new file at `temp` and syncs it. Returns an empty string
// on success, else what went wrong; a file it created is removed again (and
// one it did not create, because the name was taken, is left alone).
std::string writeAndSync(const fs::path& temp, std::string_view bytes) {
    std::FILE* f = createExclusive(temp);
    if (!f)
        return describeErrno("cannot create the temporary file", temp, lastError());
    errno = 0;
    int error = 0;
    if (!bytes.empty() && std::fwrite(bytes.data(), 1, bytes.size(), f) != bytes.size())
        error = lastError();
    if (error == 0 && std::fflush(f) != 0)
        error = lastError();
    if (error == 0 && !syncToDisk(f))
        error = lastError();
    if (std::fclose(f) != 0 && error == 0)
        error = lastError();
    if (error == 0)
        return {};
    std::error_code ignored;
    fs::remove(temp, ignored);
    return describeErrno("cannot write the temporary file", temp, error);
}

} // namespace

Expected<void> writeFileAtomically(const fs::path& file, std::string_view bytes) {
    auto written = detail::writeFileAtomicallyFolderUnsynced(file, bytes);
    if (written)
        syncFolder(file.parent_path());
    return written;
}

void detail::syncFolderToDisk(const fs::path& folder) { syncFolder(folder); }

Expected<void> detail::writeFileAtomicallyFolderUnsynced(const fs::path& file, std::string_view bytes) {
    if (file.filename().empty())
        return makeError(ErrorCode::IoError, file.string(), "", "not a file name");
    const fs::path folder = file.parent_path();
    std::error_code ec;
    if (!folder.empty()) {
        fs::create_directories(folder, ec);
        if (ec)
            return makeError(ErrorCode::IoError, file.string(), "",
                             "cannot create the folder " + folder.string() + ": " + ec.message());
    }

    fs::path temp = file;
    temp += ".tmp-" + std::to_string(processId()) + "-" + std::to_string(tempCounter.fetch_add(1));
    if (const std::string failure = writeAndSync(temp, bytes); !failure.empty())
        return makeError(ErrorCode::IoError, file.string(), "", failure);
    fs::rename(temp, file, ec);
    if (ec) {
        std::error_code ignored;
        fs::remove(temp, ignored);
        return makeError(ErrorCode::IoError, file.string(), "", "cannot replace the file: " + ec.message());
    }
    return {};
}

Expected<void> syncFileToDisk(const fs::path& file) {
#ifdef _WIN32
    const int fd = ::_wopen(file.c_str(), _O_RDWR | _O_BINARY);
#else
    const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
#endif
    if (fd < 0)
        return makeError(ErrorCode::IoError, file.string(), "",
                         describeErrno("cannot open", file, lastError()));
    errno = 0;
#ifdef _WIN32
    int error = ::_commit(fd) == 0 ? 0 : lastError();
    if (::_close(fd) != 0 && error == 0)
        error = lastError();
#else
    int error = ::fsync(fd) == 0 ? 0 : lastError();
    if (::close(fd) != 0 && error == 0)
        error = lastError();
#endif
    if (error != 0)
        return makeError(ErrorCode::IoError, file.string(), "", describeErrno("cannot write", file, error));
    return {};
}

} // namespace lpv::scene
