#include "FileText.h"

#include <fstream>
#include <iomanip>
#include <iterator>
#include <sstream>

namespace lpv::scene::detail {

namespace fs = std::filesystem;

std::string utf8(const fs::path& p) {
    const std::u8string s = p.u8string();
    return std::string(s.begin(), s.end());
}

fs::path fromUtf8(const std::string& s) { return fs::path(std::u8string(s.begin(), s.end())); }

std::string hex16(std::uint64_t v) {
    std::ostringstream out;
    out << std::hex;
    out.width(16);
    out.fill('0');
    out << v;
    return out.str();
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
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (status.type() == fs::file_type::not_found)
        return makeError(ErrorCode::FileNotFound, where, "", "no such file");
    if (ec)
        return makeError(ErrorCode::IoError, where, "", "cannot read: " + ec.message());
    if (fs::is_directory(status))
        return makeError(ErrorCode::IoError, where, "", "is a folder, not a file");
    if (!fs::is_regular_file(status)) {
        const char* kind = fs::is_fifo(status)       ? "a FIFO (named pipe)"
                           : fs::is_character_file(status) ? "a character device"
                           : fs::is_block_file(status)     ? "a block device"
                           : fs::is_socket(status)         ? "a socket"
                                                           : "not a regular file";
        return makeError(ErrorCode::IoError, where, "",
                         std::string("is ") + kind + ", not a regular file: only regular files are read");
    }
    const std::uintmax_t onDisk = fs::file_size(path, ec);
    if (ec)
        return makeError(ErrorCode::IoError, where, "", "cannot read its size: " + ec.message());
    if (onDisk > limit.maxBytes)
        return makeError(ErrorCode::IoError, where, "",
                         "the file is " + formatBytes(onDisk) + ", more than a " + limit.what + " can be (" +
                             formatBytes(limit.maxBytes) + "); refused before reading");
    std::ifstream in(path, std::ios::binary);
    if (in)
        in.seekg(0, std::ios::end);
    const std::streamoff size = in ? static_cast<std::streamoff>(in.tellg()) : -1;
    if (size < 0)
        return makeError(ErrorCode::IoError, where, "", "cannot open the file for reading");
    if (std::uint64_t(size) > limit.maxBytes) // grew since it was measured
        return makeError(ErrorCode::IoError, where, "",
                         "the file is " + formatBytes(std::uint64_t(size)) + ", more than a " + limit.what +
                             " can be (" + formatBytes(limit.maxBytes) + "); refused before reading");
    in.seekg(0, std::ios::beg);
    std::string bytes(static_cast<std::size_t>(size), '\0');
    in.read(bytes.data(), size);
    if (in.gcount() != size)
        return makeError(ErrorCode::IoError, where, "", "the file could not be read completely");
    return bytes;
}

} // namespace lpv::scene::detail
