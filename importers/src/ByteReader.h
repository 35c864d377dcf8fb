#pragma once
// A bounds-checked little-endian reader over a byte span, for binary parsers.
// Every read checks what is left first; a read past the end throws
// FormatError, which the parser turns into an error value at its boundary
// (exceptions never leave a parser). Counts read from a file are checked
// against the bytes that remain before anything is allocated for them, so a
// corrupt count in a 100-byte file cannot ask for gigabytes.
#include "lpv/scene/Error.h"

#include <glm/glm.hpp>

#include <bit>
#include <cstdint>
#include <cstring>
#include <exception>
#include <span>
#include <string>
#include <string_view>

namespace lpv::importers {

// Thrown inside a parser only; offset is where the offending field starts.
class FormatError : public std::exception {
  public:
    FormatError(scene::ErrorCode code, std::size_t offset, std::string message)
        : code_(code), offset_(offset), message_(std::move(message)) {}

    scene::ErrorCode code() const { return code_; }
    std::size_t offset() const { return offset_; }
    const std::string& message() const { return message_; }
    const char* what() const noexcept override { return message_.c_str(); }

  private:
    scene::ErrorCode code_;
    std::size_t offset_;
    std::string message_;
};

class ByteReader {
  public:
    explicit ByteReader(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}

    std::size_t offset() const { return offset_; }
    std::size_t size() const { return bytes_.size(); }
    std::size_t remaining() const { return bytes_.size() - offset_; }
    bool atEnd() const { return offset_ == bytes_.size(); }

    std::uint8_t u8(std::string_view what) { return readScalar<std::uint8_t>(what); }
    std::uint16_t u16(std::string_view what) { return readScalar<std::uint16_t>(what); }
    std::uint32_t u32(std::string_view what) { return readScalar<std::uint32_t>(what); }
    std::uint64_t u64(std::string_view what) { return readScalar<std::uint64_t>(what); }
    float f32(std::string_view what) { return readScalar<float>(what); }

    glm::vec3 vec3(std::string_view what) {
        require(12, what);
        const float x = f32(what);
        const float y = f32(what);
        const float z = f32(what);
        return {x, y, z};
    }

    // A view of the next n bytes (no copy).
    std::span<const std::uint8_t> bytes(std::size_t n, std::string_view what) {
        require(n, what);
        const auto view = bytes_.subspan(offset_, n);
        offset_ += n;
        return view;
    }

    void skip(std::uint64_t n, std::string_view what) {
        require(n, what);
        offset_ += static_cast<std::size_t>(n);
    }

    // Throws unless count elements of elementSize bytes fit in what is left.
    // 64-bit arithmetic: a u32 count times a small element size cannot wrap.
    void requireArray(std::uint64_t count, std::uint64_t elementSize, std::string_view what) const {
        const std::uint64_t needed = count * elementSize;
        if (needed > remaining())
            throw FormatError(scene::ErrorCode::Truncated, offset_,
                              std::string(what) + ": a count of " + std::to_string(count) + " needs " +
                                  std::to_string(needed) + " bytes but only " + std::to_string(remaining()) +
                                  " remain (file truncated or count corrupt)");
    }

    void require(std::uint64_t n, std::string_view what) const {
        if (n > remaining())
            throw FormatError(scene::ErrorCode::Truncated, offset_,
                              "file ends after " + std::to_string(bytes_.size()) + " bytes; " +
                                  std::string(what) + " needs " + std::to_string(n) + " bytes but only " +
                                  std::to_string(remaining()) + " remain");
    }

  private:
    // memcpy: the data has no alignment, and the formats we read are
    // little-endian like every machine we build for.
    template <class T> T readScalar(std::string_view what) {
        static_assert(std::endian::native == std::endian::little, "ByteReader assumes a little-endian host");
        require(sizeof(T), what);
        T value;
        std::memcpy(&value, bytes_.data() + offset_, sizeof(T));
        offset_ += sizeof(T);
        return value;
    }

    std::span<const std::uint8_t> bytes_;
    std::size_t offset_ = 0;
};

} // namespace lpv::importers
