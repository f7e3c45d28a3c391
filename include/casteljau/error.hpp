// casteljau/error.hpp: the one exception type the library throws at its API boundaries.
//
// Every failure that reaches a caller (parsing, I/O, limits, invalid arguments) is a casteljau::Error
// with a kind and a one-line message. Hot loops never throw; they are guarded by checks made before
// they start. Thread-safety: plain value type.
#pragma once

#include <stdexcept>
#include <string>

namespace casteljau {

enum class ErrorKind {
    InvalidArgument,  // a caller passed a value outside the documented domain (bad usage)
    Parse,            // text input (path data, colour, SVG, JSON, numbers) is malformed
    InvalidData,      // input parsed but its content is unusable (NaN, negative size, ...)
    Limit,            // input exceeds a documented limit (canvas size, path size, nesting depth)
    Io,               // a file could not be read or written
    Font,             // FreeType or HarfBuzz refused a font
};

class Error : public std::runtime_error {
public:
    Error(ErrorKind kind, const std::string& message) : std::runtime_error(message), kind_(kind) {}
    ErrorKind kind() const noexcept { return kind_; }

private:
    ErrorKind kind_;
};

}  // namespace casteljau
