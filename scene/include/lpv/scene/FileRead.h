#pragma once
// Reading a whole file that a project, a scene or a user names, safely
// (issue #29): regular files only, and the size on disk checked against what
// the file can hold before anything is allocated. Every library reads
// through these (projects, mesh assets, camera paths, radiosity solutions,
// images, glTF buffers), so the checks and their words exist once.
#include "lpv/scene/Error.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace lpv::scene {

// Why `file` cannot be read as a file, or nothing when it is a regular file:
// "no such file", "is a folder, not a file", "is a FIFO (named pipe), not a
// regular file" (opening one would block until a writer came), a device or
// socket likewise, or "cannot look it up: " and the system's word for a name
// it cannot resolve ("File name too long" for a name over 255 bytes).
// Never throws: std::filesystem's throwing calls aborted `lpv info`,
// `render` and the editor on such names.
std::optional<std::string> notARegularFile(const std::filesystem::path& file);

// How large a file a reader accepts, and what it calls the file in the error:
// checked against the size on disk before reading, so a sparse 30 GB file is
// refused at once instead of read.
struct ReadLimit {
    std::uint64_t maxBytes = std::uint64_t{1} << 30; // 1 GiB
    std::string what = "file";
};

// The whole file. FileNotFound when there is none; IoError for anything else
// (notARegularFile's reasons, a file larger than `limit`).
Expected<std::string> readFileBytes(const std::filesystem::path& path, const ReadLimit& limit = {});

// A size for messages: "512 bytes", "64.0 MiB", "30.0 GiB".
std::string formatBytes(std::uint64_t bytes);

} // namespace lpv::scene
