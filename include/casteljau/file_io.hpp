// casteljau/file_io.hpp: reading whole files and writing them atomically.
//
// read_file and read_standard_input read everything up to the end, bounded by
// Limits::input_bytes (casteljau/limits.hpp). write_file_atomic writes to a temporary file in the
// destination's folder that is renamed over the destination only once complete, so a failure
// never leaves a half-written file. Paths are passed to the operating system as given (relative
// to the current directory). Thread-safety: free functions; distinct files from distinct threads.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace casteljau {

// Writes bytes to `path` through a temporary file (mkstemp, same folder) + fsync + rename, so the
// destination is either untouched or completely replaced. An existing file keeps its permission
// bits; a new one gets 0666 minus the umask. A symbolic link is followed (its target is replaced);
// a device or FIFO (/dev/null, /dev/stdout) is written directly. Throws Error(Io) naming the path
// and the system's reason, after removing the temporary file.
void write_file_atomic(const std::string& path, std::span<const std::uint8_t> bytes);
// True for the name of a temporary file of write_file_atomic (".NAME.tmp-XXXXXX"), which only a
// process killed in the middle of a write leaves behind.
bool is_atomic_write_temporary(std::string_view file_name);
// Reads a whole file: a regular file, or a pipe, socket or device up to its end. Throws Error(Io)
// naming the path and the reason, Error(Limit) past Limits::input_bytes (checked against a regular
// file's size before reading, and as the bytes arrive from anything else, so that /dev/zero or an
// endless pipe ends in an error, not in all the memory there is).
std::vector<std::uint8_t> read_file(const std::string& path);
// Reads standard input to its end, with the same bound and errors as read_file.
std::vector<std::uint8_t> read_standard_input();

}  // namespace casteljau
