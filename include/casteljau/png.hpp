// casteljau/png.hpp: PNG files through libpng, and atomic file writes.
//
// Files hold 8-bit RGBA with straight alpha (sRGB chunk written); Pixmaps hold premultiplied
// alpha, converted on the way in and out. Writing goes to a temporary file in the destination's
// folder that is renamed over the destination only once complete, so a failure never leaves a
// half-written file. Thread-safety: free functions; distinct files from distinct threads.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "casteljau/paint.hpp"

namespace casteljau {

std::vector<std::uint8_t> encode_png(const Pixmap& pixmap);
Pixmap decode_png(std::span<const std::uint8_t> bytes);  // any PNG colour type/bit depth -> RGBA8

// Throws Error(Io) when the file cannot be written/read, Error(InvalidData) for a corrupt PNG.
void write_png(const Pixmap& pixmap, const std::string& path);
Pixmap read_png(const std::string& path);

// Writes bytes to `path` through a temporary file + rename. Throws Error(Io).
void write_file_atomic(const std::string& path, std::span<const std::uint8_t> bytes);
// Reads a whole file. Throws Error(Io) naming the path and the reason.
std::vector<std::uint8_t> read_file(const std::string& path);

}  // namespace casteljau
