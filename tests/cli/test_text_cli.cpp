// `casteljau text`: the command-line face of the text pipeline. Runs the built executable.
#include <catch2/catch.hpp>

#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "casteljau/png.hpp"
#include "casteljau/text.hpp"
#include "temp_dir.hpp"
#include "text_support.hpp"

using namespace casteljau;
using namespace text_test;
namespace fs = std::filesystem;

namespace {

std::string quote(const std::string& s) {
    std::string q = "'";
    for (char c : s) {
        if (c == '\'')
            q += "'\\''";
        else
            q += c;
    }
    return q + "'";
}

struct Run {
    int status = -1;
    std::string err;
};

fs::path temp_dir() {
    const fs::path d = casteljau::testing::process_temp_dir() / "text_cli";
    fs::create_directories(d);
    return d;
}

std::string slurp(const fs::path& p) {
    std::ifstream f(p, std::ios::binary);
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

// The environment the CLI runs in by default: the shipped fonts named explicitly, so the tests do
// not depend on where the build folder is.
const std::string kShippedFontEnv = std::string("CASTELJAU_FONT_DIR=") + quote(CASTELJAU_TEST_FONT_DIR) + " ";

// Runs `casteljau text ARGS...` and returns the exit status and standard error. `prefix` goes in
// front of the whole command (e.g. a pipe), `env` right before the executable (environment
// assignments, or `env -u NAME `).
Run run_text(const std::vector<std::string>& args, const std::string& prefix = "",
             const std::string& env = kShippedFontEnv) {
    const fs::path err = temp_dir() / "stderr.txt";
    std::string cmd = prefix + env + quote(CASTELJAU_CLI_PATH) + " text";
    for (const auto& a : args) {
        cmd += ' ';
        cmd += quote(a);
    }
    cmd += " 2>" + quote(err.string()) + " >/dev/null";
    const int raw = std::system(cmd.c_str());
    Run r;
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    r.err = slurp(err);
    return r;
}

fs::path out_path(const std::string& name) {
    const fs::path p = temp_dir() / name;
    fs::remove(p);
    return p;
}

long dark_pixels(const Pixmap& pm) {
    long n = 0;
    for (int y = 0; y < pm.height(); ++y)
        for (int x = 0; x < pm.width(); ++x) n += pm.pixel(x, y).r < 100;
    return n;
}

}  // namespace

TEST_CASE("casteljau text renders with the default font and fits the image to the text", "[text-cli]") {
    const fs::path out = out_path("hello.png");
    const Run r = run_text({"Hello, AV To fi", "-o", out.string(), "--size", "24", "--padding", "5"});
    INFO(r.err);
    REQUIRE(r.status == 0);
    REQUIRE(fs::exists(out));
    const Pixmap pm = read_png(out.string());
    // The same layout through the library gives the image size: box (or ink) plus padding.
    const Font f = Font::load(kDejaVu);
    TextStyle st;
    st.size = 24;
    const Rect b = layout_text("Hello, AV To fi", f, st).bounds();
    CHECK(pm.width() == static_cast<int>(std::ceil(b.x1) - std::floor(b.x0)) + 10);
    CHECK(pm.height() == static_cast<int>(std::ceil(b.y1) - std::floor(b.y0)) + 10);
    CHECK(dark_pixels(pm) > 200);
    // Padding is background: white, opaque.
    for (int x = 0; x < pm.width(); ++x) CHECK(pm.pixel(x, 0) == PremulPixel{255, 255, 255, 255});
}

TEST_CASE("casteljau text: '-' reads standard input, minus its final newline", "[text-cli]") {
    const fs::path a = out_path("arg.png"), b = out_path("stdin.png");
    REQUIRE(run_text({"two\nlines", "-o", a.string()}).status == 0);
    REQUIRE(run_text({"-", "-o", b.string()}, "printf 'two\\nlines\\n' | ").status == 0);
    CHECK(slurp(a) == slurp(b));
    CHECK(read_png(a.string()).height() > 60);  // two lines at 32 px
}

TEST_CASE("casteljau text: options change the picture as documented", "[text-cli]") {
    const std::string text = "The quick brown fox jumps over the lazy dog";
    const fs::path wrapped = out_path("wrapped.png");
    REQUIRE(run_text(
                {text, "-o", wrapped.string(), "--width", "200", "--align", "center", "--size", "20", "--padding", "0"})
                .status == 0);
    const Pixmap w = read_png(wrapped.string());
    CHECK(w.width() == 200);
    CHECK(w.height() > 3 * 20);

    const fs::path transparent = out_path("transparent.png");
    REQUIRE(run_text({"x", "-o", transparent.string(), "--background", "transparent", "--color", "#ff0000"}).status ==
            0);
    const Pixmap t = read_png(transparent.string());
    CHECK(t.pixel(0, 0).a == 0);
    bool red = false;
    for (int y = 0; y < t.height(); ++y)
        for (int x = 0; x < t.width(); ++x) red = red || (t.pixel(x, y) == PremulPixel{255, 0, 0, 255});
    CHECK(red);

    const fs::path plain = out_path("plain.png"), gamma = out_path("gamma.png");
    REQUIRE(run_text({"gamma", "-o", plain.string()}).status == 0);
    REQUIRE(run_text({"gamma", "-o", gamma.string(), "--gamma-correct"}).status == 0);
    CHECK(slurp(plain) != slurp(gamma));

    // A fallback chain and a right-to-left line.
    const fs::path chain = out_path("chain.png");
    const Run rc = run_text(
        {"Salam \xD8\xB3\xD9\x84\xD8\xA7\xD9\x85", "-o", chain.string(), "--font", kLibertine, "--font", kNotoArabic});
    INFO(rc.err);
    CHECK(rc.status == 0);

    // Variable font weight: heavier ink at wght=900 than at 100.
    const fs::path thin = out_path("thin.png"), heavy = out_path("heavy.png");
    REQUIRE(run_text({"Weight", "-o", thin.string(), "--font", kInterVar, "--variation", "wght=100"}).status == 0);
    REQUIRE(run_text({"Weight", "-o", heavy.string(), "--font", kInterVar, "--variation", "wght=900"}).status == 0);
    CHECK(dark_pixels(read_png(heavy.string())) > 2 * dark_pixels(read_png(thin.string())));

    // Features and direction are passed through.
    const fs::path liga = out_path("liga.png"), noliga = out_path("noliga.png");
    REQUIRE(run_text({"fi", "-o", liga.string()}).status == 0);
    REQUIRE(run_text({"fi", "-o", noliga.string(), "--feature", "liga=0"}).status == 0);
    CHECK(slurp(liga) != slurp(noliga));
}

TEST_CASE("casteljau text: CASTELJAU_FONT_DIR points at the default font", "[text-cli]") {
    const fs::path dir = temp_dir() / "fontdir";
    fs::create_directories(dir);
    fs::copy_file(kLibertine, dir / "DejaVuSans.ttf", fs::copy_options::overwrite_existing);
    const fs::path a = out_path("default.png"), b = out_path("envfont.png");
    REQUIRE(run_text({"Font", "-o", a.string()}).status == 0);
    REQUIRE(run_text({"Font", "-o", b.string()}, "", "CASTELJAU_FONT_DIR=" + quote(dir.string()) + " ").status == 0);
    CHECK(slurp(a) != slurp(b));
}

TEST_CASE("casteljau text finds the shipped fonts with no CASTELJAU_FONT_DIR, wherever the build folder is",
          "[text-cli]") {
    // The executable lies in the build folder, which may be anywhere (a packager's /tmp/build): the
    // folder fixed at configure time must still lead to the shipped DejaVu Sans.
    const fs::path a = out_path("explicit.png"), b = out_path("configured.png");
    REQUIRE(run_text({"Font", "-o", a.string()}).status == 0);
    const Run r = run_text({"Font", "-o", b.string()}, "", "env -u CASTELJAU_FONT_DIR ");
    INFO(r.err);
    REQUIRE(r.status == 0);
    CHECK(slurp(a) == slurp(b));
}

TEST_CASE("casteljau text: bad input gives a clear error, the right status and no output file", "[text-cli]") {
    const fs::path trunc = temp_dir() / "truncated.ttf";
    {
        const auto bytes = read_bytes(kDejaVu);
        write_bytes(trunc.string(), std::vector<std::uint8_t>(
                                        bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(bytes.size() / 2)));
    }
    struct Case {
        std::vector<std::string> args;
        int status;
        std::string message;
        std::string prefix;
    };
    const std::vector<Case> cases{
        {{"x", "--font", "/nonexistent/font.ttf"}, 1, "cannot read font '/nonexistent/font.ttf': no such file", ""},
        {{"x", "--font", source_path("fonts/README.md")}, 1, "not a font file", ""},
        {{"x", "--font", trunc.string()}, 1, "truncated", ""},
        {{"x", "--font", kDejaVu, "--face", "3"}, 1, "face index 3 out of range", ""},
        {{""}, 1, "the text is empty", ""},
        {{"-"}, 1, "the text is empty", "printf '\\n' | "},
        {{"x", "--size", "0"}, 2, "--size: must be greater than 0 and at most 10000 pixels", ""},
        {{"x", "--size=-5"}, 2, "--size: must be greater than 0", ""},
        {{"x", "--size", "1e6"}, 2, "at most 10000 pixels, got '1e6'", ""},
        {{"x", "--size", "big"}, 2, "--size: expected a number", ""},
        {{"x", "--font", kInterVar, "--variation", "wdth=100"},
         1,
         "unknown variation axis 'wdth': the fonts' axes are wght",
         ""},
        {{"x", "--variation", "wght=700"}, 1, "unknown variation axis 'wght': no font given is a variable font", ""},
        {{"x", "--variation", "wght"}, 2, "--variation: invalid variation 'wght'", ""},
        {{"x", "--color", "nocolour"}, 2, "--color", ""},
        {{"x", "--width", "0"}, 2, "--width", ""},
        {{"x", "--line-height", "0"}, 2, "--line-height", ""},
        {{"x", "--padding", "-1"}, 2, "--padding", ""},
        {{"x", "--align", "justify"}, 2, "--align", ""},
        {{"x", "--feature", "@@"}, 1, "invalid font feature", ""},
        {{"x", "--size", "10000.5"}, 2, "at most 10000 pixels", ""},
        {{"x", "--size", "300", "--padding", "0"}, 0, "", ""},
    };
    for (const Case& c : cases) {
        const fs::path out = out_path("bad.png");
        std::vector<std::string> args = c.args;
        args.push_back("-o");
        args.push_back(out.string());
        std::string shown;
        for (const auto& a : c.args) shown += a + " ";
        INFO(shown);
        const Run r = run_text(args, c.prefix);
        INFO(r.err);
        CHECK(r.status == c.status);
        if (c.status != 0) {
            CHECK(r.err.rfind("casteljau: error: ", 0) == 0);
            CHECK(r.err.find(c.message) != std::string::npos);
            CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
            CHECK_FALSE(fs::exists(out));
        } else {
            CHECK(fs::exists(out));
        }
    }
    // Invalid UTF-8 is not an error: it shows U+FFFD.
    const fs::path ok = out_path("fffd.png");
    CHECK(run_text({"-", "-o", ok.string()}, "printf 'a\\377b' | ").status == 0);
    CHECK(fs::exists(ok));
    // An unwritable output path and a missing -o.
    const Run unwritable = run_text({"x", "-o", "/nonexistent/dir/out.png"});
    CHECK(unwritable.status == 1);
    CHECK(unwritable.err.find("/nonexistent/dir/out.png") != std::string::npos);
    CHECK(run_text({"x"}).status == 2);
    CHECK(run_text({"--help"}).status == 0);
}
