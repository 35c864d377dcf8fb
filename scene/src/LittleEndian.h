#pragma once
// The byte primitives of the project's binary files (mesh assets, bench
// packs): little-endian on disk whatever the machine, read and written with
// memcpy because a file's buffer has no alignment guarantee, and the
// "byte offset N" wording their errors share.
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <string>
#include <string_view>

namespace lpv::scene::binary {

template <class... Args>
std::string concat(const Args&... args) {
    std::ostringstream out;
    (out << ... << args);
    return out.str();
}

inline std::string atByte(std::uint64_t offset) { return concat("byte offset ", offset); }

template <class T>
T littleEndian(T v) {
    if constexpr (std::endian::native == std::endian::big)
        return std::byteswap(v);
    else
        return v;
}

template <class T>
void append(std::string& out, T v) {
    v = littleEndian(v);
    out.append(reinterpret_cast<const char*>(&v), sizeof v);
}

template <class T>
void storeAt(std::string& out, std::size_t at, T v) {
    v = littleEndian(v);
    std::memcpy(out.data() + at, &v, sizeof v);
}

template <class T>
T loadAt(std::string_view bytes, std::size_t at) {
    T v{};
    std::memcpy(&v, bytes.data() + at, sizeof v);
    return littleEndian(v);
}

} // namespace lpv::scene::binary
