// Core stage: reading whole files and writing them atomically (include/casteljau/file_io.hpp).
#include "casteljau/file_io.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <string_view>

#include "casteljau/error.hpp"
#include "casteljau/limits.hpp"

namespace casteljau {

namespace {

std::string quote(const std::string& path) { return "'" + path + "'"; }

[[noreturn]] void throw_io(const std::string& what, const std::string& path, int err) {
    throw Error(ErrorKind::Io, what + " " + quote(path) + ": " + std::strerror(err));
}

class FileDescriptor {
public:
    explicit FileDescriptor(int fd) : fd_(fd) {}
    FileDescriptor(const FileDescriptor&) = delete;
    FileDescriptor& operator=(const FileDescriptor&) = delete;
    ~FileDescriptor() {
        if (fd_ >= 0) ::close(fd_);
    }
    int get() const { return fd_; }
    // Closes now and reports close()'s error (0 or an errno value).
    int close() {
        const int r = ::close(fd_);
        fd_ = -1;
        return r == 0 ? 0 : errno;
    }

private:
    int fd_;
};

// Writes all bytes; returns 0 or an errno value.
int write_all(int fd, std::span<const std::uint8_t> bytes) {
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0) {
            if (errno == EINTR) continue;
            return errno;
        }
        if (n == 0) return EIO;
        done += static_cast<std::size_t>(n);
    }
    return 0;
}

// The process umask, read without changing it (umask() would be a race between threads).
mode_t current_umask() {
    mode_t mask = 022;
    if (std::FILE* f = std::fopen("/proc/self/status", "re")) {
        char line[256];
        while (std::fgets(line, sizeof line, f) != nullptr) {
            unsigned value = 0;
            if (std::sscanf(line, "Umask: %o", &value) == 1) {
                mask = static_cast<mode_t>(value & 0777);
                break;
            }
        }
        std::fclose(f);
    }
    return mask;
}

}  // namespace

bool is_atomic_write_temporary(std::string_view name) {
    constexpr std::string_view kTag = ".tmp-";
    if (name.size() < 1 + kTag.size() + 6 || name.front() != '.') return false;
    return name.compare(name.size() - 6 - kTag.size(), kTag.size(), kTag) == 0;
}

void write_file_atomic(const std::string& path, std::span<const std::uint8_t> bytes) {
    if (path.empty()) throw Error(ErrorKind::Io, "cannot write a file with an empty name");
    if (path.back() == '/') throw_io("cannot write", path, EISDIR);

    std::string target = path;  // a symbolic link is followed: its target is replaced
    struct stat st {};
    bool exists = ::stat(path.c_str(), &st) == 0;
    if (exists && S_ISDIR(st.st_mode)) throw_io("cannot write", path, EISDIR);
    if (exists && !S_ISREG(st.st_mode)) {
        // A device, FIFO or socket (/dev/null, /dev/stdout, a pipe): write to it directly; there
        // is nothing to rename over, and replacing it would be wrong.
        FileDescriptor fd(::open(path.c_str(), O_WRONLY | O_CLOEXEC));
        if (fd.get() < 0) throw_io("cannot write", path, errno);
        if (int err = write_all(fd.get(), bytes)) throw_io("cannot write", path, err);
        if (int err = fd.close()) throw_io("cannot write", path, err);
        return;
    }
    struct stat lst {};
    if (exists && ::lstat(path.c_str(), &lst) == 0 && S_ISLNK(lst.st_mode)) {
        if (char* real = ::realpath(path.c_str(), nullptr)) {
            target = real;
            std::free(real);
        }
    }

    // The temporary file: ".NAME.XXXXXX.tmp"-like, next to the destination (same file system,
    // so rename() is atomic). The name part is shortened to keep within NAME_MAX.
    const std::size_t slash = target.rfind('/');
    const std::string dir = slash == std::string::npos ? "." : (slash == 0 ? "/" : target.substr(0, slash));
    const std::string prefix = slash == std::string::npos ? "" : target.substr(0, slash + 1);
    const std::string base = slash == std::string::npos ? target : target.substr(slash + 1);
    std::string temp = prefix + "." + base.substr(0, 96) + ".tmp-XXXXXX";
    FileDescriptor fd(::mkstemp(temp.data()));
    if (fd.get() < 0) {
        const int err = errno;
        throw Error(ErrorKind::Io, "cannot write " + quote(path) + ": cannot create a temporary file in " + quote(dir) +
                                       ": " + std::strerror(err));
    }
    auto fail = [&](int err) {
        ::unlink(temp.c_str());
        throw_io("cannot write", path, err);
    };
    if (int err = write_all(fd.get(), bytes)) fail(err);
    // mkstemp creates the file 0600; give it the mode the destination had, or what a plain
    // open(O_CREAT, 0666) would have given it under the current umask.
    const mode_t mode = exists ? (st.st_mode & 0777) : (0666 & ~current_umask());
    if (::fchmod(fd.get(), mode) != 0) fail(errno);
    if (::fsync(fd.get()) != 0) fail(errno);
    if (int err = fd.close()) fail(err);
    if (::rename(temp.c_str(), target.c_str()) != 0) fail(errno);
}

namespace {

[[noreturn]] void input_too_large(const std::string& name, std::uint64_t max_bytes) {
    throw Error(ErrorKind::Limit,
                name + " is larger than " + std::to_string(max_bytes) + " bytes (Limits::input_bytes)");
}

// Reads fd to its end; `name` names it in errors ("'PATH'" or "standard input").
std::vector<std::uint8_t> read_descriptor(int fd, const std::string& name) {
    const std::uint64_t max_bytes = current_limits().input_bytes;
    struct stat st {};
    if (::fstat(fd, &st) != 0) throw Error(ErrorKind::Io, "cannot read " + name + ": " + std::strerror(errno));
    if (S_ISDIR(st.st_mode)) throw Error(ErrorKind::Io, "cannot read " + name + ": " + std::strerror(EISDIR));
    std::vector<std::uint8_t> out;
    if (S_ISREG(st.st_mode) && st.st_size > 0) {
        if (static_cast<std::uint64_t>(st.st_size) > max_bytes) input_too_large(name, max_bytes);
        out.reserve(static_cast<std::size_t>(st.st_size));
    }
    std::uint8_t buf[65536];
    for (;;) {
        const ssize_t n = ::read(fd, buf, sizeof buf);
        if (n < 0) {
            if (errno == EINTR) continue;
            throw Error(ErrorKind::Io, "cannot read " + name + ": " + std::strerror(errno));
        }
        if (n == 0) break;
        if (out.size() + static_cast<std::uint64_t>(n) > max_bytes) input_too_large(name, max_bytes);
        out.insert(out.end(), buf, buf + n);
    }
    return out;
}

}  // namespace

std::vector<std::uint8_t> read_file(const std::string& path) {
    if (path.empty()) throw Error(ErrorKind::Io, "cannot read a file with an empty name");
    FileDescriptor fd(::open(path.c_str(), O_RDONLY | O_CLOEXEC));
    if (fd.get() < 0) throw_io("cannot read", path, errno);
    return read_descriptor(fd.get(), quote(path));
}

std::vector<std::uint8_t> read_standard_input() { return read_descriptor(STDIN_FILENO, "standard input"); }

}  // namespace casteljau
