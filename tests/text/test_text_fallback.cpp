// System font fallback (fontconfig) and line breaking: the mixed line drawn without a
// .notdef glyph and each cluster's ink where pango-view draws it, language and style in the choice
// of fallback faces, --no-system-fonts reproducibility, and UAX #14 wrapping of CJK and Thai.
#include <catch2/catch.hpp>

#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "casteljau/png.hpp"
#include "casteljau/text.hpp"
#include "skip.hpp"
#include "temp_dir.hpp"
#include "text_support.hpp"

using namespace casteljau;
namespace fs = std::filesystem;

namespace {

const std::string kSystemDejaVu = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

// The reason the fallback tests cannot run here, or "".
std::string missing_fonts() {
    for (const std::string& f : {kSystemDejaVu, text_test::kNotoEmoji, text_test::kNotoCjk})
        if (!fs::exists(f)) return "no " + f + " (Debian fonts-dejavu-core, fonts-noto-color-emoji, fonts-noto-cjk)";
    return "";
}

std::string quote(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

fs::path temp_dir() {
    const fs::path d = casteljau::testing::process_temp_dir() / "text_fallback";
    fs::create_directories(d);
    return d;
}

int run(const std::string& cmd) {
    const int raw = std::system(cmd.c_str());
    return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

std::string font_of(const TextLayout& layout, std::size_t glyph) {
    return layout.fonts[layout.glyphs[glyph].font]->family_name();
}

// Ink boxes of the columns groups of an image on a light background: a pixel inks when a channel is
// more than 96 below white; a group is a maximal run of columns with ink.
std::vector<IRect> ink_groups(const Pixmap& pm) {
    auto ink = [&](int x, int y) {
        const Color c = unpremultiply(pm.pixel(x, y));
        return c.a > 0 && (c.r < 160 || c.g < 160 || c.b < 160);
    };
    std::vector<IRect> groups;
    bool open = false;
    for (int x = 0; x <= pm.width(); ++x) {
        int y0 = pm.height(), y1 = -1;
        if (x < pm.width())
            for (int y = 0; y < pm.height(); ++y)
                if (ink(x, y)) {
                    y0 = std::min(y0, y);
                    y1 = std::max(y1, y);
                }
        if (y1 >= 0) {
            if (!open) groups.push_back({x, y0, x + 1, y1 + 1});
            IRect& g = groups.back();
            g.x1 = x + 1;
            g.y0 = std::min(g.y0, y0);
            g.y1 = std::max(g.y1, y1 + 1);
            open = true;
        } else {
            open = false;
        }
    }
    return groups;
}

}  // namespace

// LeakSanitizer (sanitizer builds): fontconfig 2.14 loses a pattern while parsing its
// configuration files, once per configuration loaded (288 bytes here); system font fallback loads
// one per process. Not casteljau's memory, so not reported.
extern "C" const char* __lsan_default_suppressions() { return "leak:libfontconfig.so\n"; }

TEST_CASE("Fallback: the mixed line has no .notdef glyph and takes emoji and CJK from system fonts",
          "[text][fallback]") {
    if (const std::string why = missing_fonts(); !why.empty()) { CASTELJAU_SKIP(why); }
    const Font base = Font::load(text_test::kDejaVu);
    TextStyle st;
    st.size = 40;
    st.system_fonts = true;
    const TextLayout layout = layout_text(text_test::kMixedLine, base, st);
    for (const PositionedGlyph& g : layout.glyphs) {
        INFO("cluster " << g.cluster << " U+" << std::hex << static_cast<unsigned>(layout.text[g.cluster]));
        CHECK(g.glyph != 0);
    }
    // H, the emoji, the check mark (DejaVu has it), the first ideograph, the first Greek letter.
    auto glyph_at = [&](std::size_t cluster) {
        for (std::size_t i = 0; i < layout.glyphs.size(); ++i)
            if (layout.glyphs[i].cluster == cluster) return i;
        FAIL("no glyph for cluster " << cluster);
        return std::size_t{0};
    };
    CHECK(font_of(layout, glyph_at(0)) == "DejaVu Sans");
    CHECK(font_of(layout, glyph_at(6)) == "Noto Color Emoji");
    CHECK(font_of(layout, glyph_at(14)) == "DejaVu Sans");
    CHECK(font_of(layout, glyph_at(16)).rfind("Noto Sans CJK", 0) == 0);
    CHECK(font_of(layout, glyph_at(20)) == "DejaVu Sans");
    CHECK(layout.system_fonts.size() == 2);  // one Font per face, however many clusters it serves

    // Without system fonts the same text shows .notdef boxes.
    st.system_fonts = false;
    const TextLayout plain = layout_text(text_test::kMixedLine, base, st);
    CHECK(plain.system_fonts.empty());
    CHECK(plain.fonts.size() == 1);
    CHECK(std::any_of(plain.glyphs.begin(), plain.glyphs.end(), [](const PositionedGlyph& g) { return g.glyph == 0; }));
}

TEST_CASE("Fallback: the language picks the regional forms of Han characters", "[text][fallback]") {
    if (const std::string why = missing_fonts(); !why.empty()) { CASTELJAU_SKIP(why); }
    const Font base = Font::load(text_test::kDejaVu);
    TextStyle st;
    st.size = 20;
    st.system_fonts = true;
    for (const auto& [language, family] :
         std::vector<std::pair<std::string, std::string>>{{"ja", "Noto Sans CJK JP"},
                                                          {"zh-cn", "Noto Sans CJK SC"},
                                                          {"zh-tw", "Noto Sans CJK TC"},
                                                          {"ko", "Noto Sans CJK KR"}}) {
        st.language = language;
        const TextLayout layout = layout_text("\u76F4", base, st);  // a character with regional forms
        INFO(language);
        REQUIRE(layout.glyphs.size() == 1);
        CHECK(font_of(layout, 0) == family);
    }
}

TEST_CASE("Fallback: the fallback face follows the base font's weight", "[text][fallback]") {
    const std::string bold = "/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf";
    const std::string cjk_bold = "/usr/share/fonts/opentype/noto/NotoSansCJK-Bold.ttc";
    if (!fs::exists(bold) || !fs::exists(cjk_bold)) { CASTELJAU_SKIP("no " << bold << " or " << cjk_bold); }
    TextStyle st;
    st.size = 20;
    st.system_fonts = true;
    st.language = "ja";
    const Font regular = Font::load(text_test::kDejaVu);
    const Font heavy = Font::load(bold);
    const TextLayout a = layout_text("\u65E5", regular, st), b = layout_text("\u65E5", heavy, st);
    REQUIRE(a.glyphs.size() == 1);
    REQUIRE(b.glyphs.size() == 1);
    CHECK(a.fonts[a.glyphs[0].font]->style_name() == "Regular");
    CHECK(b.fonts[b.glyphs[0].font]->style_name() == "Bold");
}

TEST_CASE("Fallback: each cluster's ink lies within 2 px of pango-view's", "[text][fallback]") {
    if (const std::string why = missing_fonts(); !why.empty()) { CASTELJAU_SKIP(why); }
    if (run("command -v pango-view >/dev/null 2>&1") != 0) { CASTELJAU_SKIP("no pango-view (Debian pango1.0-tools)"); }
    const fs::path dir = temp_dir();
    const fs::path theirs = dir / "pango.png", ours = dir / "ours.png";
    REQUIRE(run("pango-view --no-display --pixels --subpixel-positions --hinting=none --margin 10 --font 'DejaVu Sans "
                "40px' "
                "--text " +
                quote(text_test::kMixedLine) + " -o " + quote(theirs.string()) + " >/dev/null 2>&1") == 0);
    REQUIRE(run(quote(CASTELJAU_CLI_PATH) + " text " + quote(text_test::kMixedLine) +
                " --size 40 --padding 10 --font " + quote(kSystemDejaVu) + " -o " + quote(ours.string())) == 0);
    const std::vector<IRect> a = ink_groups(read_png(theirs.string())), b = ink_groups(read_png(ours.string()));
    // The clusters that do not touch: H e l l o, the emoji, w o r l d, the check mark, three
    // ideographs and the Greek letters.
    REQUIRE(a.size() >= 20);
    REQUIRE(a.size() == b.size());
    // Aligned on the H's top-left corner (the images' margins and line heights differ).
    const int dx = a[0].x0 - b[0].x0, dy = a[0].y0 - b[0].y0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        INFO("group " << i << ": pango [" << a[i].x0 << ", " << a[i].y0 << ", " << a[i].x1 << ", " << a[i].y1
                      << "], casteljau moved [" << b[i].x0 + dx << ", " << b[i].y0 + dy << ", " << b[i].x1 + dx << ", "
                      << b[i].y1 + dy << "]");
        CHECK(std::abs(a[i].x0 - (b[i].x0 + dx)) <= 2);
        CHECK(std::abs(a[i].x1 - (b[i].x1 + dx)) <= 2);
        CHECK(std::abs(a[i].y0 - (b[i].y0 + dy)) <= 2);
        CHECK(std::abs(a[i].y1 - (b[i].y1 + dy)) <= 2);
    }
}

TEST_CASE("casteljau text --no-system-fonts gives the same bytes whatever fonts the system has", "[text][fallback]") {
    const fs::path dir = temp_dir();
    const fs::path normal = dir / "normal.png", bare = dir / "bare.png", conf = dir / "empty-fonts.conf";
    {
        std::ofstream f(conf);
        f << "<?xml version=\"1.0\"?>\n<fontconfig></fontconfig>\n";
    }
    const std::string cli = quote(CASTELJAU_CLI_PATH) + " text " + quote(text_test::kMixedLine) +
                            " --size 30 --no-system-fonts --font " + quote(text_test::kDejaVu) + " -o ";
    REQUIRE(run(cli + quote(normal.string())) == 0);
    // A process whose fontconfig knows no fonts at all.
    REQUIRE(run("FONTCONFIG_FILE=" + quote(conf.string()) + " " + cli + quote(bare.string())) == 0);
    const std::string x = text_test::read_text(normal), y = text_test::read_text(bare);
    REQUIRE(!x.empty());
    CHECK(x == y);
}

TEST_CASE("Line breaking follows UAX #14: CJK between characters, Thai between words", "[text][linebreak]") {
    const Font base = Font::load(text_test::kDejaVu);
    TextStyle st;
    st.size = 20;
    // Japanese with no spaces: a narrow width breaks it between ideographs, never before the
    // full stop (a closing character).
    st.max_width = 40;
    const char* ja = "\u65E5\u672C\u8A9E\u306E\u6587\u7AE0\u3002\u6298\u308A\u8FD4\u3057";
    const TextLayout j = layout_text(ja, base, st);
    CHECK(j.lines.size() > 2);
    for (const TextLine& l : j.lines) CHECK(j.text[l.text_begin] != U'\u3002');
    // Thai (no spaces between words): breaks fall only between the words
    // ภาษา|ไทย|เป็น|ภาษา|ที่|สวยงาม.
    st.max_width = 60;
    const TextLayout t = layout_text(
        "\u0E20\u0E32\u0E29\u0E32\u0E44\u0E17\u0E22\u0E40\u0E1B\u0E47\u0E19\u0E20\u0E32\u0E29"
        "\u0E32\u0E17\u0E35\u0E48\u0E2A\u0E27\u0E22\u0E07\u0E32\u0E21",
        base, st);
    CHECK(t.lines.size() > 1);
    for (std::size_t i = 1; i < t.lines.size(); ++i) {
        const std::size_t at = t.lines[i].text_begin;
        INFO("line " << i << " starts at " << at);
        CHECK((at == 4 || at == 7 || at == 11 || at == 15 || at == 18));
    }
}
