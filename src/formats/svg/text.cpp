// Formats stage, SVG conversion: text elements (text, tspan, tref, textPath, a) converted into
// glyph outlines, painted as fills and strokes.
#include "formats/svg/context.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "casteljau/flatten.hpp"
#include "casteljau/text.hpp"
#include "formats/svg/text_properties.hpp"
#include "formats/svg/text_layout.hpp"

namespace casteljau::svg {

namespace {

// The fonts of the document, opened when its first text is laid out.
svg_text::FontSet* text_fonts(Context& cx) {
    if (!cx.font_set) {
        std::shared_ptr<const FontDatabase> db = cx.options.font_database;
        if (!db) {
            FontDatabaseOptions fo;
            fo.font_dirs = cx.options.font_dirs;
            fo.font_files = cx.options.font_files;
            fo.system_fonts = cx.options.system_fonts;
            db = std::make_shared<const FontDatabase>(fo);
            cx.options.font_database = db;  // nested SVG images share it
        }
        cx.font_set = std::make_unique<svg_text::FontSet>(db, cx.options.system_fallback);
    }
    return cx.font_set.get();
}

// Appends the characters of a text node under white-space processing (xml:space).
void text_chars(Context& cx, std::string_view raw, const TextCtx& ctx, TextBuild& b) {
    std::u32string in = decode_utf8(raw), out;
    for (char32_t c : in) {
        if (cx.text_chars_total + out.size() >= cx.limits.svg_text_chars) {
            b.truncated = true;
            break;
        }
        if (ctx.preserve) {
            // Kept as they are (newlines and tabs become spaces); a collapsible space right
            // after a preserved one still collapses.
            const char32_t k = (c == U'\n' || c == U'\r' || c == U'\t') ? U' ' : c;
            out += k;
            b.last_space = k == U' ';
            b.last_preserved = true;
            continue;
        }
        b.last_preserved = false;
        if (c == U'\n' || c == U'\r') continue;
        if (c == U'\t') c = U' ';
        if (c == U' ') {
            if (b.last_space) continue;
            b.last_space = true;
        } else {
            b.last_space = false;
        }
        out += c;
    }
    if (out.empty()) return;
    svg_text::Span sp;
    sp.style = ctx.style;
    sp.font = ctx.font;
    sp.text = std::move(out);
    sp.letter_spacing = ctx.letter_spacing;
    sp.word_spacing = ctx.word_spacing;
    sp.anchor = ctx.anchor;
    sp.baseline = ctx.baseline;
    sp.baseline_shifts = ctx.baseline_shifts;
    sp.decorations = ctx.decorations;
    sp.path = ctx.path;
    sp.path_element = ctx.path_element;
    b.chars += sp.text.size();
    cx.text_chars_total += sp.text.size();
    b.in.spans.push_back(std::move(sp));
}

// The text content of an element and its descendants (for tref).
void all_text(const pugi::xml_node& n, std::string& out) {
    for (const pugi::xml_node& c : n.children()) {
        if (c.type() == pugi::node_pcdata || c.type() == pugi::node_cdata)
            out += c.value();
        else if (c.type() == pugi::node_element && std::string_view(c.name()) != "title" &&
                 std::string_view(c.name()) != "desc" && std::string_view(c.name()) != "metadata")
            all_text(c, out);
    }
}

// A text, tspan, tref, textPath or a element and its children appended to `b` with their styles and
// text properties.
void text_element(Context& cx, const pugi::xml_node& node, TextCtx ctx, const Style& parent, const Affine& text_m,
                  Viewport vp, TextBuild& b, int depth) {
    if (depth > cx.limits.nesting_depth)
        throw Error(ErrorKind::Limit, "SVG elements nested deeper than " + std::to_string(cx.limits.nesting_depth));
    for (const auto& [k, v] : properties(cx, node))
        if (k == "display" && trim(v) == "none") return;
    Style st = parent;
    apply_style(cx, node, st);
    ctx.style = b.styles.size();
    b.styles.push_back(st);
    // Decorations declared outside the text element are painted with the text's own paint.
    for (svg_text::Decoration& d : ctx.decorations)
        if (d.style == kTextElementStyle) d.style = ctx.style;
    apply_text_props(cx, node, ctx);
    const std::string_view name = node.name();
    if (name == "textPath") {
        const char* h = href(node);
        const pugi::xml_node target = *h == '#' ? lookup(cx, h + 1) : pugi::xml_node();
        std::optional<Path> p;
        // SVG 2: any basic shape may carry the text, not only a path.
        if (target) p = shape_path(cx, target, vp);
        if (p && p->control_bounds().width() == 0 && p->control_bounds().height() == 0) p.reset();  // no length
        if (!p || p->empty()) {
            warn(cx, "<textPath> references no usable path; its text is not drawn");
            return;
        }
        Affine pt;
        if (const char* t = target.attribute("transform").value(); *t) {
            try {
                pt = with_origin(cx, target, parse_svg_transform(t), vp);
            } catch (const Error&) {}
        }
        (void)text_m;
        svg_text::TextPath tp;
        tp.path = p->transformed(pt);
        // side="right" (SVG 2) is ignored, as resvg and most browsers do.
        if (const char* so = node.attribute("startOffset").value(); *so) {
            std::string_view sv = trim(so);
            if (!sv.empty() && sv.back() == '%') {
                if (auto pct = parse_number(sv.substr(0, sv.size() - 1))) {
                    Polyline poly;
                    try {
                        flatten(tp.path, Affine{}, 0.01, poly);
                    } catch (const Error&) {
                        poly.clear();  // an unusable path: the text is not drawn (text_layout.cpp)
                    }
                    double total = 0;
                    std::uint32_t s0 = 0;
                    for (std::size_t c = 0; c < poly.contour_count(); ++c) {
                        for (std::uint32_t i = s0 + 1; i < poly.contour_ends[c]; ++i)
                            total += std::hypot(poly.points[i].x - poly.points[i - 1].x,
                                                poly.points[i].y - poly.points[i - 1].y);
                        s0 = poly.contour_ends[c];
                    }
                    tp.start_offset = *pct / 100 * total;
                }
            } else if (auto l = text_length(sv, ctx.font.size, vp.w, cx.options.dpi)) {
                tp.start_offset = *l;
            }
        }
        ctx.path = static_cast<int>(b.in.paths.size());
        ctx.path_element = ++b.path_elements;
        b.in.paths.push_back(std::move(tp));
    }
    const std::size_t range_index = b.ranges.size();
    b.ranges.push_back({node, b.chars, b.chars, ctx.font.size});
    if (name == "tref") {
        const char* h = href(node);
        const pugi::xml_node target = *h == '#' ? lookup(cx, h + 1) : pugi::xml_node();
        // Only SVG elements lend their text (resvg): <not-a-text> gives none.
        const std::string_view tn = target ? target.name() : "";
        if (target && (known_element(tn) || tn == "tspan" || tn == "textPath" || tn == "tref" || tn == "g")) {
            std::string s;
            all_text(target, s);
            text_chars(cx, s, ctx, b);
        }
    } else {
        for (const pugi::xml_node& c : node.children()) {
            if (c.type() == pugi::node_pcdata || c.type() == pugi::node_cdata) {
                text_chars(cx, c.value(), ctx, b);
            } else if (c.type() == pugi::node_element) {
                const std::string_view cn = c.name();
                if (!conditions_pass(c)) continue;
                if (cn == "tspan" || cn == "a" || cn == "tref" || (cn == "textPath" && ctx.path < 0))
                    text_element(cx, c, ctx, st, text_m, vp, b, depth + 1);
            }
        }
    }
    b.ranges[range_index].end = b.chars;
}

// The ancestors `node` inherits from, innermost first: its parents, except that an element
// instanced by a use being expanded has that use as its parent (the use hosts the instance).
std::vector<pugi::xml_node> inheritance_ancestors(const Context& cx, const pugi::xml_node& node) {
    std::vector<pugi::xml_node> anc;
    std::size_t uses = cx.use_stack.size();
    for (pugi::xml_node n = node;;) {
        pugi::xml_node p = n.parent();
        if (uses > 0) {
            const char* h = href(cx.use_stack[uses - 1]);
            if (*h == '#' && lookup(cx, h + 1) == n) p = cx.use_stack[--uses];
        }
        if (!p || p.type() != pugi::node_element) break;
        anc.push_back(p);
        n = p;
    }
    return anc;
}

}  // namespace

// Lays out a text element: the outlines of its spans with their styles.
std::vector<svg_text::Outline> text_outlines(Context& cx, const pugi::xml_node& node, const Style& st, Viewport vp,
                                             std::vector<Style>& styles, std::optional<Rect>* box,
                                             std::vector<svg_text::ColorGlyph>* color) {
    TextCtx ctx;
    ctx.viewport_width = vp.w;
    // Inherited text properties from the ancestors, outermost first.
    const std::vector<pugi::xml_node> anc = inheritance_ancestors(cx, node);
    for (auto it = anc.rbegin(); it != anc.rend(); ++it) {
        apply_text_props(cx, *it, ctx);
        for (svg_text::Decoration& d : ctx.decorations) d.style = kTextElementStyle;
        ctx.baseline_shifts.clear();
    }
    TextBuild b;
    text_element(cx, node, ctx, st, Affine{}, vp, b, 1);
    if (b.truncated)
        warn(cx, "the document's text holds more than " + std::to_string(cx.limits.svg_text_chars) +
                     " characters; the rest is not drawn");
    // A trailing collapsible space is removed.
    if (!b.in.spans.empty() && b.last_space && !b.last_preserved && !b.in.spans.back().text.empty() &&
        b.in.spans.back().text.back() == U' ') {
        b.in.spans.back().text.pop_back();
        --b.chars;
        if (b.in.spans.back().text.empty()) b.in.spans.pop_back();
    }
    for (const svg_text::Span& sp : b.in.spans) {
        if (!(sp.font.size <= limits::kMaxSvgFontSize)) {
            warn(cx, "font-size above " + std::to_string(static_cast<long long>(limits::kMaxSvgFontSize)) +
                         "; text not drawn");
            return {};
        }
    }
    if (b.chars == 0) return {};
    // Every font-family list ends with the default family.
    for (svg_text::Span& sp : b.in.spans) sp.font.families.push_back(cx.options.font_family);
    // Position lists: outer elements first, inner ones override.
    b.in.pos.assign(b.chars, {});
    for (TextBuild::Range& r : b.ranges) {
        r.end = std::min(r.end, b.chars);  // the trailing space may have gone
        r.begin = std::min(r.begin, r.end);
        auto list = [&](const char* attr, double percent_of, std::optional<double> svg_text::CharPos::*field,
                        bool repeat_last) {
            const char* v = r.node.attribute(attr).value();
            if (!*v) return;
            std::optional<double> last;
            std::size_t i = r.begin;
            for (std::string_view w : split_list(v)) {
                if (i >= r.end) break;
                auto l = std::string_view(attr) == "rotate" ? parse_number(w)
                                                            : text_length(w, r.font_size, percent_of, cx.options.dpi);
                if (!l) return;
                b.in.pos[i++].*field = *l;
                last = *l;
            }
            if (repeat_last && last)
                for (; i < r.end; ++i) b.in.pos[i].*field = *last;
        };
        list("x", vp.w, &svg_text::CharPos::x, false);
        list("y", vp.h, &svg_text::CharPos::y, false);
        list("dx", vp.w, &svg_text::CharPos::dx, false);
        list("dy", vp.h, &svg_text::CharPos::dy, false);
        list("rotate", 1, &svg_text::CharPos::rotate, true);
        if (const char* tl = r.node.attribute("textLength").value(); *tl && r.end > r.begin) {
            // Only a negative length is an error: 0 squeezes the text to no advance at all.
            if (auto l = text_length(tl, r.font_size, vp.w, cx.options.dpi); l && *l >= 0)
                b.in.lengths.push_back(
                    {r.begin, r.end, *l,
                     std::string_view(r.node.attribute("lengthAdjust").value()) == "spacingAndGlyphs"});
        }
    }
    std::string dir;
    for (const auto& [k, v] : properties(cx, node))
        if (k == "direction") dir = std::string(trim(v));
    if (dir.empty()) dir = inherited(cx, node, "direction");
    b.in.direction = dir == "rtl" ? TextDirection::RightToLeft : TextDirection::LeftToRight;
    std::string wm;
    for (const auto& [k, v] : properties(cx, node))
        if (k == "writing-mode") wm = std::string(trim(v));
    if (wm.empty()) wm = inherited(cx, node, "writing-mode");
    b.in.vertical = wm == "tb" || wm == "tb-rl" || wm == "vertical-rl" || wm == "vertical-lr";
    styles = std::move(b.styles);
    return svg_text::layout(b.in, *text_fonts(cx), cx.warnings, box, color);
}

namespace {

// Colour glyphs in their palette's colours; the span's solid fill colour stands for the text
// colour entry, and the fill and element opacities multiply them.
void color_glyphs(Context& cx, const std::vector<svg_text::ColorGlyph>& glyphs, const std::vector<Style>& styles,
                  const Affine& cm, double opacity) {
    for (const svg_text::ColorGlyph& g : glyphs) {
        const Style& s = styles[g.style];
        if (!s.visible) continue;
        DisplayItem it;
        it.kind = DisplayItem::ColorGlyph;
        it.font = g.font;
        it.glyph = g.glyph;
        it.glyph_size = g.size;
        it.transform = cm * g.transform;
        it.color = s.fill.kind == PaintRef::Solid ? s.fill.color : Color::black();
        it.opacity = s.fill_opacity * opacity;
        cx.items.push_back(std::move(it));
    }
}

}  // namespace

void text(Context& cx, const pugi::xml_node& node, const Style& st, const Affine& cm, Viewport vp, double opacity) {
    std::vector<Style> styles;
    std::optional<Rect> cells;
    std::vector<svg_text::ColorGlyph> colored;
    const std::vector<svg_text::Outline> outlines = text_outlines(cx, node, st, vp, styles, &cells, &colored);
    if (!cells || (outlines.empty() && colored.empty())) return;
    // The text's bounding box is the union of its glyph cells (SVG 2), hidden spans included: it
    // counts in its group's bounding box, and paint servers in objectBoundingBox units use it.
    Path box;
    box.add_rect(*cells);
    cx.items.push_back(bounds_item(box, cm));
    for (svg_text::Outline::Layer layer :
         {svg_text::Outline::Under, svg_text::Outline::Glyphs, svg_text::Outline::Over}) {
        for (const svg_text::Outline& o : outlines) {
            if (o.layer != layer || o.path.empty()) continue;
            const Style& s = styles[o.style];
            if (!s.visible) continue;
            for (int part : s.paint_order) {
                DisplayItem it;
                if (part == 0 && resolve_paint(cx, s.fill, box, cm, vp, it)) {
                    it.kind = DisplayItem::Fill;
                    it.path = o.path;
                    it.transform = cm;
                    it.rule = s.fill_rule;
                    it.opacity = s.fill_opacity * opacity;
                    cx.items.push_back(std::move(it));
                } else if (part == 1 && s.stroke_style.width > 0 && resolve_paint(cx, s.stroke, box, cm, vp, it)) {
                    it.kind = DisplayItem::Stroke;
                    it.stroke = s.stroke_style;
                    it.path = o.path;
                    it.transform = cm;
                    it.opacity = s.stroke_opacity * opacity;
                    cx.items.push_back(std::move(it));
                }
            }
        }
        if (layer == svg_text::Outline::Glyphs) color_glyphs(cx, colored, styles, cm, opacity);
    }
}

}  // namespace casteljau::svg
