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

// The whole file. FileNotFound when there is none, IoError for anything else.
Expected<std::string> readFileBytes(const std::filesystem::path& path);

} // namespace lpv::scene::detail
