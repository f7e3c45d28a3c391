// System font fallback's answers kept across processes (src/text/fallback_cache.hpp): the file
// format and its strict reader, the stamp that invalidates answers when fontconfig's configuration,
// font folders or environment change, where the file lives, and the command line reading and
// writing it (answers used without fontconfig, the same bytes as without a cache, a bad answer
// ignored, --no-system-fonts never touching it).
#include <catch2/catch.hpp>

#include <fcntl.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

#include "skip.hpp"
#include "temp_dir.hpp"
#include "text/fallback_cache.hpp"
#include "text_support.hpp"

using namespace casteljau;
using namespace casteljau::text_detail;
namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name) {
    const fs::path d = casteljau::testing::process_temp_dir() / "fallback_cache" / name;
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
}

void spit(const fs::path& p, const std::string& text) {
    std::ofstream f(p, std::ios::binary);
    f << text;
}

std::string quote(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

int run(const std::string& cmd) {
    const int raw = std::system(cmd.c_str());
    return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

// Sets an environment variable for the scope, then puts back what was there.
class ScopedEnv {
public:
    ScopedEnv(const char* name, const char* value) : name_(name) {
        if (const char* old = std::getenv(name)) old_ = old;
        if (value)
            ::setenv(name, value, 1);
        else
            ::unsetenv(name);
    }
    ~ScopedEnv() {
        if (old_)
            ::setenv(name_, old_->c_str(), 1);
        else
            ::unsetenv(name_);
    }
    ScopedEnv(const ScopedEnv&) = delete;
    ScopedEnv& operator=(const ScopedEnv&) = delete;

private:
    const char* name_;
    std::optional<std::string> old_;
};

FallbackCacheData sample() {
    FallbackCacheData d;
    d.stamp = {{"env LANG", "=C.UTF-8"}, {"path /no/such/folder with space", "-"}};
    d.faces = {{"/fonts/Emoji.ttf", 0}, {"/fonts/My Fonts/CJK%.ttc", 3}};
    d.answers[U"emoji\n\n400r" + std::u32string(1, U'\0') + U"\U0001F44B"] = 0;
    d.answers[U"Sans\nja\n700i" + std::u32string(1, U'\0') + U"\u65E5"] = 1;
    d.answers[U"Sans\n\n400r" + std::u32string(1, U'\0') + U"\U0010FFFF"] = -1;
    return d;
}

}  // namespace

TEST_CASE("Fallback cache: the file reads back what was written, and only that", "[text][fallback]") {
    const FallbackCacheData d = sample();
    const auto text = format_fallback_cache(d);
    REQUIRE(text);
    CHECK(text->find("My%20Fonts/CJK%25.ttc") != std::string::npos);
    const auto back = parse_fallback_cache(*text);
    REQUIRE(back);
    CHECK(back->stamp == d.stamp);
    CHECK(back->faces == d.faces);
    CHECK(back->answers == d.answers);
    CHECK(format_fallback_cache(*back) == text);

    // Anything else is refused whole.
    auto refused = [&](const std::string& from, const std::string& to) {
        std::string t = *text;
        const std::size_t at = t.find(from);
        REQUIRE(at != std::string::npos);
        t.replace(at, from.size(), to);
        return !parse_fallback_cache(t);
    };
    CHECK(refused("casteljau fallback cache 1", "casteljau fallback cache 2"));
    CHECK(refused("My%20Fonts", "My Fonts"));                         // an unescaped space
    CHECK(refused("%25", "%2g"));                                     // a bad escape
    CHECK(refused("%25", "%41"));                                     // an escape of a plain byte
    CHECK(refused("f 3 ", "f 03 "));                                  // a leading zero
    CHECK(refused("a 1 ", "a 2 "));                                   // a face that is not there
    CHECK(refused("a -1 ", "a -2 "));                                 //
    CHECK(refused("10ffff", "110000"));                               // beyond Unicode
    CHECK(refused("1f44b", "1F44B"));                                 // upper-case code points
    CHECK(refused("f 0 /fonts/Emoji.ttf\n", ""));                     // answers naming faces not listed
    CHECK(refused("s env%20LANG =C.UTF-8\n", "x y z\n"));             // an unknown record
    CHECK(!parse_fallback_cache(text->substr(0, text->size() - 1)));  // no final newline
    CHECK(!parse_fallback_cache(""));
    CHECK(!parse_fallback_cache(*text + "s late stamp\n"));  // records out of order
    // Answers in key order, each once.
    const std::size_t first = text->find("\na ") + 1;
    const std::size_t second = text->find("\na ", first) + 1;
    std::string swapped = text->substr(0, first) + text->substr(second, text->find('\n', second) + 1 - second) +
                          text->substr(first, second - first) + text->substr(text->find('\n', second) + 1);
    CHECK(!parse_fallback_cache(swapped));
}

TEST_CASE("Fallback cache: the stamp follows files, folders and the environment", "[text][fallback]") {
    const fs::path dir = scratch("stamp");
    const fs::path conf = dir / "fonts.conf", fonts = dir / "fonts", later = dir / "later";
    spit(conf, "<fontconfig/>\n");
    fs::create_directories(fonts);
    const auto stamp = make_stamp({conf.string(), fonts.string(), later.string(), conf.string()});
    CHECK(stamp.size() == environment_stamp().size() + 3);  // each path once
    CHECK(stamp_is_current(stamp));

    // A changed file, a font added to a folder, a folder created, a variable changed.
    struct timespec times[2] = {{0, UTIME_OMIT}, {12345, 0}};
    {
        REQUIRE(::utimensat(AT_FDCWD, conf.c_str(), times, 0) == 0);
        CHECK(!stamp_is_current(stamp));
    }
    const auto after_conf = make_stamp({conf.string(), fonts.string(), later.string()});
    CHECK(stamp_is_current(after_conf));
    spit(fonts / "new.ttf", "x");
    REQUIRE(::utimensat(AT_FDCWD, fonts.c_str(), times, 0) == 0);
    CHECK(!stamp_is_current(after_conf));
    const auto after_font = make_stamp({conf.string(), fonts.string(), later.string()});
    fs::create_directories(later);
    CHECK(!stamp_is_current(after_font));
    const auto after_folder = make_stamp({conf.string(), fonts.string(), later.string()});
    CHECK(stamp_is_current(after_folder));
    {
        const ScopedEnv env("FC_LANG", "ja");
        CHECK(!stamp_is_current(after_folder));
    }
    CHECK(stamp_is_current(after_folder));
    // A stamp that lacks the environment says nothing about it.
    auto no_environment = after_folder;
    no_environment.erase(no_environment.begin());
    CHECK(!stamp_is_current(no_environment));
}

TEST_CASE("Fallback cache: where the file lives, and files that are ignored", "[text][fallback]") {
    const fs::path dir = scratch("location");
    {
        const ScopedEnv a("CASTELJAU_CACHE_DIR", nullptr), b("XDG_CACHE_HOME", "/xdg/cache"), c("HOME", "/home/u");
        CHECK(fallback_cache_path() == "/xdg/cache/casteljau/fallback-1.cache");
        const ScopedEnv d("XDG_CACHE_HOME", "relative");
        CHECK(fallback_cache_path() == "/home/u/.cache/casteljau/fallback-1.cache");
        const ScopedEnv e("HOME", nullptr);
        CHECK(fallback_cache_path().empty());
        const ScopedEnv f("CASTELJAU_CACHE_DIR", "");
        CHECK(fallback_cache_path().empty());
    }
    const ScopedEnv env("CASTELJAU_CACHE_DIR", (dir / "made/on/demand").c_str());
    const std::string path = fallback_cache_path();
    CHECK(path == (dir / "made/on/demand/fallback-1.cache").string());

    FallbackCacheData d = sample();
    d.stamp = make_stamp({dir.string() + "/watched"});
    REQUIRE(store_fallback_cache(path, d));
    const auto back = load_fallback_cache(path);
    REQUIRE(back);
    CHECK(back->answers == d.answers);
    // Stale, malformed, missing or not a file: no answers.
    fs::create_directories(dir / "watched");
    CHECK(!load_fallback_cache(path));
    spit(path, "casteljau fallback cache 1\ngarbage\n");
    CHECK(!load_fallback_cache(path));
    fs::remove(path);
    CHECK(!load_fallback_cache(path));
    fs::create_directories(path);
    CHECK(!load_fallback_cache(path));
    CHECK(!load_fallback_cache(""));
}

TEST_CASE("Fallback cache: casteljau text keeps its answers and draws the same bytes", "[text][fallback]") {
    for (const std::string& f : {text_test::kNotoEmoji, text_test::kNotoCjk})
        if (!fs::exists(f)) CASTELJAU_SKIP("no " << f << " (Debian fonts-noto-color-emoji, fonts-noto-cjk)");
    const fs::path dir = scratch("cli");
    const fs::path cache = dir / "cache", file = cache / "fallback-1.cache";
    const std::string cli = "CASTELJAU_CACHE_DIR=" + quote(cache.string()) + " " + quote(CASTELJAU_CLI_PATH) +
                            " text " + quote(text_test::kMixedLine) + " --size 30 --font " + quote(text_test::kDejaVu);
    auto draw = [&](const std::string& name, const std::string& extra = "") {
        REQUIRE(run(cli + extra + " -o " + quote((dir / name).string())) == 0);
        return text_test::read_text(dir / name);
    };

    // --no-system-fonts neither reads nor writes the file.
    draw("bare.png", " --no-system-fonts");
    CHECK(!fs::exists(file));

    const std::string first = draw("first.png");
    REQUIRE(fs::exists(file));
    const std::string kept = text_test::read_text(file);
    CHECK(kept.find(text_test::kNotoCjk) != std::string::npos);
    CHECK(kept.find(text_test::kNotoEmoji) != std::string::npos);
    CHECK(draw("second.png") == first);         // answered from the file
    CHECK(text_test::read_text(file) == kept);  // which needed no new answer

    // The answers are what the process used: with the Han characters answered "no face", they
    // are drawn as .notdef boxes.
    std::istringstream lines(kept);
    std::string line, none;
    int faces = 0, cjk = -1;
    while (std::getline(lines, line)) {
        if (line.rfind("f ", 0) == 0) {
            if (line == "f 0 " + text_test::kNotoCjk) cjk = faces;
            ++faces;
        }
        const std::string cjk_answer = "a " + std::to_string(cjk) + " ";
        if (cjk >= 0 && line.rfind(cjk_answer, 0) == 0) line = "a -1 " + line.substr(cjk_answer.size());
        none += line + "\n";
    }
    REQUIRE(cjk >= 0);
    spit(file, none);
    CHECK(draw("no_face.png") != first);
    const std::string face0 = "f 0 " + text_test::kNotoCjk;

    // A face that no longer exists, or that lacks the characters, is looked for again through
    // fontconfig: the same bytes.
    std::string missing = kept;
    missing.replace(missing.find(face0), face0.size(), "f 0 /no/such/font.ttc");
    spit(file, missing);
    CHECK(draw("missing_face.png") == first);
    std::string wrong = kept;
    wrong.replace(wrong.find(face0), face0.size(), "f 0 " + text_test::kDejaVu);
    spit(file, wrong);
    CHECK(draw("wrong_face.png") == first);
    // A file that is not a cache is ignored, and replaced.
    spit(file, "not a cache\n");
    CHECK(draw("garbage.png") == first);
    CHECK(text_test::read_text(file) == kept);
}
