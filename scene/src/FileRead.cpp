#include "lpv/scene/FileRead.h"

#include <fstream>
#include <iomanip>
#include <iterator>
#include <sstream>

namespace lpv::scene {

namespace fs = std::filesystem;

std::optional<std::string> notARegularFile(const fs::path& file) {
    std::error_code ec;
    const fs::file_status status = fs::status(file, ec);
    if (status.type() == fs::file_type::not_found)
        return "no such file";
    if (ec)
        return "cannot look it up: " + ec.message();
    if (fs::is_directory(status))
        return "is a folder, not a file";
    if (fs::is_regular_file(status))
        return std::nullopt;
    const char* kind = fs::is_fifo(status)             ? "a FIFO (named pipe)"
                       : fs::is_character_file(status) ? "a character device"
                       : fs::is_block_file(status)     ? "a block device"
                       : fs::is_socket(status)         ? "a socket"
                                                       : "something else";
    return std::string("is ") + kind + ", not a regular file";
}

std::string formatBytes(std::uint64_t bytes) {
    static constexpr const char* kUnits[] = {"bytes", "KiB", "MiB", "GiB", "TiB"};
    double value = double(bytes);
    std::size_t unit = 0;
    while (value >= 1024.0 && unit + 1 < std::size(kUnits)) {
        value /= 1024.0;
        ++unit;
    }
    std::ostringstream out;
    if (unit == 0)
        out << bytes << " bytes";
    else
        out << std::fixed << std::setprecision(1) << value << " " << kUnits[unit];
    return out.str();
}

Expected<std::string> readFileBytes(const fs::path& path, const ReadLimit& limit) {
    const std::string where = path.string();
    if (const auto why = notARegularFile(path)) {
        if (*why == "no such file")
            return makeError(ErrorCode::FileNotFound, where, "", *why);
        const bool special = why->ends_with(", not a regular file");
        return makeError(ErrorCode::IoError, where, "", *why + (special ? ": only regular files are read" : ""));
    }
    auto tooLarge = [&](std::uint64_t size) {
        return makeError(ErrorCode::IoError, where, "",
                         "the file is " + formatBytes(size) + ", more than a " + limit.what + " can be (" +
                             formatBytes(limit.maxBytes) + "); refused before reading");
    };
    std::error_code ec;
    const std::uintmax_t onDisk = fs::file_size(path, ec);
    if (ec)
        return makeError(ErrorCode::IoError, where, "", "cannot read its size: " + ec.message());
    if (onDisk > limit.maxBytes)
        return tooLarge(onDisk);
    std::ifstream in(path, std::ios::binary);
    if (in)
        in.seekg(0, std::ios::end);
    const std::streamoff size = in ? static_cast<std::streamoff>(in.tellg()) : -1;
    if (size < 0)
        return makeError(ErrorCode::IoError, where, "", "cannot open the file for reading");
    if (std::uint64_t(size) > limit.maxBytes) // grew since it was measured
        return tooLarge(std::uint64_t(size));
    in.seekg(0, std::ios::beg);
    std::string bytes(static_cast<std::size_t>(size), '\0');
    in.read(bytes.data(), size);
    if (in.gcount() != size)
        return makeError(ErrorCode::IoError, where, "", "the file could not be read completely");
    return bytes;
}

} // namespace lpv::scene
