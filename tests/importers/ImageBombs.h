#pragma once
// Image files made byte by byte for the image-budget tests (issue #42): only
// the headers that claim more pixels than their files could hold. Shared by
// the library's tests and the same bombs through `lpv compare`.
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace lpv::test::bombs {

inline std::string le16(unsigned v) { return {char(v & 0xFF), char(v >> 8 & 0xFF)}; }
inline std::string le32(std::uint32_t v) { return le16(v & 0xFFFF) + le16(v >> 16); }
inline std::string be16(unsigned v) { return {char(v >> 8 & 0xFF), char(v & 0xFF)}; }
inline std::string be32(std::uint32_t v) {
    return {char(v >> 24 & 0xFF), char(v >> 16 & 0xFF), char(v >> 8 & 0xFF), char(v & 0xFF)};
}

// This process's own temporary folder `name`-<pid>.
inline std::filesystem::path tempFolder(const std::string& name) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / (name + "-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    return dir;
}

// `bytes` as the file `name` in tempFolder(folder).
inline std::filesystem::path writeTempFile(const std::string& folder, const std::string& name, const std::string& bytes) {
    const std::filesystem::path file = tempFolder(folder) / name;
    std::ofstream(file, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
    return file;
}

// The 35-byte GIF of the issue: a 1x1 frame on a w x h logical screen.
inline std::string gifBomb(unsigned w, unsigned h) {
    std::string b =
        "GIF89a" + le16(w) + le16(h) + std::string("\x80\x00\x00", 3) + std::string("\0\0\0\xff\xff\xff", 6);
    b += "," + le16(0) + le16(0) + le16(1) + le16(1) + std::string(1, '\0');
    b += std::string("\x02\x02\x44\x01\x00", 5) + ";";
    return b;
}

// An OpenEXR scanline header (no pixel data): `channels` of `type` (1 half, 2 float).
inline std::string exrHeader(int w, int h, int channels, int type, int compression) {
    std::string b("\x76\x2f\x31\x01\x02\x00\x00\x00", 8);
    auto attr = [&](const std::string& name, const std::string& kind, const std::string& value) {
        b += name + '\0' + kind + '\0' + le32(std::uint32_t(value.size())) + value;
    };
    std::string list;
    for (int c = 0; c < channels; ++c)
        list += "c" + std::to_string(c) + '\0' + le32(std::uint32_t(type)) + std::string(4, '\0') + le32(1) +
                le32(1);
    list += '\0';
    attr("channels", "chlist", list);
    attr("compression", "compression", std::string(1, char(compression)));
    const std::string box = le32(0) + le32(0) + le32(std::uint32_t(w - 1)) + le32(std::uint32_t(h - 1));
    attr("dataWindow", "box2i", box);
    attr("displayWindow", "box2i", box);
    attr("lineOrder", "lineOrder", std::string(1, '\0'));
    attr("pixelAspectRatio", "float", le32(0x3f800000));
    attr("screenWindowCenter", "v2f", std::string(8, '\0'));
    attr("screenWindowWidth", "float", le32(0x3f800000));
    b += '\0';
    return b;
}

} // namespace lpv::test::bombs
