#include "FileText.h"

#include <fstream>
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

Expected<std::string> readFileBytes(const fs::path& path) {
    const std::string where = path.string();
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (status.type() == fs::file_type::not_found)
        return makeError(ErrorCode::FileNotFound, where, "", "no such file");
    if (ec)
        return makeError(ErrorCode::IoError, where, "", "cannot read: " + ec.message());
    if (fs::is_directory(status))
        return makeError(ErrorCode::IoError, where, "", "is a folder, not a file");
    std::ifstream in(path, std::ios::binary);
    if (in)
        in.seekg(0, std::ios::end);
    const std::streamoff size = in ? static_cast<std::streamoff>(in.tellg()) : -1;
    if (size < 0)
        return makeError(ErrorCode::IoError, where, "", "cannot open the file for reading");
    in.seekg(0, std::ios::beg);
    std::string bytes(static_cast<std::size_t>(size), '\0');
    in.read(bytes.data(), size);
    if (in.gcount() != size)
        return makeError(ErrorCode::IoError, where, "", "the file could not be read completely");
    return bytes;
}

} // namespace lpv::scene::detail
