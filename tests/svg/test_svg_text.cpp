// SVG text: font discovery and matching (FontDatabase), text layout checked against HarfBuzz's own
// shaping, bad input (text paths, huge sizes and texts, missing fonts) and the CLI's font options.
#include <catch2/catch.hpp>

#include <hb.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "casteljau/limits.hpp"
#include "casteljau/canvas.hpp"
#include "casteljau/error.hpp"
#include "casteljau/font.hpp"
#include "casteljau/font_database.hpp"
#include "casteljau/png.hpp"
#include "casteljau/svg.hpp"
#include "cli_util.hpp"
#include "text/font_impl.hpp"
#include "skip.hpp"

using namespace casteljau;

namespace {

const std::string kFontDir = CASTELJAU_TEST_FONT_DIR;

// The repository's fonts only (no system fonts): results do not depend on the machine.
std::shared_ptr<const FontDatabase> repo_fonts() {
    FontDatabaseOptions o;
    o.font_dirs = {kFontDir};
    o.system_fonts = false;
    return std::make_shared<const FontDatabase>(o);
}

SvgOptions repo_options(std::shared_ptr<const FontDatabase> db = repo_fonts()) {
    SvgOptions o;
    o.font_database = std::move(db);
    o.font_family = "DejaVu Sans";
    return o;
}

int ink(const Pixmap& pm) {
    int n = 0;
    for (int y = 0; y < pm.height(); ++y)
        for (int x = 0; x < pm.width(); ++x) n += pm.pixel(x, y).a > 0;
    return n;
}

int max_diff(const Pixmap& a, const Pixmap& b) {
    int d = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            const auto p = a.pixel(x, y), q = b.pixel(x, y);
            d = std::max({d, std::abs(p.r - q.r), std::abs(p.g - q.g), std::abs(p.b - q.b), std::abs(p.a - q.a)});
        }
    return d;
}

bool has_warning(const SvgDocument& doc, const std::string& part) {
    return std::any_of(doc.warnings().begin(), doc.warnings().end(),
                       [&](const std::string& w) { return w.find(part) != std::string::npos; });
}

struct HbGlyph {
    unsigned id;
    double x, y;  // origin in font units, y up
};

// HarfBuzz's own shaping of `text` with `font_file` (its OpenType functions, not hb-ft, at a scale
// of one unit per font unit), left to right, default features.
std::vector<HbGlyph> harfbuzz_positions(const std::string& font_file, const std::string& text) {
    hb_blob_t* blob = hb_blob_create_from_file(font_file.c_str());
    hb_face_t* face = hb_face_create(blob, 0);
    hb_font_t* font = hb_font_create(face);
    const int upem = static_cast<int>(hb_face_get_upem(face));
    hb_font_set_scale(font, upem, upem);
    hb_buffer_t* buf = hb_buffer_create();
    hb_buffer_add_utf8(buf, text.c_str(), static_cast<int>(text.size()), 0, -1);
    hb_buffer_guess_segment_properties(buf);
    hb_shape(font, buf, nullptr, 0);
    unsigned n = 0;
    const hb_glyph_info_t* info = hb_buffer_get_glyph_infos(buf, &n);
    const hb_glyph_position_t* pos = hb_buffer_get_glyph_positions(buf, &n);
    std::vector<HbGlyph> out;
    double pen = 0;
    for (unsigned i = 0; i < n; ++i) {
        out.push_back({info[i].codepoint, pen + pos[i].x_offset, static_cast<double>(pos[i].y_offset)});
        pen += pos[i].x_advance;
    }
    hb_buffer_destroy(buf);
    hb_font_destroy(font);
    hb_face_destroy(face);
    hb_blob_destroy(blob);
    return out;
}

// Draws glyphs at the given positions (font units) as one filled path, the way an independent
// program would: origin (x0, y0) on the baseline, `size` px per em.
Pixmap draw_positions(const Font& font, const std::vector<HbGlyph>& glyphs, double size, double x0, double y0, int w,
                      int h) {
    const double s = size / font.units_per_em();
    Path all;
    for (const HbGlyph& g : glyphs)
        all.append(font.glyph_path(g.id), Affine::translate(x0 + g.x * s, y0 - g.y * s) * Affine::scale(s, -s));
    Pixmap pm(w, h);
    Canvas c(pm);
    c.fill_path(all, Paint::solid(Color::black()));
    return pm;
}

}  // namespace

TEST_CASE("FontDatabase: a font folder lists its faces with their family names and styles", "[svg_text]") {
    const auto db = repo_fonts();
    REQUIRE(db->faces().size() >= 3);
    auto has_family = [&](const std::string& name) {
        return std::any_of(db->faces().begin(), db->faces().end(), [&](const FontFaceInfo& f) {
            return std::find(f.families.begin(), f.families.end(), name) != f.families.end();
        });
    };
    CHECK(has_family("DejaVu Sans"));
    CHECK(has_family("Noto Sans Arabic"));
    const auto dejavu = db->match("dejavu sans");  // family names match case-insensitively
    REQUIRE(dejavu);
    CHECK(db->faces()[*dejavu].weight == 400);
    CHECK(db->faces()[*dejavu].slant == FontSlant::Normal);
    CHECK_FALSE(db->match("No Such Family"));
    // A face opened twice shares the file's bytes (read once) but is an independent Font.
    const Font a = db->open(*dejavu), b = db->open(*dejavu);
    CHECK(&a.impl() != &b.impl());
    CHECK(a.impl().face != b.impl().face);
    CHECK(a.impl().bytes.get() == b.impl().bytes.get());
    CHECK(a.family_name() == "DejaVu Sans");
}

TEST_CASE("FontDatabase: a missing font folder is Error(Io) naming it", "[svg_text]") {
    FontDatabaseOptions o;
    o.font_dirs = {kFontDir + "/no-such-folder"};
    o.system_fonts = false;
    try {
        FontDatabase db(o);
        FAIL("no error");
    } catch (const Error& e) {
        CHECK(e.kind() == ErrorKind::Io);
        CHECK(std::string(e.what()).find("no-such-folder") != std::string::npos);
    }
}

TEST_CASE("FontDatabase: CSS matching picks stretch, then style, then weight in CSS order", "[svg_text]") {
    const std::filesystem::path fonts = casteljau::test::shared_dir() / "conformance/resvg-suite/fonts";
    if (!std::filesystem::exists(fonts / "NotoSans-Thin.ttf")) {
        CASTELJAU_SKIP("the resvg suite's fonts are absent (" + fonts.string() + ")");
        return;
    }
    FontDatabaseOptions o;
    o.font_dirs = {fonts.string()};
    o.system_fonts = false;
    const FontDatabase db(o);
    auto weight_of = [&](int w, FontSlant s = FontSlant::Normal) {
        const auto i = db.match("Noto Sans", w, s);
        REQUIRE(i);
        return std::make_pair(db.faces()[*i].weight, db.faces()[*i].slant);
    };
    // Noto Sans here: Thin 100, Light 300, Regular 400, Bold 700, Black 900, Italic 400.
    CHECK(weight_of(400).first == 400);
    CHECK(weight_of(450).first == 400);  // 400..500: nothing heavier up to 500, so lighter first
    CHECK(weight_of(500).first == 400);
    CHECK(weight_of(600).first == 700);  // above 500: heavier first
    CHECK(weight_of(800).first == 900);
    CHECK(weight_of(350).first == 300);  // below 400: lighter first
    CHECK(weight_of(200).first == 100);
    CHECK(weight_of(50).first == 100);  // nothing lighter: the nearest heavier
    CHECK(weight_of(400, FontSlant::Italic).second == FontSlant::Italic);
    CHECK(weight_of(400, FontSlant::Oblique).second == FontSlant::Italic);  // oblique falls back to italic
    CHECK(weight_of(700, FontSlant::Italic).second == FontSlant::Italic);   // style before weight
}

TEST_CASE("FontDatabase: per-character fallback finds a face that has the character", "[svg_text]") {
    const auto db = repo_fonts();
    const char32_t alef = 0x0627, kaf_with_ring = 0x06AB;
    for (char32_t c : {alef, kaf_with_ring, U'A'}) {
        const auto f = db->fallback(c);
        REQUIRE(f);
        CHECK(db->covers(*f, c));
        CHECK(db->open(*f).has_glyph(c));
    }
    CHECK_FALSE(db->fallback(0x65E5));  // no font here has CJK ideographs
}

TEST_CASE("SVG text: glyph positions equal HarfBuzz's own shaping of the same string and font", "[svg_text]") {
    // Kerning pairs (AV, Ty, We) make positions differ from plain advances.
    const std::string s = "AVATAR To We";
    const double size = 40, x0 = 10, y0 = 60;
    const std::string svg =
        "<svg xmlns='http://www.w3.org/2000/svg' width='320' height='80'><text x='10' y='60' "
        "font-family='DejaVu Sans' font-size='40'>" +
        s + "</text></svg>";
    const SvgDocument doc = SvgDocument::parse(svg, repo_options());
    const Pixmap actual = doc.render();
    const Font font = Font::load(kFontDir + "/DejaVuSans.ttf");
    const std::vector<HbGlyph> hb = harfbuzz_positions(kFontDir + "/DejaVuSans.ttf", s);
    REQUIRE(hb.size() == s.size());
    const Pixmap expected = draw_positions(font, hb, size, x0, y0, 320, 80);
    CHECK(ink(actual) > 1000);
    CHECK(max_diff(actual, expected) <= 1);
    // The check can fail: the same glyphs at their plain advances (no kerning) differ.
    std::vector<HbGlyph> plain = hb;
    double pen = 0;
    for (HbGlyph& g : plain) {
        g.x = pen;
        pen += font.glyph_metrics(g.id).advance;
    }
    CHECK(max_diff(actual, draw_positions(font, plain, size, x0, y0, 320, 80)) > 100);
}

TEST_CASE("SVG text: kerning 0 places glyphs at their plain advances", "[svg_text]") {
    const std::string s = "AVAV";
    const std::string svg =
        "<svg xmlns='http://www.w3.org/2000/svg' width='200' height='60'><text x='10' y='45' "
        "font-family='DejaVu Sans' font-size='40' kerning='0'>" +
        s + "</text></svg>";
    const Pixmap actual = SvgDocument::parse(svg, repo_options()).render();
    const Font font = Font::load(kFontDir + "/DejaVuSans.ttf");
    std::vector<HbGlyph> plain = harfbuzz_positions(kFontDir + "/DejaVuSans.ttf", s);
    double pen = 0;
    for (HbGlyph& g : plain) {
        g.x = pen;
        pen += font.glyph_metrics(g.id).advance;
    }
    CHECK(max_diff(actual, draw_positions(font, plain, 40, 10, 45, 200, 60)) <= 1);
    // Without kerning="0" the AV pairs move closer.
    const std::string kerned =
        "<svg xmlns='http://www.w3.org/2000/svg' width='200' height='60'><text x='10' y='45' "
        "font-family='DejaVu Sans' font-size='40'>" +
        s + "</text></svg>";
    CHECK(max_diff(SvgDocument::parse(kerned, repo_options()).render(), actual) > 100);
}

TEST_CASE("SVG text: x, dx, text-anchor and letter-spacing move glyphs by their exact amounts", "[svg_text]") {
    auto render = [](const std::string& attrs) {
        const std::string svg =
            "<svg xmlns='http://www.w3.org/2000/svg' width='200' height='60'><text y='40' "
            "font-family='DejaVu Sans' font-size='30' " +
            attrs + ">H</text></svg>";
        return SvgDocument::parse(svg, repo_options()).render();
    };
    // The left edge of the ink.
    auto left = [](const Pixmap& pm) {
        for (int x = 0; x < pm.width(); ++x)
            for (int y = 0; y < pm.height(); ++y)
                if (pm.pixel(x, y).a > 128) return x;
        return -1;
    };
    const Font font = Font::load(kFontDir + "/DejaVuSans.ttf");
    const double adv = font.glyph_metrics(font.glyph_index(U'H')).advance * 30.0 / font.units_per_em();
    const int base = left(render("x='50'"));
    REQUIRE(base > 0);
    CHECK(left(render("x='30' dx='20'")) == base);
    CHECK(left(render("x='70' text-anchor='end'")) == left(render("x='" + std::to_string(70 - adv) + "'")));
    CHECK(left(render("x='50' text-anchor='middle'")) == left(render("x='" + std::to_string(50 - adv / 2) + "'")));
    CHECK(left(render("x='50' dx='10'")) == base + 10);
}

TEST_CASE("SVG text: fill, stroke and gradients paint text like shapes", "[svg_text]") {
    const std::string svg =
        "<svg xmlns='http://www.w3.org/2000/svg' width='200' height='60'>"
        "<linearGradient id='g'><stop offset='0' stop-color='red'/><stop offset='1' "
        "stop-color='blue'/></linearGradient>"
        "<text x='5' y='45' font-family='DejaVu Sans' font-size='40' fill='url(#g)' stroke='lime' "
        "stroke-width='2'>MMMM</text></svg>";
    const Pixmap pm = SvgDocument::parse(svg, repo_options()).render();
    bool reddish = false, bluish = false, green = false;
    for (int y = 0; y < pm.height(); ++y)
        for (int x = 0; x < pm.width(); ++x) {
            const auto p = pm.pixel(x, y);
            if (p.a == 255 && p.r > 150 && p.b < 100 && p.g < 100) reddish = true;
            if (p.a == 255 && p.b > 150 && p.r < 100 && p.g < 100) bluish = true;
            if (p.a == 255 && p.g > 200 && p.r < 60 && p.b < 60) green = true;
        }
    CHECK(reddish);
    CHECK(bluish);
    CHECK(green);
}

TEST_CASE("SVG text: a textPath to a missing or degenerate path draws nothing and warns", "[svg_text][bad-input]") {
    for (const std::string& defs :
         {std::string(""), std::string("<path id='p' d='M 10 10'/>"), std::string("<circle id='p' r='0'/>")}) {
        const std::string svg =
            "<svg xmlns='http://www.w3.org/2000/svg' width='100' height='100'><defs>" + defs +
            "</defs><text font-family='DejaVu Sans' font-size='20'><textPath href='#p'>Text</textPath></text></svg>";
        const SvgDocument doc = SvgDocument::parse(svg, repo_options());
        CHECK(ink(doc.render()) == 0);
        CHECK(has_warning(doc, "textPath"));
    }
    // A usable path draws the text along it.
    const std::string ok =
        "<svg xmlns='http://www.w3.org/2000/svg' width='100' height='100'><defs><path id='p' d='M 10 50 L 90 50'/>"
        "</defs><text font-family='DejaVu Sans' font-size='20'><textPath href='#p'>Text</textPath></text></svg>";
    CHECK(ink(SvgDocument::parse(ok, repo_options()).render()) > 100);
}

TEST_CASE("SVG text: a font-size of 1e9 is skipped with a warning in bounded time", "[svg_text][bad-input]") {
    const std::string svg =
        "<svg xmlns='http://www.w3.org/2000/svg' width='100' height='100'><text x='0' y='50' "
        "font-family='DejaVu Sans' font-size='1e9'>W</text></svg>";
    const SvgDocument doc = SvgDocument::parse(svg, repo_options());
    CHECK(has_warning(doc, "font-size"));
    CHECK(ink(doc.render()) == 0);
}

TEST_CASE("SVG text: a 1 MB text node is cut at the documented limit with a warning", "[svg_text][bad-input]") {
    std::string body(1u << 20, 'x');
    for (std::size_t i = 7; i < body.size(); i += 8) body[i] = ' ';
    const std::string svg =
        "<svg xmlns='http://www.w3.org/2000/svg' width='100' height='100'><text x='0' y='50' "
        "font-family='DejaVu Sans' font-size='10'>" +
        body + "</text></svg>";
    const SvgDocument doc = SvgDocument::parse(svg, repo_options());
    CHECK(has_warning(doc, std::to_string(Limits{}.svg_text_chars) + " characters"));
    CHECK(ink(doc.render()) > 0);
}

TEST_CASE("SVG text: a missing font family falls back to the default family, and no font at all warns",
          "[svg_text][bad-input]") {
    const std::string svg =
        "<svg xmlns='http://www.w3.org/2000/svg' width='100' height='60'><text x='5' y='40' "
        "font-family='No Such Font' font-size='30'>Ab</text></svg>";
    const Pixmap with_fallback = SvgDocument::parse(svg, repo_options()).render();
    const std::string same =
        "<svg xmlns='http://www.w3.org/2000/svg' width='100' height='60'><text x='5' y='40' "
        "font-family='DejaVu Sans' font-size='30'>Ab</text></svg>";
    CHECK(ink(with_fallback) > 100);
    CHECK(max_diff(with_fallback, SvgDocument::parse(same, repo_options()).render()) == 0);
    // An empty database: nothing to draw with.
    FontDatabaseOptions none;
    none.system_fonts = false;
    const SvgDocument doc = SvgDocument::parse(svg, repo_options(std::make_shared<const FontDatabase>(none)));
    CHECK(has_warning(doc, "no font"));
    CHECK(ink(doc.render()) == 0);
}

TEST_CASE("SVG text: per-character fallback draws Arabic from another font of the folder", "[svg_text]") {
    const std::string svg =
        "<svg xmlns='http://www.w3.org/2000/svg' width='200' height='60'><text x='5' y='40' "
        "font-family='Linux Libertine O' font-size='30'>\xd9\x85\xd8\xb1\xd8\xad\xd8\xa8\xd8\xa7</text></svg>";
    const SvgDocument doc = SvgDocument::parse(svg, repo_options());
    CHECK(ink(doc.render()) > 100);
}

TEST_CASE("casteljau svg: --font-dir and --font-family draw text, a missing font folder is an error",
          "[svg_text][cli]") {
    namespace fs = std::filesystem;
    const fs::path dir = casteljau::test::scratch_dir("svg_text_cli");
    const fs::path in = dir / "t.svg", out = dir / "t.png";
    {
        std::ofstream f(in);
        f << "<svg xmlns='http://www.w3.org/2000/svg' width='120' height='50'><text x='5' y='35' font-size='30' "
             "font-family='serif'>Text</text></svg>";
    }
    using casteljau::test::shell_quote;
    const auto r = casteljau::test::run_cli("svg " + shell_quote(in.string()) + " -o " + shell_quote(out.string()) +
                                            " --skip-system-fonts --font-dir " + shell_quote(kFontDir) +
                                            " --serif-family 'DejaVu Sans'");
    INFO(r.err);
    REQUIRE(r.status == 0);
    CHECK(ink(read_png(out.string())) > 100);
    const fs::path out2 = dir / "u.png";
    const auto bad = casteljau::test::run_cli("svg " + shell_quote(in.string()) + " -o " + shell_quote(out2.string()) +
                                              " --font-dir " + shell_quote((dir / "missing").string()));
    CHECK(bad.status == 1);
    CHECK(bad.err.rfind("casteljau: error: ", 0) == 0);
    CHECK(bad.err.find("missing") != std::string::npos);
    CHECK_FALSE(fs::exists(out2));
}

TEST_CASE("SVG text: spacing and text paths beyond double range neither fail nor draw garbage",
          "[svg_text][bad-input]") {
    const std::string svg =
        "<svg xmlns='http://www.w3.org/2000/svg' width='100' height='100'><defs><path id='p' d='M 0 0 L 1e308 1e308 L "
        "-1e308 0'/></defs>"
        "<text x='5' y='50' font-family='DejaVu Sans' font-size='20' letter-spacing='1e308'>ABC</text>"
        "<text font-family='DejaVu Sans' font-size='20'><textPath href='#p'>Text</textPath></text></svg>";
    const SvgDocument doc = SvgDocument::parse(svg, repo_options());
    const Pixmap pm = doc.render();
    CHECK(pm.width() == 100);
    // The first glyph stands where it should; the ones pushed to infinity are left out.
    CHECK(ink(pm) > 0);
}

TEST_CASE("SVG text: the character budget counts every use copy of a text", "[svg_text][bad-input]") {
    std::string svg =
        "<svg xmlns='http://www.w3.org/2000/svg' xmlns:xlink='http://www.w3.org/1999/xlink' width='100' height='100'>"
        "<defs><text id='t' font-family='DejaVu Sans' font-size='5'>" +
        std::string(1000, 'x') + "</text></defs>";
    for (int i = 0; i < 200; ++i) svg += "<use xlink:href='#t'/>";
    svg += "</svg>";
    const SvgDocument doc = SvgDocument::parse(svg, repo_options());
    CHECK(has_warning(doc, std::to_string(Limits{}.svg_text_chars) + " characters"));
}

TEST_CASE("SVG text: system fallback draws CJK the document's fonts lack, after them", "[svg_text]") {
    const std::string cjk_font = "/usr/share/fonts/opentype/noto/NotoSansCJK-Regular.ttc";
    if (!std::filesystem::exists(cjk_font)) {
        CASTELJAU_SKIP("no " + cjk_font + " (Debian fonts-noto-cjk)");
        return;
    }
    // "A" from DejaVu Sans, then two Han characters none of the repository's fonts has.
    const std::string svg =
        "<svg xmlns='http://www.w3.org/2000/svg' width='120' height='50'><text x='5' y='38' "
        "font-family='DejaVu Sans' font-size='30'>A\xe6\x97\xa5\xe6\x9c\xac</text></svg>";
    SvgOptions on = repo_options();
    on.system_fallback = true;
    const Pixmap without = SvgDocument::parse(svg, repo_options()).render();
    const Pixmap with = SvgDocument::parse(svg, on).render();
    // Off: .notdef boxes where the Han characters go; on: their glyphs, so the pixels differ there.
    int differ = 0;
    for (int y = 0; y < with.height(); ++y)
        for (int x = 0; x < with.width(); ++x) {
            const auto p = with.pixel(x, y), q = without.pixel(x, y);
            const bool same = p.r == q.r && p.g == q.g && p.b == q.b && p.a == q.a;
            differ += !same;
            // The document's font still draws the "A" (about 20 px wide from x 5).
            if (x < 24) CHECK(same);
        }
    CHECK(differ > 100);
}
