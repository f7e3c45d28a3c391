// Formats stage, SVG conversion: fill, stroke and the other painting properties of an element
// resolved into a Style.
#include "formats/svg/context.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace casteljau::svg {

// A fill or stroke value: none, currentColor, inherit (keeps the inherited paint), a colour,
// or url(#id) with an optional fallback (none or a colour) after it.
void apply_paint(Context& cx, const std::string& property, std::string_view value, Color current, PaintRef& paint) {
    auto simple = [&](std::string_view v, PaintRef::Kind& kind, Color& color, bool& is_current) -> bool {
        if (v == "none") {
            kind = PaintRef::None;
            return true;
        }
        if (v == "currentColor") {
            kind = PaintRef::Solid;
            color = current;
            is_current = true;
            return true;
        }
        try {
            color = parse_color(v);
            kind = PaintRef::Solid;
            return true;
        } catch (const Error&) { return false; }
    };
    if (value == "inherit") return;
    if (value.substr(0, 4) == "url(") {
        const std::size_t close = value.find(')');
        if (close == std::string_view::npos) {
            warn(cx, "invalid " + property + " '" + std::string(value) + "'");
            return;
        }
        std::string_view ref = trim(value.substr(4, close - 4));
        if (ref.size() >= 2 && (ref.front() == '\'' || ref.front() == '"')) ref = ref.substr(1, ref.size() - 2);
        PaintRef p;
        p.kind = PaintRef::Server;
        p.id = ref.empty() || ref.front() != '#' ? std::string() : std::string(ref.substr(1));
        const std::string_view rest = trim(value.substr(close + 1));
        if (!rest.empty() && !simple(rest, p.fallback, p.fallback_color, p.fallback_current))
            p.fallback = PaintRef::None;
        paint = p;
        return;
    }
    PaintRef p;
    if (simple(value, p.kind, p.color, p.current))
        paint = p;
    else
        warn(cx, "invalid " + property + " '" + std::string(value) + "'");
}

namespace {

// A fill or stroke property: context-fill and context-stroke take the context element's paint.
void apply_fill_or_stroke(Context& cx, const std::string& property, std::string_view value, const Style& st,
                          PaintRef& paint) {
    if (value == "context-fill" || value == "context-stroke") {
        // The context element's paint as it used it: its currentColor is already resolved.
        paint = value == "context-fill" ? st.context_fill : st.context_stroke;
        paint.current = paint.fallback_current = false;
    } else {
        apply_paint(cx, property, value, st.color, paint);
    }
}

// What lengths in the element's properties are relative to: the viewport's diagonal (percentages),
// its font size (em) and the document's dpi (physical units).
struct LengthBase {
    double diagonal, font_size, dpi;
    std::optional<double> operator()(std::string_view v) const { return parse_length(v, diagonal, font_size, dpi); }
};

// The element's `color`, first, so that currentColor in the same element resolves to it; an
// inherited currentColor paint takes it too.
void apply_color(Context& cx, const pugi::xml_node& node, Style& st) {
    for (const auto& [k, v] : properties(cx, node)) {
        if (k == "color") {
            try {
                st.color = parse_color(trim(v));
            } catch (const Error&) { warn(cx, "invalid color '" + v + "'"); }
        }
    }
    for (PaintRef* p : {&st.fill, &st.stroke}) {
        if (p->current) p->color = st.color;
        if (p->fallback_current) p->fallback_color = st.color;
    }
}

// stroke-dasharray: lengths separated by commas or spaces; none, or any invalid or negative
// length, gives no dashes.
std::vector<double> parse_dasharray(std::string_view value, const LengthBase& length) {
    std::vector<double> dashes;
    if (value == "none") return dashes;
    std::string list(value);
    for (char& c : list)
        if (c == ',') c = ' ';
    std::size_t pos = 0;
    while (pos < list.size()) {
        while (pos < list.size() && std::isspace(static_cast<unsigned char>(list[pos]))) ++pos;
        if (pos >= list.size()) break;
        std::size_t end = list.find(' ', pos);
        if (end == std::string::npos) end = list.size();
        const auto l = length(std::string_view(list).substr(pos, end - pos));
        if (!l || *l < 0) return {};
        dashes.push_back(*l);
        pos = end;
    }
    return dashes;
}

// paint-order: the keywords given, in their order, then the missing ones in the normal order
// (0 fill, 1 stroke, 2 markers); nothing for an unknown or repeated keyword.
std::optional<std::array<int, 3>> parse_paint_order(std::string_view value) {
    std::array<int, 3> order{};
    std::size_t n = 0;
    for (std::string_view rest = value; !rest.empty() && value != "normal";) {
        const std::size_t sp = rest.find(' ');
        const std::string_view w = rest.substr(0, sp);
        rest = sp == std::string_view::npos ? std::string_view{} : trim(rest.substr(sp));
        const int id = w == "fill" ? 0 : w == "stroke" ? 1 : w == "markers" ? 2 : -1;
        if (id < 0 || std::find(order.begin(), order.begin() + n, id) != order.begin() + n) return std::nullopt;
        order[n++] = id;
    }
    for (int id = 0; id < 3; ++id)
        if (std::find(order.begin(), order.begin() + n, id) == order.begin() + n) order[n++] = id;
    return order;
}

// marker-start, marker-mid, marker-end and the shorthand marker: url(#id), or none (no marker).
void apply_marker(const std::string& property, std::string_view value, Style& st) {
    std::string id;
    if (value.substr(0, 5) == "url(#") {
        const std::size_t close = value.find(')');
        if (close != std::string_view::npos) id = std::string(trim(value.substr(5, close - 5)));
    } else if (value != "none") {
        return;
    }
    if (property == "marker-start" || property == "marker") st.marker_start = id;
    if (property == "marker-mid" || property == "marker") st.marker_mid = id;
    if (property == "marker-end" || property == "marker") st.marker_end = id;
}

// The stroke's geometry: width, caps, joins, miter limit, dashes. False for another property.
bool apply_stroke_geometry(const std::string& property, std::string_view value, const LengthBase& length,
                           StrokeStyle& ss) {
    if (property == "stroke-width") {
        if (auto l = length(value); l && *l >= 0) ss.width = *l;
    } else if (property == "stroke-linecap") {
        parse_line_cap(value, ss.cap);
    } else if (property == "stroke-linejoin") {
        parse_line_join(value, ss.join);
    } else if (property == "stroke-miterlimit") {
        if (auto n = parse_number(value); n && *n >= 1) ss.miter_limit = *n;
    } else if (property == "stroke-dasharray") {
        ss.dashes = parse_dasharray(value, length);
    } else if (property == "stroke-dashoffset") {
        if (auto l = length(value)) ss.dash_offset = *l;
    } else {
        return false;
    }
    return true;
}

// One painting property other than the stroke's geometry and `color`.
void apply_painting(Context& cx, const std::string& property, std::string_view value, Style& st) {
    if (property == "fill") {
        apply_fill_or_stroke(cx, property, value, st, st.fill);
    } else if (property == "fill-rule") {
        if (value == "evenodd")
            st.fill_rule = FillRule::EvenOdd;
        else if (value == "nonzero")
            st.fill_rule = FillRule::NonZero;
    } else if (property == "fill-opacity") {
        if (auto o = parse_opacity(value)) st.fill_opacity = *o;
    } else if (property == "stroke") {
        apply_fill_or_stroke(cx, property, value, st, st.stroke);
    } else if (property == "stroke-opacity") {
        if (auto o = parse_opacity(value)) st.stroke_opacity = *o;
    } else if (property == "paint-order") {
        if (auto order = parse_paint_order(value)) st.paint_order = *order;
    } else if (property == "marker-start" || property == "marker-mid" || property == "marker-end" ||
               property == "marker") {
        apply_marker(property, value, st);
    } else if (property == "visibility") {
        if (value == "visible")
            st.visible = true;
        else if (value == "hidden" || value == "collapse")
            st.visible = false;
    }
}

}  // namespace

void apply_style(Context& cx, const pugi::xml_node& node, Style& st) {
    st.font_size = font_size_of(cx, node);
    apply_color(cx, node, st);
    const LengthBase length{st.viewport.diagonal(), st.font_size, cx.options.dpi};
    for (const auto& [k, v] : properties(cx, node)) {
        const std::string_view val = trim(v);
        if (!apply_stroke_geometry(k, val, length, st.stroke_style)) apply_painting(cx, k, val, st);
    }
}

// `paint` as the context paint of an element drawn with `context`: a paint server keeps the
// context element it already has (a context paint passed on), or takes `context`.
PaintRef context_paint(PaintRef paint, const std::shared_ptr<const ContextElement>& context) {
    if (paint.kind == PaintRef::Server && !paint.context) paint.context = context;
    return paint;
}

}  // namespace casteljau::svg
