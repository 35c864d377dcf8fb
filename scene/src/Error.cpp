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

std::string Error::describe() const {
    std::string out = file.empty() ? std::string("<input>") : file;
    if (!location.empty())
        out += ": " + location;
    out += ": " + message;
    return out;
}

} // namespace lpv::scene
