#pragma once
// Errors as values: every load/parse/import returns std::expected<T, Error>.
#include <cstddef>
#include <expected>
#include <string>

namespace lpv::scene {

enum class ErrorCode {
    FileNotFound,
    IoError,
    Truncated,
    NotJson,
    UnknownFormat,
    NewerVersion,
    MissingField,
    TypeMismatch,
    MissingAsset,
    CorruptAsset,
    ChecksumMismatch,
    NonFinite,
    OutOfRange,
    UnknownParameter,
    IndexOutOfRange,
    InvalidValue,
    Cancelled, // the user stopped a long operation (a video export); not a failure to report
};

const char* toString(ErrorCode code);

// An error names the file, where in it (a JSON field path such as
// "materials[2].diffuseColor" or "byte offset 1234"), and what was wrong.
struct Error {
    ErrorCode code = ErrorCode::InvalidValue;
    std::string file;
    std::string location;
    std::string message;

    std::string describe() const;
};

template <class T>
using Expected = std::expected<T, Error>;

// An error's text quotes what it read (a path, a name, a value); quoting a
// 200 MB path must not make a 200 MB message (issue #29). Text longer than
// this keeps its start and end, and says how much of the middle was left out.
inline constexpr std::size_t kMaxErrorText = 1000;
std::string capErrorText(std::string text);

inline std::unexpected<Error> makeError(ErrorCode code, std::string file, std::string location,
                                        std::string message) {
    return std::unexpected(Error{code, capErrorText(std::move(file)), capErrorText(std::move(location)),
                                 capErrorText(std::move(message))});
}

} // namespace lpv::scene
