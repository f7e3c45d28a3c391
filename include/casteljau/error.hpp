// casteljau/error.hpp: the one exception type the library throws at its API boundaries.
//
// Every failure that reaches a caller (parsing, I/O, limits, invalid arguments) is a casteljau::Error
// with a kind and a one-line message. Hot loops never throw; they are guarded by checks made before
// they start. Thread-safety: plain value type.
#pragma once

#include <cstddef>
#include <cstdint>
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

// Fixed limits, and the defaults of the run-time limits of casteljau/limits.hpp (Limits: the
// canvas, path and segment values here are also the highest values it accepts). README.md
// "Limits" lists them all.
namespace limits {
inline constexpr int kMaxCanvasDimension = 32768;            // pixels per side
inline constexpr long long kMaxCanvasPixels = 268435456LL;   // 2^28 pixels = 1 GiB of RGBA8
inline constexpr std::size_t kMaxPathPoints = 1u << 24;      // points in one Path
inline constexpr std::size_t kMaxFlattenedSegments = 1u << 23;  // line segments after flattening (~340 MB of edges)
inline constexpr int kMaxFlattenDepth = 16;                  // subdivision depth per curve
inline constexpr int kMaxNestingDepth = 64;                  // SVG element / group nesting (default)
inline constexpr double kMaxCoordinate = 1e15;               // |coordinate| after transform
inline constexpr std::size_t kMaxPngChunkBytes = 16u << 20;  // one PNG chunk's data (text, ICC, Exif)
inline constexpr std::uint32_t kMaxPngAncillaryChunks = 1000;  // text, sPLT and unknown chunks kept per PNG
}  // namespace limits

}  // namespace casteljau
