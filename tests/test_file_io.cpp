// Tests for file I/O (src/formats/png.cpp): write_file_atomic, read_file, write_png, read_png.
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "casteljau/error.hpp"
#include "casteljau/file_io.hpp"
#include "casteljau/paint.hpp"
#include "casteljau/png.hpp"
#include "skip.hpp"

namespace fs = std::filesystem;
using casteljau::Error;
using casteljau::ErrorKind;
using casteljau::Pixmap;

namespace {

// A fresh, empty folder under the build tree, removed again at the end of the test.
struct TempDir {
    fs::path path;
    explicit TempDir(const std::string& name) : path(fs::path(CASTELJAU_BINARY_DIR) / "test-tmp" / name) {
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
    std::string operator/(const std::string& leaf) const { return (path / leaf).string(); }
};

std::set<std::string> listing(const fs::path& dir) {
    std::set<std::string> names;
    for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
    return names;
}

std::vector<std::uint8_t> bytes_of(const std::string& s) { return {s.begin(), s.end()}; }

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Runs f, which must throw Error(Io); returns the message.
template <class F>
std::string io_error(F&& f) {
    try {
        f();
    } catch (const Error& e) {
        CHECK(e.kind() == ErrorKind::Io);
        return e.what();
    }
    FAIL_CHECK("no Error(Io) was thrown");
    return {};
}

}  // namespace

TEST_CASE("write_file_atomic writes the bytes, read_file reads them back exactly", "[png]") {
    TempDir dir("file-io-roundtrip");
    std::vector<std::uint8_t> data(200000);
    std::mt19937 rng(11);
    for (auto& b : data) b = static_cast<std::uint8_t>(rng());
    data[0] = 0;  // embedded zero bytes are data like any other
    const std::string p = dir / "blob.bin";
    casteljau::write_file_atomic(p, data);
    CHECK(casteljau::read_file(p) == data);
    CHECK(listing(dir.path) == std::set<std::string>{"blob.bin"});  // no temporary file left

    // Empty files are fine both ways.
    casteljau::write_file_atomic(dir / "empty", std::vector<std::uint8_t>{});
    CHECK(fs::file_size(dir / "empty") == 0);
    CHECK(casteljau::read_file(dir / "empty").empty());
}

TEST_CASE("write_file_atomic gives a new file the mode open() would, under the umask", "[png]") {
    TempDir dir("file-io-mode");
    const mode_t mask = ::umask(022);  // read the umask (this test runs on one thread)
    ::umask(mask);
    const std::string p = dir / "new.txt";
    casteljau::write_file_atomic(p, bytes_of("x"));
    struct stat st {};
    REQUIRE(::stat(p.c_str(), &st) == 0);
    CHECK((st.st_mode & 0777) == (0666 & ~mask));
}

TEST_CASE("write_file_atomic replaces an existing file by rename, keeping its mode", "[png]") {
    TempDir dir("file-io-replace");
    const std::string p = dir / "out.png";
    casteljau::write_file_atomic(p, bytes_of("first version, rather long ......................"));
    REQUIRE(::chmod(p.c_str(), 0640) == 0);
    struct stat before {};
    REQUIRE(::stat(p.c_str(), &before) == 0);
    // Keep the old file open: a reader holding it keeps seeing the complete old content, which
    // is what an atomic replacement (a new inode renamed over the name) guarantees.
    std::ifstream old_reader(p, std::ios::binary);

    casteljau::write_file_atomic(p, bytes_of("second"));
    CHECK(slurp(p) == "second");
    struct stat after {};
    REQUIRE(::stat(p.c_str(), &after) == 0);
    CHECK(after.st_ino != before.st_ino);  // replaced, not rewritten in place
    CHECK((after.st_mode & 0777) == 0640);
    const std::string old_content{std::istreambuf_iterator<char>(old_reader), std::istreambuf_iterator<char>()};
    CHECK(old_content == "first version, rather long ......................");
    CHECK(listing(dir.path) == std::set<std::string>{"out.png"});
}

TEST_CASE("write_file_atomic into a missing folder is Error(Io) naming the path and reason", "[png]") {
    TempDir dir("file-io-missing-dir");
    const std::string p = dir / "no/such/folder/out.png";
    const std::string msg = io_error([&] { casteljau::write_file_atomic(p, bytes_of("data")); });
    CHECK_THAT(msg, Catch::Contains(p));
    CHECK_THAT(msg, Catch::Contains("No such file or directory"));
    CHECK(listing(dir.path).empty());
    // write_png goes the same way.
    Pixmap pm(2, 2);
    const std::string msg2 = io_error([&] { casteljau::write_png(pm, p); });
    CHECK_THAT(msg2, Catch::Contains(p));
    CHECK(listing(dir.path).empty());
}

TEST_CASE("write_file_atomic onto a directory is Error(Io) and leaves no temporary file", "[png]") {
    TempDir dir("file-io-onto-dir");
    fs::create_directories(dir.path / "sub");
    std::ofstream(dir / "sub/keep.txt") << "keep";
    const auto before_top = listing(dir.path);
    const auto before_sub = listing(dir.path / "sub");

    const std::string msg = io_error([&] { casteljau::write_file_atomic(dir / "sub", bytes_of("data")); });
    CHECK_THAT(msg, Catch::Contains(dir / "sub"));
    CHECK_THAT(msg, Catch::Contains("Is a directory"));
    const std::string msg2 = io_error([&] { casteljau::write_file_atomic(dir / "sub/", bytes_of("data")); });
    CHECK_THAT(msg2, Catch::Contains("Is a directory"));
    Pixmap pm(1, 1);
    io_error([&] { casteljau::write_png(pm, dir / "sub"); });

    CHECK(listing(dir.path) == before_top);
    CHECK(listing(dir.path / "sub") == before_sub);
    CHECK(fs::is_directory(dir.path / "sub"));
    CHECK(slurp(dir / "sub/keep.txt") == "keep");
    io_error([&] { casteljau::write_file_atomic("", bytes_of("data")); });
}

TEST_CASE("write_file_atomic failing mid-write removes its temporary file and keeps the old file", "[png]") {
    // Forces write() to fail with EFBIG by lowering RLIMIT_FSIZE below the data size for the one
    // call (SIGXFSZ ignored so that write() returns the error instead of killing the process).
    TempDir dir("file-io-write-fails");
    const std::string p = dir / "out.bin";
    casteljau::write_file_atomic(p, bytes_of("the old content"));
    const std::vector<std::uint8_t> big(1 << 20, 0xab);

    rlimit old_limit{};
    REQUIRE(::getrlimit(RLIMIT_FSIZE, &old_limit) == 0);
    rlimit low = old_limit;
    low.rlim_cur = 64 * 1024;
    auto* old_handler = std::signal(SIGXFSZ, SIG_IGN);
    REQUIRE(::setrlimit(RLIMIT_FSIZE, &low) == 0);
    std::string msg;
    ErrorKind kind = ErrorKind::InvalidArgument;
    bool threw = false;
    try {
        casteljau::write_file_atomic(p, big);
    } catch (const Error& e) {
        threw = true;
        kind = e.kind();
        msg = e.what();
    }
    ::setrlimit(RLIMIT_FSIZE, &old_limit);  // restore before any test output is written
    std::signal(SIGXFSZ, old_handler);

    REQUIRE(threw);
    CHECK(kind == ErrorKind::Io);
    CHECK_THAT(msg, Catch::Contains(p));
    CHECK_THAT(msg, Catch::Contains("File too large"));
    CHECK(slurp(p) == "the old content");
    CHECK(listing(dir.path) == std::set<std::string>{"out.bin"});
}

TEST_CASE("write_file_atomic through a symbolic link replaces the link's target", "[png]") {
    TempDir dir("file-io-symlink");
    casteljau::write_file_atomic(dir / "real.txt", bytes_of("old"));
    fs::create_symlink("real.txt", dir.path / "link.txt");
    casteljau::write_file_atomic(dir / "link.txt", bytes_of("new"));
    CHECK(fs::is_symlink(dir.path / "link.txt"));
    CHECK(slurp(dir / "real.txt") == "new");
    CHECK(listing(dir.path) == std::set<std::string>{"link.txt", "real.txt"});
}

TEST_CASE("write_file_atomic writes straight into a device such as /dev/null", "[png]") {
    if (!fs::exists("/dev/null")) CASTELJAU_SKIP("no /dev/null on this machine");
    casteljau::write_file_atomic("/dev/null", bytes_of("discarded"));
    CHECK(fs::is_character_file("/dev/null"));  // still the device, not replaced by a file
}

TEST_CASE("read_file: a missing file, a directory, an unreadable file are Error(Io)", "[png]") {
    TempDir dir("file-io-read-errors");
    const std::string missing = dir / "missing.png";
    std::string msg = io_error([&] { casteljau::read_file(missing); });
    CHECK_THAT(msg, Catch::Contains(missing));
    CHECK_THAT(msg, Catch::Contains("No such file or directory"));
    msg = io_error([&] { casteljau::read_png(missing); });
    CHECK_THAT(msg, Catch::Contains("No such file or directory"));

    msg = io_error([&] { casteljau::read_file(dir.path.string()); });
    CHECK_THAT(msg, Catch::Contains("Is a directory"));
    io_error([&] { casteljau::read_file(""); });
}

TEST_CASE("read_file: a file without read permission is Error(Io) naming the cause", "[png]") {
    if (::geteuid() == 0) CASTELJAU_SKIP("running as root, which reads any file whatever its permissions");
    TempDir dir("file-io-unreadable");
    const std::string locked = dir / "locked.png";
    std::ofstream(locked) << "secret";
    REQUIRE(::chmod(locked.c_str(), 0) == 0);
    const std::string msg = io_error([&] { casteljau::read_file(locked); });
    CHECK_THAT(msg, Catch::Contains("Permission denied"));
}

TEST_CASE("write_png/read_png round-trip a premultiplied pixmap through a file", "[png]") {
    TempDir dir("file-io-png");
    Pixmap pm(7, 5);
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 7; ++x) {
            const auto a = static_cast<std::uint8_t>(x * 40);
            pm.set_pixel(x, y, casteljau::PremulPixel{static_cast<std::uint8_t>(a * y / 4), 0, a, a});
        }
    const std::string p = dir / "pm.png";
    casteljau::write_png(pm, p);
    const Pixmap back = casteljau::read_png(p);
    REQUIRE(back.width() == 7);
    REQUIRE(back.height() == 5);
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 7; ++x) CHECK(back.pixel(x, y) == pm.pixel(x, y));
    CHECK(casteljau::read_file(p) == casteljau::encode_png(pm));
    CHECK(listing(dir.path) == std::set<std::string>{"pm.png"});
}

TEST_CASE("read_png of a non-PNG file is InvalidData naming the file", "[png]") {
    TempDir dir("file-io-bad-png");
    const std::string p = dir / "fake.png";
    std::ofstream(p) << "this is not a PNG file at all";
    try {
        casteljau::read_png(p);
        FAIL("no error");
    } catch (const Error& e) {
        CHECK(e.kind() == ErrorKind::InvalidData);
        CHECK_THAT(std::string(e.what()), Catch::Contains(p));
        CHECK_THAT(std::string(e.what()), Catch::Contains("signature"));
    }
    std::ofstream(dir / "empty.png");
    try {
        casteljau::read_png(dir / "empty.png");
        FAIL("no error");
    } catch (const Error& e) {
        CHECK(e.kind() == ErrorKind::InvalidData);
        CHECK_THAT(std::string(e.what()), Catch::Contains("empty"));
    }
}
