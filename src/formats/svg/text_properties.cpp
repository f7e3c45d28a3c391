// Formats stage, SVG conversion: the text properties (font, font-size, spacing, anchors, baselines,
// decorations) of text elements.
#include "formats/svg/context.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "formats/svg/text_properties.hpp"

namespace casteljau::svg {

std::vector<std::string_view> split_list(std::string_view v) {
    std::vector<std::string_view> out;
    std::size_t i = 0;
    while (i < v.size()) {
        while (i < v.size() && (std::isspace(static_cast<unsigned char>(v[i])) || v[i] == ',')) ++i;
        const std::size_t b = i;
        while (i < v.size() && !std::isspace(static_cast<unsigned char>(v[i])) && v[i] != ',') ++i;
        if (i > b) out.push_back(v.substr(b, i - b));
    }
    return out;
}

// A length for text properties: em and ex relative to `font_size`, percentages of `percent_of`,
// physical units at `dpi` pixels per inch.
std::optional<double> text_length(std::string_view v, double font_size, double percent_of, double dpi) {
    v = trim(v);
    if (v.size() > 2 && v.substr(v.size() - 2) == "em") {
        auto n = parse_number(v.substr(0, v.size() - 2));
        return n ? std::optional<double>(*n * font_size) : std::nullopt;
    }
    if (v.size() > 2 && v.substr(v.size() - 2) == "ex") {
        auto n = parse_number(v.substr(0, v.size() - 2));
        return n ? std::optional<double>(*n * font_size / 2) : std::nullopt;
    }
    return parse_length(v, percent_of, kUnknownFontSize, dpi);
}

std::string generic_family(const Context& cx, std::string_view f) {
    if (f == "serif") return cx.options.serif_family;
    if (f == "sans-serif") return cx.options.sans_serif_family;
    if (f == "cursive") return cx.options.cursive_family;
    if (f == "fantasy") return cx.options.fantasy_family;
    if (f == "monospace") return cx.options.monospace_family;
    return std::string(f);
}

void apply_font_family(const Context& cx, std::string_view v, TextCtx& ctx) {
    std::vector<std::string> fams;
    std::size_t i = 0;
    while (i <= v.size()) {
        std::size_t comma = v.find(',', i);
        if (comma == std::string_view::npos) comma = v.size();
        std::string_view f = trim(v.substr(i, comma - i));
        if (f.size() >= 2 && (f.front() == '\'' || f.front() == '"') && f.back() == f.front())
            f = f.substr(1, f.size() - 2);
        if (!f.empty()) fams.push_back(generic_family(cx, f));
        i = comma + 1;
    }
    if (!fams.empty()) ctx.font.families = std::move(fams);
}

// font-feature-settings and font-variation-settings: a comma-separated list of a quoted tag
// and an optional value ("'liga' 0, 'smcp'"), as (tag, value) pairs without the quotes.
std::vector<std::pair<std::string, std::string>> tag_value_list(std::string_view v) {
    std::vector<std::pair<std::string, std::string>> out;
    std::size_t i = 0;
    while (i <= v.size()) {
        std::size_t comma = v.find(',', i);
        if (comma == std::string_view::npos) comma = v.size();
        std::string item(trim(v.substr(i, comma - i)));
        std::erase(item, '"');
        std::erase(item, '\'');
        const std::size_t sp = item.find(' ');
        if (!item.empty())
            out.emplace_back(item.substr(0, sp), sp == std::string::npos
                                                     ? std::string()
                                                     : std::string(trim(std::string_view(item).substr(sp))));
        i = comma + 1;
    }
    return out;
}

std::optional<int> font_weight(std::string_view v, int parent) {
    if (v == "normal") return 400;
    if (v == "bold") return 700;
    if (v == "bolder") return parent < 350 ? 400 : parent < 550 ? 700 : 900;
    if (v == "lighter") return parent < 550 ? 100 : parent < 750 ? 400 : 700;
    if (auto n = parse_number(v); n && *n >= 1 && *n <= 1000) return static_cast<int>(std::lround(*n));
    return std::nullopt;
}

std::optional<double> font_stretch(std::string_view v) {
    static const std::pair<std::string_view, double> names[] = {
        {"ultra-condensed", 50},  {"extra-condensed", 62.5}, {"condensed", 75},
        {"semi-condensed", 87.5}, {"normal", 100},           {"semi-expanded", 112.5},
        {"expanded", 125},        {"extra-expanded", 150},   {"ultra-expanded", 200}};
    for (const auto& [k, p] : names)
        if (v == k) return p;
    if (!v.empty() && v.back() == '%')
        if (auto n = parse_number(v.substr(0, v.size() - 1)); n && *n >= 0) return *n;
    return std::nullopt;
}

std::optional<double> font_size(std::string_view v, double parent, double dpi) {
    static const std::pair<std::string_view, int> names[] = {{"xx-small", -3}, {"x-small", -2}, {"small", -1},
                                                             {"medium", 0},    {"large", 1},    {"x-large", 2},
                                                             {"xx-large", 3},  {"xxx-large", 4}};
    for (const auto& [k, e] : names)
        if (v == k) return 12.0 * std::pow(1.2, e);
    if (v == "larger") return parent * 1.2;
    if (v == "smaller") return parent / 1.2;
    auto l = text_length(v, parent, parent, dpi);
    if (l && *l >= 0) return l;
    return std::nullopt;
}

svg_text::Baseline baseline_kind(std::string_view v, svg_text::Baseline fallback) {
    using B = svg_text::Baseline;
    if (v == "middle") return B::Middle;
    if (v == "central") return B::Central;
    if (v == "hanging") return B::Hanging;
    if (v == "mathematical") return B::Mathematical;
    if (v == "text-before-edge" || v == "text-top" || v == "before-edge") return B::TextTop;
    if (v == "text-after-edge" || v == "text-bottom" || v == "after-edge") return B::TextBottom;
    if (v == "ideographic") return B::Ideographic;
    if (v == "alphabetic") return B::Alphabetic;
    return fallback;
}

// The `font` shorthand: [style] [variant] [weight] [stretch] size[/line-height] family-list.
// An invalid value (no size, a size without a unit, no family) changes nothing; a valid one
// resets the style, weight, stretch and variant it does not give, and font-kerning to auto.
void apply_font_shorthand(const Context& cx, std::string_view v, TextCtx& ctx, double parent_size) {
    TextCtx t = ctx;
    t.font.slant = FontSlant::Normal;
    t.font.weight = 400;
    t.font.stretch = 100;
    t.small_caps = false;
    t.no_kerning = false;
    std::size_t i = 0;
    while (i < v.size()) {
        while (i < v.size() && std::isspace(static_cast<unsigned char>(v[i]))) ++i;
        std::size_t e = i;
        while (e < v.size() && !std::isspace(static_cast<unsigned char>(v[e]))) ++e;
        const std::string_view w = v.substr(i, e - i);
        if (w.empty()) return;
        if (w == "italic")
            t.font.slant = FontSlant::Italic;
        else if (w == "oblique")
            t.font.slant = FontSlant::Oblique;
        else if (w == "small-caps")
            t.small_caps = true;
        else if (w == "normal") {
        } else if (w == "bold" || w == "bolder" || w == "lighter") {
            t.font.weight = *font_weight(w, ctx.font.weight);
        } else if (auto fs = font_stretch(w)) {
            t.font.stretch = *fs;
        } else {
            const std::string_view size = w.substr(0, w.find('/'));
            const bool bare_number = parse_number(size).has_value();
            if (bare_number && w.find('/') == std::string_view::npos && e < v.size()) {
                // A bare number before the size is a weight; a bare number as the size is invalid.
                auto fw = font_weight(w, ctx.font.weight);
                std::size_t n = e;
                while (n < v.size() && std::isspace(static_cast<unsigned char>(v[n]))) ++n;
                std::size_t ne = n;
                while (ne < v.size() && !std::isspace(static_cast<unsigned char>(v[ne]))) ++ne;
                const std::string_view next = v.substr(n, ne - n).substr(0, v.substr(n, ne - n).find('/'));
                if (fw && !next.empty() && font_size(next, parent_size, cx.options.dpi) && !parse_number(next)) {
                    t.font.weight = *fw;
                    i = e;
                    continue;
                }
                return;
            }
            if (bare_number && *parse_number(size) != 0) return;
            auto fsz = font_size(size, parent_size, cx.options.dpi);
            if (!fsz) return;
            const std::string_view family = trim(v.substr(e));
            if (family.empty()) return;
            t.font.size = *fsz;
            apply_font_family(cx, family, t);
            ctx = t;
            return;
        }
        i = e;
    }
}

namespace {

// font-feature-settings: normal, or tags with values (on and off as 1 and 0).
void apply_feature_settings(std::string_view val, TextCtx& ctx) {
    ctx.feature_settings.clear();
    if (val == "normal") return;
    for (auto& [tag, value] : tag_value_list(val)) {
        if (value == "on") value = "1";
        if (value == "off") value = "0";
        ctx.feature_settings.push_back(value.empty() ? tag : tag + "=" + value);
    }
}

// The font's properties other than its size: family, weight, style, stretch, small caps,
// kerning, features and variations. False for another property.
bool apply_font_property(Context& cx, const pugi::xml_node& node, const std::string& k, std::string_view val,
                         TextCtx& ctx) {
    if (k == "font-family")
        apply_font_family(cx, val, ctx);
    else if (k == "font-weight") {
        if (auto w = font_weight(val, ctx.font.weight)) ctx.font.weight = *w;
    } else if (k == "font-style") {
        if (val == "normal")
            ctx.font.slant = FontSlant::Normal;
        else if (val == "italic")
            ctx.font.slant = FontSlant::Italic;
        else if (val.substr(0, 7) == "oblique")
            ctx.font.slant = FontSlant::Oblique;
    } else if (k == "font-stretch") {
        if (auto s = font_stretch(val)) ctx.font.stretch = *s;
    } else if (k == "font-variant" || k == "font-variant-caps") {
        ctx.small_caps = val == "small-caps";
    } else if (k == "font-kerning") {
        // A CSS property only (resvg ignores the presentation attribute).
        if (!node.attribute("font-kerning")) ctx.no_kerning = val == "none";
    } else if (k == "kerning") {
        // SVG 1.1: "auto" or a length; 0 turns kerning off, other lengths are not supported.
        if (val == "auto")
            ctx.no_kerning = false;
        else if (auto l = parse_length(val, 1, kUnknownFontSize, cx.options.dpi); l && *l == 0)
            ctx.no_kerning = true;
    } else if (k == "font-feature-settings") {
        apply_feature_settings(val, ctx);
    } else if (k == "font-variation-settings") {
        ctx.font.variations.clear();
        if (val != "normal")
            for (const auto& [tag, value] : tag_value_list(val))
                if (auto n = parse_number(value); n && tag.size() <= 4) ctx.font.variations.push_back({tag, *n});
    } else {
        return false;
    }
    return true;
}

// text-decoration and text-decoration-line: keywords separated by white space (a comma makes the
// value invalid), each drawn in the element's style.
void apply_decoration(std::string_view val, TextCtx& ctx) {
    if (val.find(',') != std::string_view::npos) return;
    for (std::string_view w : split_list(val)) {
        svg_text::Decoration d;
        d.style = ctx.style;
        if (w == "underline")
            d.kind = svg_text::Decoration::Underline;
        else if (w == "overline")
            d.kind = svg_text::Decoration::Overline;
        else if (w == "line-through")
            d.kind = svg_text::Decoration::LineThrough;
        else
            continue;
        ctx.decorations.push_back(d);
    }
}

// Spacing (relative to the font size `fs`), anchoring, baselines, decorations and direction.
void apply_layout_property(Context& cx, const pugi::xml_node& node, const std::string& k, std::string_view val,
                           double fs, TextCtx& ctx) {
    if (k == "letter-spacing" || k == "word-spacing") {
        double& spacing = k == "letter-spacing" ? ctx.letter_spacing : ctx.word_spacing;
        if (val == "normal")
            spacing = 0;
        else if (auto l = text_length(val, fs, ctx.viewport_width, cx.options.dpi))
            spacing = *l;
    } else if (k == "text-anchor") {
        if (val == "start")
            ctx.anchor = svg_text::Anchor::Start;
        else if (val == "middle")
            ctx.anchor = svg_text::Anchor::Middle;
        else if (val == "end")
            ctx.anchor = svg_text::Anchor::End;
    } else if (k == "dominant-baseline") {
        // auto is alphabetic in horizontal text; SVG 1.1's no-change (and any value not
        // understood) keeps the inherited baseline.
        ctx.dominant = val == "auto" ? svg_text::Baseline::Alphabetic : baseline_kind(val, ctx.dominant);
        ctx.baseline = ctx.dominant;
    } else if (k == "alignment-baseline") {
        ctx.baseline = baseline_kind(val, ctx.dominant);
    } else if (k == "baseline-shift" && std::string_view(node.name()) != "text") {
        // Not on the text element itself (as resvg): only tspans shift their baseline.
        if (val == "sub")
            ctx.baseline_shifts.push_back({1, 0});
        else if (val == "super")
            ctx.baseline_shifts.push_back({2, 0});
        else if (val != "baseline")
            if (auto l = text_length(val, fs, fs, cx.options.dpi)) ctx.baseline_shifts.push_back({0, *l});
    } else if (k == "text-decoration" || k == "text-decoration-line") {
        apply_decoration(val, ctx);
    } else if (k == "direction") {
        ctx.direction = std::string(val);
    }
}

}  // namespace

// Applies the text properties `node` sets itself to `ctx` (inherited ones carry on to children).
// The font size comes first (the font shorthand sets it too): other lengths are relative to it.
void apply_text_props(Context& cx, const pugi::xml_node& node, TextCtx& ctx) {
    const double parent_size = ctx.font.size;
    // alignment-baseline is not inherited (only the keyword inherit takes the parent's value).
    const svg_text::Baseline parent_alignment = ctx.baseline;
    ctx.baseline = ctx.dominant;
    for (const auto& [k, v] : properties(cx, node)) {
        const std::string_view val = trim(v);
        if (val == "inherit") continue;
        if (k == "font")
            apply_font_shorthand(cx, val, ctx, parent_size);
        else if (k == "font-size") {
            if (auto s = font_size(val, parent_size, cx.options.dpi)) ctx.font.size = *s;
        }
    }
    const double fs = ctx.font.size;
    for (const auto& [k, v] : properties(cx, node)) {
        const std::string_view val = trim(v);
        if (val == "inherit") {
            if (k == "alignment-baseline") ctx.baseline = parent_alignment;
            continue;
        }
        if (!apply_font_property(cx, node, k, val, ctx)) apply_layout_property(cx, node, k, val, fs, ctx);
    }
    if (const char* sp = node.attribute("xml:space").value(); *sp) ctx.preserve = std::string_view(sp) == "preserve";
    ctx.font.features.clear();
    if (ctx.small_caps) ctx.font.features.push_back("smcp");
    if (ctx.no_kerning) ctx.font.features.push_back("kern=0");
    for (const std::string& f : ctx.feature_settings) ctx.font.features.push_back(f);
}

}  // namespace casteljau::svg
