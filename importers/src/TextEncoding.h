#pragma once
// Legacy 8-bit names (game formats written on Windows) to valid UTF-8, so a
// name read from any file can go straight into the project (JSON) and the UI.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace lpv::importers {

// Windows-1250 (Central European: Mafia is a Czech game, its names use
// č, š, ř, ...) to UTF-8. ASCII is kept; the five undefined bytes become
// U+FFFD; C0 control characters (and DEL) become '?' so a name stays
// printable. The result is always valid UTF-8, whatever the input.
std::string windows1250ToUtf8(std::span<const std::uint8_t> bytes);

// `text` itself when it is valid UTF-8; otherwise the same bytes read as
// Windows-1250 (a legacy 8-bit name from a Windows tool), which is always
// valid. nullopt when `text` was valid already.
std::optional<std::string> legacyNameToUtf8(const std::string& text);

// Appends the UTF-8 encoding of a code point (at most U+FFFF here).
void appendUtf8(std::string& out, char32_t codePoint);

// A UTF-8 file name (glTF uris, Assimp's char* names) as a path. Replaces
// std::filesystem::u8path, deprecated since C++20 (GCC 14 warns of it).
std::filesystem::path utf8Path(std::string_view utf8);

} // namespace lpv::importers
