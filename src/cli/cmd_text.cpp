// `casteljau text`: lay out and draw UTF-8 text with casteljau's text pipeline and write a PNG.
//
// The default font is DejaVuSans.ttf, looked for in this order: $CASTELJAU_FONT_DIR,
// <executable's folder>/../fonts, <executable's folder>/../../fonts,
// <executable's folder>/../share/casteljau/fonts (the installed layout), then the two folders fixed
// when the build was configured: the install prefix's share/casteljau/fonts
// (CASTELJAU_FONT_INSTALL_DIR) and the source tree's fonts/ (CASTELJAU_FONT_SOURCE_DIR), so a build
// folder placed anywhere finds the shipped fonts without installing.
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "casteljau/canvas.hpp"
#include "casteljau/error.hpp"
#include "casteljau/font.hpp"
#include "casteljau/limits.hpp"
#include "casteljau/png.hpp"
#include "casteljau/svg.hpp"
#include "casteljau/text.hpp"
#include "cli/cli.hpp"

// LeakSanitizer (sanitizer builds): fontconfig 2.14 loses a pattern while parsing its
// configuration files, once per configuration loaded (288 bytes here); system font fallback loads
// one per process. Not casteljau's memory, so not reported.
extern "C" const char* __lsan_default_suppressions() { return "leak:libfontconfig.so\n"; }

namespace casteljau::cli {

namespace {

constexpr const char* kDefaultFontFile = "DejaVuSans.ttf";

std::vector<std::filesystem::path> default_font_dirs() {
    namespace fs = std::filesystem;
    std::vector<fs::path> dirs;
    if (const char* env = std::getenv("CASTELJAU_FONT_DIR"); env && *env) dirs.emplace_back(env);
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        const fs::path dir = exe.parent_path();
        dirs.push_back(dir / ".." / "fonts");
        dirs.push_back(dir / ".." / ".." / "fonts");
        dirs.push_back(dir / ".." / "share" / "casteljau" / "fonts");
    }
#ifdef CASTELJAU_FONT_INSTALL_DIR
    dirs.emplace_back(CASTELJAU_FONT_INSTALL_DIR);
#endif
#ifdef CASTELJAU_FONT_SOURCE_DIR
    dirs.emplace_back(CASTELJAU_FONT_SOURCE_DIR);
#endif
    return dirs;
}

std::string find_default_font() {
    std::string tried;
    for (const auto& dir : default_font_dirs()) {
        std::error_code ec;
        const auto p = dir / kDefaultFontFile;
        if (std::filesystem::is_regular_file(p, ec)) return p.lexically_normal().string();
        tried += (tried.empty() ? "" : ", ") + dir.lexically_normal().string();
    }
    throw Error(ErrorKind::Io, std::string("cannot find the default font ") + kDefaultFontFile +
                                   " (looked in: " + tried + "); pass --font FILE or set CASTELJAU_FONT_DIR");
}

double parse_number(const std::string& option, const std::string& text) {
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(v) || errno == ERANGE)
        throw UsageError(option + ": expected a number, got '" + text + "'");
    return v;
}

struct TextOptions {
    std::string text, output, size = "32", color = "black", background = "white", width, align = "start",
                              line_height = "1", padding = "4", direction = "auto", script, language;
    std::vector<std::string> fonts, variations, features;
    std::vector<int> faces;
    bool gamma = false, no_system_fonts = false;
    int palette = 0;
};

// The fonts and what is done with them: files, faces, variations, features, fallback, colour.
void add_font_options(CLI::App* cmd, TextOptions& o) {
    cmd->add_option("--font", o.fonts,
                    "Font file (TrueType, OpenType CFF/CFF2, collection, variable); repeat for a fallback chain. "
                    "Default: DejaVuSans.ttf from $CASTELJAU_FONT_DIR, <exe>/../fonts, <exe>/../../fonts, "
                    "<exe>/../share/casteljau/fonts, the configured install or source fonts folder");
    cmd->add_option("--face", o.faces, "Face index in a collection, for the --font at the same position (default 0)");
    cmd->add_option("--size", o.size, "Font size in pixels per em, greater than 0 and at most 10000")
        ->capture_default_str();
    cmd->add_option("--color", o.color, "Text colour (CSS syntax)")->capture_default_str();
    cmd->add_option("--background", o.background, "Background colour (CSS syntax; transparent allowed)")
        ->capture_default_str();
    cmd->add_option("--variation", o.variations,
                    "Variable-font axis setting TAG=VALUE, e.g. wght=700 (repeatable; applied to every font that has "
                    "the axis; an axis no font has is an error)");
    cmd->add_option("--feature", o.features, "OpenType feature for HarfBuzz, e.g. kern=0, liga=0, smcp (repeatable)");
    cmd->add_flag("--no-system-fonts", o.no_system_fonts,
                  "Use only the --font files (or the default font): characters they lack show as the first font's "
                  ".notdef box instead of coming from the system's fonts (fontconfig), so the output is the same on "
                  "every machine");
    cmd->add_option("--palette", o.palette,
                    "CPAL palette of colour glyphs (emoji, COLR fonts); 0 is the font's default. Colour glyphs keep "
                    "their palette's colours; --color colours the other glyphs and palette entry 0xFFFF")
        ->check(CLI::Range(0, 65535))
        ->capture_default_str();
    cmd->add_flag("--gamma-correct", o.gamma, "Blend coverage in linear light (gamma-correct) instead of sRGB");
}

// Lines and paragraphs: wrapping, alignment, spacing, direction, script and language.
void add_layout_options(CLI::App* cmd, TextOptions& o) {
    cmd->add_option("--width", o.width,
                    "Wrap lines at word boundaries to this width in pixels (the image is this wide plus padding)");
    cmd->add_option("--align", o.align,
                    "left, center, right, or start (left for left-to-right paragraphs, right for right-to-left)")
        ->check(CLI::IsMember({"left", "center", "right", "start"}))
        ->capture_default_str();
    cmd->add_option("--line-height", o.line_height, "Line advance as a multiple of the first font's line spacing")
        ->capture_default_str();
    cmd->add_option("--padding", o.padding, "Empty margin around the text in pixels")->capture_default_str();
    cmd->add_option("--direction", o.direction,
                    "Base direction of paragraphs: auto (from the first strong letter), ltr, rtl")
        ->check(CLI::IsMember({"auto", "ltr", "rtl"}))
        ->capture_default_str();
    cmd->add_option("--script", o.script,
                    "ISO 15924 script tag for shaping (Latn, Arab, Hebr, ...); default: detected");
    cmd->add_option("--language", o.language, "BCP 47 language tag for shaping (en, ar, tr, ...)");
}

// The option values, checked before any file is read (UsageError).
struct TextRequest {
    TextStyle style;
    Color color, background;
    int padding = 0;
    std::vector<Variation> variations;
};

TextRequest checked_request(const TextOptions& o) {
    TextRequest r;
    TextStyle& style = r.style;
    style.size = parse_number("--size", o.size);
    if (!(style.size > 0) || style.size > limits::kMaxFontSize)
        throw UsageError("--size: must be greater than 0 and at most " +
                         std::to_string(static_cast<int>(limits::kMaxFontSize)) + " pixels, got '" + o.size + "'");
    r.color = parse_color_option("--color", o.color);
    r.background = parse_color_option("--background", o.background);
    if (!o.width.empty()) {
        style.max_width = parse_number("--width", o.width);
        if (!(style.max_width >= 1) || style.max_width > limits::kMaxCanvasDimension)
            throw UsageError("--width: must be 1 to " + std::to_string(limits::kMaxCanvasDimension) + " pixels, got '" +
                             o.width + "'");
    }
    style.line_height = parse_number("--line-height", o.line_height);
    if (!(style.line_height > 0) || style.line_height > 100)
        throw UsageError("--line-height: must be greater than 0 and at most 100, got '" + o.line_height + "'");
    const double padding = parse_number("--padding", o.padding);
    if (!(padding >= 0) || padding > limits::kMaxCanvasDimension || padding != std::floor(padding))
        throw UsageError("--padding: must be a whole number of pixels from 0 to " +
                         std::to_string(limits::kMaxCanvasDimension) + ", got '" + o.padding + "'");
    r.padding = static_cast<int>(padding);
    for (const std::string& v : o.variations) {
        try {
            r.variations.push_back(parse_variation(v));
        } catch (const Error& e) { throw UsageError(std::string("--variation: ") + e.what()); }
    }
    if (o.faces.size() > std::max<std::size_t>(o.fonts.size(), 1))
        throw UsageError("--face: given " + std::to_string(o.faces.size()) + " times for " +
                         std::to_string(std::max<std::size_t>(o.fonts.size(), 1)) + " font(s)");
    for (int f : o.faces)
        if (f < 0 || f > 65535) throw UsageError("--face: must be 0 to 65535, got " + std::to_string(f));
    style.align = o.align == "left"     ? TextAlign::Left
                  : o.align == "center" ? TextAlign::Center
                  : o.align == "right"  ? TextAlign::Right
                                        : TextAlign::Start;
    style.direction = o.direction == "ltr"   ? TextDirection::LeftToRight
                      : o.direction == "rtl" ? TextDirection::RightToLeft
                                             : TextDirection::Auto;
    style.script = o.script;
    style.language = o.language;
    style.features = o.features;
    style.system_fonts = !o.no_system_fonts;
    return r;
}

// The text argument, or standard input for "-" (without the newline that ends it); never empty.
std::string read_text(const std::string& arg) {
    std::string text = arg;
    if (text == "-") {
        text = read_text_input("-");
        if (!text.empty() && text.back() == '\n') text.pop_back();
        if (!text.empty() && text.back() == '\r') text.pop_back();
    }
    if (text.empty()) throw Error(ErrorKind::InvalidData, "nothing to render: the text is empty");
    return text;
}

// The --font chain (or the default font), each at its --face, with the variations set.
std::vector<Font> load_fonts(const TextOptions& o, const std::vector<Variation>& variations) {
    std::vector<std::string> paths = o.fonts;
    if (paths.empty()) paths.push_back(find_default_font());
    std::vector<Font> fonts;
    fonts.reserve(paths.size());
    for (std::size_t i = 0; i < paths.size(); ++i)
        fonts.push_back(Font::load(paths[i], i < o.faces.size() ? o.faces[i] : 0));
    std::vector<Font*> chain;
    for (Font& f : fonts) chain.push_back(&f);
    set_chain_variations(chain, variations);
    return fonts;
}

void run_text(const TextOptions& o) {
    const TextRequest r = checked_request(o);  // usage first
    const std::string text = read_text(o.text);
    const std::vector<Font> fonts = load_fonts(o, r.variations);
    std::vector<const Font*> chain;
    for (const Font& f : fonts) chain.push_back(&f);

    enable_svg_glyphs();  // colour glyphs of OpenType SVG fonts, measured in the layout too
    const TextLayout layout = layout_text(text, chain, r.style);
    const Rect b = layout.bounds();
    const double x0 = std::floor(b.x0), y0 = std::floor(b.y0), x1 = std::ceil(b.x1), y1 = std::ceil(b.y1);
    const double w = std::max(1.0, x1 - x0) + 2.0 * r.padding, h = std::max(1.0, y1 - y0) + 2.0 * r.padding;
    check_canvas_size(w, h);
    Pixmap pm(static_cast<int>(w), static_cast<int>(h));
    pm.fill(r.background);
    Canvas canvas(pm);
    Paint paint = Paint::solid(r.color);
    paint.linear_blend = o.gamma;
    TextDrawOptions draw;
    draw.palette = o.palette;
    draw_text(canvas, layout, {r.padding - x0, r.padding - y0}, paint, nullptr, draw);
    write_png(pm, o.output);
}

}  // namespace

void register_text(CLI::App& app) {
    auto o = std::make_shared<TextOptions>();
    CLI::App* cmd = app.add_subcommand(
        "text",
        "Render UTF-8 text to a PNG: HarfBuzz shaping (kerning, ligatures, marks, right-to-left), line breaks on "
        "newlines, optional wrapping and alignment, font fallback (the --font chain, then the system's fonts), glyphs "
        "drawn by casteljau's exact-area "
        "rasterizer. Without --width the image fits the text plus padding.");
    cmd->add_option("TEXT", o->text, "The text (UTF-8; invalid bytes show as U+FFFD); - reads standard input")
        ->required();
    cmd->add_option("-o,--output", o->output, "Output PNG file")->required();
    add_font_options(cmd, *o);
    add_layout_options(cmd, *o);
    cmd->callback([o] { run_text(*o); });
}

}  // namespace casteljau::cli
