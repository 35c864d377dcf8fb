#pragma once
// File and path helpers shared by the project loader and saver (internal).
#include "lpv/scene/Error.h"

#include <cstdint>
#include <filesystem>
#include <string>

namespace lpv::scene::detail {

// JSON text is UTF-8; paths are converted explicitly so non-ASCII names also
// work where the native encoding is not UTF-8 (Windows).
std::string utf8(const std::filesystem::path& p);
std::filesystem::path fromUtf8(const std::string& s);

// 16 lower-case hex digits (content hashes in asset names).
std::string hex16(std::uint64_t v);

// How large a file a reader accepts, and what it calls the file in the
// error: checked against the size on disk before anything is allocated, so a
// sparse 30 GB file is refused at once instead of read (issue #29).
struct ReadLimit {
    std::uint64_t maxBytes = std::uint64_t{1} << 30; // 1 GiB
    std::string what = "file";
};
inline const ReadLimit kProjectFileLimit{std::uint64_t{64} << 20, "project file"};
inline const ReadLimit kCameraPathFileLimit{std::uint64_t{64} << 20, "camera path file"};

// The whole file. FileNotFound when there is none; IoError for anything else:
// a folder, a FIFO, device or socket (opening a FIFO would block until a
// writer comes; regular files only), a file larger than `limit`.
Expected<std::string> readFileBytes(const std::filesystem::path& path, const ReadLimit& limit = {});

// "30.0 GB", "64.0 MiB"-style sizes for messages: bytes with a unit.
std::string formatBytes(std::uint64_t bytes);

} // namespace lpv::scene::detail
