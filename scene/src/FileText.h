#pragma once
// File and path helpers shared by the project loader and saver (internal).
#include "lpv/scene/Error.h"
#include "lpv/scene/FileRead.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace lpv::scene::detail {

// JSON text is UTF-8; paths are converted explicitly so non-ASCII names also
// work where the native encoding is not UTF-8 (Windows).
std::string utf8(const std::filesystem::path& p);
std::filesystem::path fromUtf8(const std::string& s);

// 16 lower-case hex digits (content hashes in asset names).
std::string hex16(std::uint64_t v);

// The readers' limits for the files the project format consists of
// (lpv/scene/FileRead.h has readFileBytes itself).
using scene::readFileBytes;
using scene::ReadLimit;
inline const ReadLimit kProjectFileLimit{std::uint64_t{64} << 20, "project file"};
inline const ReadLimit kCameraPathFileLimit{std::uint64_t{64} << 20, "camera path file"};

// writeFileAtomically without its last step, the fsync of the folder, for a
// save that puts many files in one folder: it syncs the folder once
// (syncFolderToDisk) before it writes the file that names them. One sync per
// mesh asset made a save of 16,000 meshes take twice as long.
Expected<void> writeFileAtomicallyFolderUnsynced(const std::filesystem::path& file, std::string_view bytes);
void syncFolderToDisk(const std::filesystem::path& folder);

} // namespace lpv::scene::detail
