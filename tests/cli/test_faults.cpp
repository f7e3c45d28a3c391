// Faults around the command line, run as real processes: a full disk (a file-size limit), an
// output folder that cannot be written, truncated input files, and a tile run killed in the
// middle and resumed. Each must end in a one-line error (or, for the kill, a resumed run equal to
// an uninterrupted one) and never leave a partial file under the final name.
#include <catch2/catch.hpp>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "casteljau/file_io.hpp"
#include "casteljau/png.hpp"
#include "cli_util.hpp"

using casteljau::test::run_cli;
using casteljau::test::shell_quote;
namespace fs = std::filesystem;

namespace {

const std::string kWorld = std::string(CASTELJAU_SOURCE_DIR) + "/tests/data/maps/countries-110m.json";

// Runs `casteljau ARGS` after the shell command `prefix` (ulimit, timeout), returning the status.
casteljau::test::CliResult run_with(const std::string& prefix, const std::string& args) {
    const std::string wrapped = "-c " + shell_quote(prefix + " " + std::string(CASTELJAU_CLI_PATH) + " " + args);
    // run_cli runs "CLI ARGS"; run the shell instead through a tiny indirection.
    const fs::path dir = casteljau::testing::process_temp_dir() / "faults";
    fs::create_directories(dir);
    const std::string out = (dir / "out").string(), err = (dir / "err").string();
    const int raw = std::system(("sh " + wrapped + " > " + out + " 2> " + err).c_str());
    casteljau::test::CliResult r;
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
    std::ifstream e(err);
    r.err.assign(std::istreambuf_iterator<char>(e), std::istreambuf_iterator<char>());
    return r;
}

std::vector<std::string> names_in(const fs::path& dir) {
    std::vector<std::string> v;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        if (e.is_regular_file()) v.push_back(fs::relative(e.path(), dir).string());
    return v;
}

std::map<std::string, std::vector<std::uint8_t>> tiles_in(const fs::path& dir) {
    std::map<std::string, std::vector<std::uint8_t>> out;
    for (const auto& e : fs::recursive_directory_iterator(dir)) {
        const std::string name = e.path().filename().string();
        if (e.is_regular_file() && name.find(".tmp-") == std::string::npos)
            out[fs::relative(e.path(), dir).string()] = casteljau::read_file(e.path().string());
    }
    return out;
}

}  // namespace

TEST_CASE("faults: a full disk (file-size limit) is a one-line error and leaves no file", "[faults][cli]") {
    const fs::path dir = casteljau::test::scratch_dir("faults_full_disk");
    const std::string png = (dir / "world.png").string();
    // 2 KiB may be written; the PNG is far larger.
    const auto r =
        run_with("ulimit -f 2;", "map " + shell_quote(kWorld) + " --layer countries --width 1024 --fill-by name -o " +
                                     shell_quote(png));
    INFO(r.err);
    CHECK(r.status == 1);
    CHECK(r.err.rfind("casteljau: error: ", 0) == 0);
    CHECK(r.err.find("too large") != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK(names_in(dir).empty());  // neither the PNG nor its temporary file
    // Tiles stop at the first failed write, with no tile under its final name cut short.
    const fs::path tiles = dir / "tiles";
    const auto t =
        run_with("ulimit -f 1;", "tiles " + shell_quote(kWorld) + " --layer countries --zoom 0-3 --threads 1 -o " +
                                     shell_quote(tiles.string()));
    INFO(t.err);
    CHECK(t.status == 1);
    CHECK(t.err.find("too large") != std::string::npos);
    if (fs::exists(tiles))
        for (const auto& [name, bytes] : tiles_in(tiles)) CHECK_NOTHROW(casteljau::decode_png(bytes));
}

TEST_CASE("faults: an output folder that cannot be written is a one-line error", "[faults][cli]") {
    // Root may write into a folder without write permission, so root uses /proc, which nobody can
    // create files in.
    fs::path target;
    fs::path ro;
    if (::geteuid() == 0) {
        target = "/proc/casteljau-fault-test.png";
    } else {
        ro = casteljau::test::scratch_dir("faults_read_only");
        fs::permissions(ro, fs::perms::owner_read | fs::perms::owner_exec);
        target = ro / "out.png";
    }
    const auto r = run_cli("path 'M0 0 L10 0 L5 8 Z' --size 16x16 -o " + shell_quote(target.string()));
    INFO(r.err);
    CHECK(r.status == 1);
    CHECK(r.err.rfind("casteljau: error: ", 0) == 0);
    CHECK(r.err.find(target.string()) != std::string::npos);
    CHECK(!fs::exists(target));
    if (!ro.empty()) {
        CHECK(names_in(ro).empty());
        fs::permissions(ro, fs::perms::owner_all);
    }
}

TEST_CASE("faults: truncated input files are one-line errors with no output", "[faults][cli]") {
    const fs::path dir = casteljau::test::scratch_dir("faults_truncated");
    const auto world = casteljau::read_file(kWorld);
    const std::string cut_json = (dir / "cut.json").string();
    {
        std::ofstream f(cut_json, std::ios::binary);
        f.write(reinterpret_cast<const char*>(world.data()), static_cast<std::streamsize>(world.size() / 2));
    }
    auto r = run_cli("map " + shell_quote(cut_json) + " --width 256 -o " + shell_quote((dir / "m.png").string()));
    INFO(r.err);
    CHECK(r.status == 1);
    CHECK(r.err.find("invalid JSON") != std::string::npos);
    const std::string svg = (dir / "cut.svg").string();
    {
        std::ofstream f(svg);
        f << "<svg xmlns='http://www.w3.org/2000/svg' width='10' height='10'><rect width='5' height='5'/><g";
    }
    r = run_cli("svg " + shell_quote(svg) + " -o " + shell_quote((dir / "s.png").string()));
    CHECK(r.status == 1);
    CHECK(r.err.rfind("casteljau: error: ", 0) == 0);
    const std::string font = (dir / "cut.ttf").string();
    {
        const auto bytes = casteljau::read_file(std::string(CASTELJAU_SOURCE_DIR) + "/fonts/DejaVuSans.ttf");
        std::ofstream f(font, std::ios::binary);
        f.write(reinterpret_cast<const char*>(bytes.data()), 4096);
    }
    r = run_cli("text Hello --font " + shell_quote(font) + " --size 24 -o " + shell_quote((dir / "t.png").string()));
    CHECK(r.status == 1);
    CHECK(r.err.rfind("casteljau: error: ", 0) == 0);
    for (const std::string& n : names_in(dir)) CHECK(n.find(".png") == std::string::npos);
}

TEST_CASE("faults: a tile run killed in the middle and resumed equals an uninterrupted run", "[faults][tiles][cli]") {
    const fs::path dir = casteljau::test::scratch_dir("faults_kill_resume");
    const std::string args =
        "tiles " + shell_quote(kWorld) +
        " --layer countries --zoom 0-5 --metatile 2 --threads 1 --fill-by name --stroke '#333' -o ";
    const fs::path whole = dir / "whole", killed = dir / "killed";
    const auto start = std::chrono::steady_clock::now();
    auto r = run_cli(args + shell_quote(whole.string()));
    REQUIRE(r.status == 0);
    // Killed with SIGKILL part-way (some metatiles written, some not). The kill comes at half of
    // the uninterrupted run's time, halved again whenever the run still got to its end: a fixed
    // delay would outlast the whole run on a fast machine.
    double after = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / 2;
    for (int attempt = 0; attempt < 6; ++attempt, after /= 2) {
        fs::remove_all(killed);
        r = run_with("timeout -s KILL " + std::to_string(after), args + shell_quote(killed.string()));
        if (r.status != 0) break;
    }
    CHECK(r.status == 128 + 9);  // really killed before the end (SIGKILL)
    if (fs::exists(killed))
        for (const auto& [name, bytes] : tiles_in(killed)) CHECK_NOTHROW(casteljau::decode_png(bytes));
    r = run_cli(args + shell_quote(killed.string()) + " --resume");
    INFO(r.err);
    REQUIRE(r.status == 0);
    CHECK(tiles_in(killed) == tiles_in(whole));
    // Resuming also removed the temporary files of the writes the kill interrupted.
    for (const std::string& n : names_in(killed)) CHECK(n.find(".tmp-") == std::string::npos);
}

TEST_CASE("faults: an endless input stream ends in the input-size error, with no output", "[faults][cli][limits]") {
    const fs::path dir = casteljau::test::scratch_dir("faults_endless");
    const std::string png = (dir / "z.png").string();
    // /dev/zero never ends: the reader stops at Limits::input_bytes (1 GiB) instead of taking all
    // the memory there is.
    auto r = run_cli("svg /dev/zero -o " + shell_quote(png));
    INFO(r.err);
    CHECK(r.status == 1);
    CHECK(r.err == "casteljau: error: '/dev/zero' is larger than 1073741824 bytes (Limits::input_bytes)\n");
    CHECK(!fs::exists(png));
}

TEST_CASE("faults: map data from a FIFO is read to its end, and a writer stopping early is a one-line error",
          "[faults][cli][maps]") {
    const fs::path dir = casteljau::test::scratch_dir("faults_fifo");
    const std::string fifo = (dir / "world.json").string();
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    const std::string whole = (dir / "whole.png").string(), cut = (dir / "cut.png").string();
    // The whole file through the FIFO renders as from the file itself.
    auto r = run_with("cat " + shell_quote(kWorld) + " > " + shell_quote(fifo) + " &",
                      "map " + shell_quote(fifo) + " --width 256 -o " + shell_quote(whole));
    INFO(r.err);
    CHECK(r.status == 0);
    r = run_cli("map " + shell_quote(kWorld) + " --width 256 -o " + shell_quote((dir / "file.png").string()));
    CHECK(r.status == 0);
    CHECK(casteljau::read_file(whole) == casteljau::read_file((dir / "file.png").string()));
    // A writer that stops half-way: the text ends early.
    const std::size_t half = casteljau::read_file(kWorld).size() / 2;
    r = run_with("head -c " + std::to_string(half) + " " + shell_quote(kWorld) + " > " + shell_quote(fifo) + " &",
                 "map " + shell_quote(fifo) + " --width 256 -o " + shell_quote(cut));
    CHECK(r.status == 1);
    CHECK(r.err.rfind("casteljau: error: map data: invalid JSON", 0) == 0);
    CHECK(!fs::exists(cut));
}
