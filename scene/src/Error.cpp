#include "lpv/scene/Error.h"

namespace lpv::scene {

const char* toString(ErrorCode code) {
    switch (code) {
    case ErrorCode::FileNotFound: return "file not found";
    case ErrorCode::IoError: return "I/O error";
    case ErrorCode::Truncated: return "truncated";
    case ErrorCode::NotJson: return "not JSON";
    case ErrorCode::UnknownFormat: return "unknown format";
    case ErrorCode::NewerVersion: return "newer version";
    case ErrorCode::MissingField: return "missing field";
    case ErrorCode::TypeMismatch: return "type mismatch";
    case ErrorCode::MissingAsset: return "missing asset";
    case ErrorCode::CorruptAsset: return "corrupt asset";
    case ErrorCode::ChecksumMismatch: return "checksum mismatch";
    case ErrorCode::NonFinite: return "not a finite number";
    case ErrorCode::OutOfRange: return "out of range";
    case ErrorCode::UnknownParameter: return "unknown parameter";
    case ErrorCode::IndexOutOfRange: return "index out of range";
    case ErrorCode::InvalidValue: return "invalid value";
    case ErrorCode::Cancelled: return "cancelled";
    }
    return "error";
}

std::string capErrorText(std::string text) {
    if (text.size() <= kMaxErrorText)
        return text;
    // Cut on UTF-8 character boundaries (never inside a multi-byte sequence).
    auto boundary = [&](std::size_t at) {
        while (at > 0 && at < text.size() && (static_cast<unsigned char>(text[at]) & 0xC0u) == 0x80u)
            --at;
        return at;
    };
    const std::size_t headEnd = boundary(kMaxErrorText * 6 / 10);
    const std::size_t tailStart = boundary(text.size() - kMaxErrorText * 3 / 10);
    return text.substr(0, headEnd) + " [... " + std::to_string(tailStart - headEnd) + " bytes left out ...] " +
           text.substr(tailStart);
}

std::string Error::describe() const {
    std::string out = file.empty() ? std::string("<input>") : file;
    if (!location.empty())
        out += ": " + location;
    out += ": " + message;
    return out;
}

} // namespace lpv::scene
